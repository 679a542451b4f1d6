#pragma once
#include "dem/parallel/mpi_rank_link.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace wear::coupling {

/// `wearsim bench dem [--workload W] [--threads N[,M..]] [--settle N] [--warm N] [--steps N]
/// [--repeats N]`, and for `--workload tester` also [--scale S] [--sample convex|plain]
/// [--case FILE]: runs a DEM benchmark workload and prints particle-steps per second, the
/// time per particle-step by engine phase, contacts and memory per particle; the last line
/// is `particle_steps_per_second <median>`. Under mpirun (`ranks`, a ring) the annulus and
/// sector workloads are cut into equal angular slabs, one per rank; every rank runs the
/// benchmark, rank 0 prints it with a table per timed loop of each rank's particles, ghosts,
/// particle-steps/s, share of time in MPI, bytes and messages per step, and the load
/// imbalance.
int run_bench_command(const std::vector<std::string>& args, std::ostream& out,
                      dem::MpiRankLink* ranks = nullptr);

} // namespace wear::coupling

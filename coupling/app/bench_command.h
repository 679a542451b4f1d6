#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace wear::coupling {

/// `wearsim bench dem [--workload W] [--threads N[,M..]] [--settle N] [--warm N] [--steps N]
/// [--repeats N]`, and for `--workload tester` also [--scale S] [--sample convex|plain]
/// [--case FILE]: runs a DEM benchmark workload and prints particle-steps per second, the
/// time per particle-step by engine phase, contacts and memory per particle; the last line
/// is `particle_steps_per_second <median>`.
int run_bench_command(const std::vector<std::string>& args, std::ostream& out);

} // namespace wear::coupling

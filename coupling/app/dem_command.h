#pragma once
#include "coupling/parameters/case_parameters.h"
#include "dem/engine/rank_link.h"

#include <iosfwd>

namespace wear::coupling {

struct DemCommandOptions {
  bool progress = true; ///< live progress line on the terminal (stderr)
  /// Over MPI ranks (`mpirun -np N wearsim dem`): the ranks as a ring, each running the same
  /// command on its slab of the bed; rank 0 writes the files and the log. Null: one process.
  dem::RankLink* ranks = nullptr;
};

/// `wearsim dem <case.prm>`: the wear tester in DEM only. Generates the sample surface,
/// fills and settles the bed, runs the revolutions and writes history.h5/.xdmf,
/// summary.csv and parameters.prm into the output folder, with a progress line. Over ranks
/// every rank calls it; the others compute and keep silent.
void run_dem_command(const CaseParameters& p, std::ostream& log,
                     const DemCommandOptions& options = {});

} // namespace wear::coupling

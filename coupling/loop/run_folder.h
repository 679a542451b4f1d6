#pragma once
// How a run is asked to go (--resume, --overwrite, stop after some stages, over ranks) and
// the output folder it writes into.
#include "coupling/parameters/case_parameters.h"
#include "dem/engine/rank_link.h"

#include <ostream>
#include <string>

namespace wear::coupling {

struct RunOptions {
  bool resume = false;    ///< continue from <output>/checkpoint.h5
  int stop_after = 0;     ///< stop after this many stages of this invocation (0: run all)
  bool overwrite = false; ///< replace a run in the output folder (kept until the first checkpoint)
  /// The DEM over these ranks (under mpirun; every rank runs the same loop, rank 0 writes and
  /// prints); null: one process.
  dem::RankLink* ranks = nullptr;
  /// The wearsim command that runs the case (run, dem, scene-run): a stopped run's message
  /// says how to continue it with this command.
  std::string command = "run";
};

/// Readies Output/Directory for a run and writes its resolved parameters: a folder holding a
/// run (its series, tables or a checkpoint) is refused unless resuming, or moved aside to
/// `<folder>.replaced` with --overwrite (returned, to be deleted after the new run's first
/// checkpoint; empty if none). Throws naming Output/Directory and the options.
std::string prepare_run_folder(const CaseParameters& p, const RunOptions& options,
                               std::ostream& log);

} // namespace wear::coupling

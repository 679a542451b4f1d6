#pragma once
// What a run needs to continue after a kill, between two of its windows: the DEM state with
// its contact histories and continuation, and the scene's own part (its inlets, outlets, node
// moves and each wearing part's worn sample, stress, records and open stage:
// scene_checkpoint.h); each stateful type writes its own part, this file composes them.
// Written to HDF5 atomically after every stage and at in-stage checkpoints, the one before
// kept beside it; read back with every size checked.
#include "coupling/loop/stage_record.h"
#include "coupling/output/checkpoint_arrays.h"
#include "coupling/output/scene_checkpoint.h"
#include "dem/engine/system.h"
#include "dem/evaluation/tester_evaluation.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// Which part of a checkpoint's DEM state a reader takes: rank `rank` of `n_ranks`.
struct DemPart {
  int rank = 0;
  int n_ranks = 1;
};

struct Checkpoint {
  int stages_done = 0;
  /// Ranks that wrote the DEM state: when it is not the reader's count, `dem` holds the parts
  /// merged into the bed of one process (dem::merge_rank_states).
  int dem_ranks = 1;
  std::string parameters; ///< fully resolved case of the run (resume refuses another)
  dem::SystemState dem;   ///< with its continuation (a checkpoint lies between two steps)
  /// False for a checkpoint kept without its particle bed (no /dem in the file, the root's
  /// attribute without_bed = 1; `dem` empty): a kept run carried between machines
  /// (cases/reference-study/keep_running.sh), written at a stage's end. Its resume fills the
  /// bed anew (SceneCoupledRun).
  bool has_bed = true;
  SceneCheckpoint scene; ///< the scene's own part and its wearing parts
};

/// Where the checkpoint before the latest one is kept: "<path without .h5>.previous.h5".
std::string previous_checkpoint_path(const std::string& path);

/// Writes atomically (a failed write leaves the previous checkpoint in place); the checkpoint
/// it replaces is kept as previous_checkpoint_path(path), so two complete ones exist at every
/// moment once two were written.
/// Over ranks `dem_parts` holds every rank's DEM state in rank order (dem::gather_rank_states,
/// on rank 0, which alone writes) and is written instead of c.dem. Without c.has_bed no DEM
/// state is written.
void write_checkpoint(const std::string& path, const Checkpoint& c,
                      const std::vector<dem::SystemState>& dem_parts = {});
/// Throws naming the file and what is missing or inconsistent. `part`: the rank that reads;
/// c.dem is its own part when the file was written on part.n_ranks ranks, else the merged bed.
Checkpoint read_checkpoint(const std::string& path, const DemPart& part = {});
/// The latest readable checkpoint: `path`, or, when it is missing or damaged, the one before
/// it, with a warning on `warnings` naming both. Throws naming `path` when neither reads.
Checkpoint read_latest_checkpoint(const std::string& path, std::ostream& warnings,
                                  const DemPart& part = {});

/// Throws naming `path` when checkpoint c was written for another case than the one whose
/// resolved parameters are `parameters` (a resume must continue the same case).
void require_same_case(const Checkpoint& c, const std::string& parameters, const std::string& path);
/// Flat numeric forms of the records (also used by the run's history.h5).
std::vector<double> pack(const dem::RevolutionRecord& r);
std::vector<double> pack(const StageRecord& r);
/// Column names of pack(StageRecord), units in the names.
std::vector<std::string> stage_columns();

} // namespace wear::coupling

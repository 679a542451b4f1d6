#pragma once
// What a coupled run needs to continue after a kill: the DEM state with its contact
// histories, the evaluation records, the worn sample (volume mesh, surface, accumulated
// fields), the per-face stress of the last stage and the stage records; inside a stage also
// the open stage (its summed loads, the open revolution). Written to HDF5 atomically after
// every stage and at in-stage checkpoints, the one before kept beside it; read back with
// every size checked.
#include "coupling/loop/stage_record.h"
#include "dem/engine/system.h"
#include "dem/tester/tester_evaluation.h"
#include "dem/tester/wall_loads.h"
#include "dem/tester/wear_tester.h"
#include "fem/worn_sample.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// A stage stopped inside its DEM part: what it had summed and where its revolution stands.
/// The loads are dem::WallLoads's fields on the current sample surface, sample frame.
struct OpenStage {
  int revolutions_done = 0;                   ///< completed revolutions of the stage
  double dem_seconds = 0;                     ///< [s] wall time of its DEM so far (reporting only)
  std::vector<meshes::Vec3> impulse;          ///< [N s] per face
  std::vector<meshes::Vec3> traction_impulse; ///< [N s] per face, as the FEM receives it
  std::vector<double> normal_impulse, archard, sliding_work; ///< [N s], [N m], [J] per face
  std::vector<double> contact_steps, wear_volume;            ///< [-], [m^3] per face
  double duration = 0;                                       ///< [s] of the summed windows
  dem::OpenRevolution revolution;
};

/// An open stage holding `loads` (sample frame) after `revolutions_done` revolutions.
OpenStage open_stage(const dem::WallLoads& loads, int revolutions_done, double dem_seconds,
                     const dem::OpenRevolution& revolution);
/// The open stage's loads on `surface` (the current sample surface); throws when the face
/// counts differ.
dem::WallLoads loads_of(const OpenStage& o, const meshes::SurfaceMesh& surface);

struct Checkpoint {
  int stages_done = 0;
  std::string parameters; ///< fully resolved case of the run (resume refuses another)
  dem::SystemState dem;
  int revolutions_done = 0;
  std::vector<dem::RevolutionRecord> revolutions;
  bool has_sample = false; ///< a worn FEM sample exists (staged runs)
  fem::WornSampleState sample;
  std::vector<double> face_von_mises; ///< [Pa] per face of the sample surface (last stage)
  std::vector<double> dem_cumulative; ///< [m^3] per face, wear-law volume (no FEM sample)
  std::vector<StageRecord> stages;
  /// Present in an in-stage checkpoint (the DEM state then carries its continuation part).
  std::optional<OpenStage> open_stage;
};

/// Where the checkpoint before the latest one is kept: "<path without .h5>.previous.h5".
std::string previous_checkpoint_path(const std::string& path);

/// Writes atomically (a failed write leaves the previous checkpoint in place); the checkpoint
/// it replaces is kept as previous_checkpoint_path(path), so two complete ones exist at every
/// moment once two were written.
void write_checkpoint(const std::string& path, const Checkpoint& c);
/// Throws naming the file and what is missing or inconsistent.
Checkpoint read_checkpoint(const std::string& path);
/// The latest readable checkpoint: `path`, or, when it is missing or damaged, the one before
/// it, with a warning on `warnings` naming both. Throws naming `path` when neither reads.
Checkpoint read_latest_checkpoint(const std::string& path, std::ostream& warnings);

/// Flat numeric forms of the records (also used by the run's history.h5).
std::vector<double> pack(const dem::RevolutionRecord& r);
std::vector<double> pack(const StageRecord& r);
/// Column names of pack(StageRecord), units in the names.
std::vector<std::string> stage_columns();

} // namespace wear::coupling

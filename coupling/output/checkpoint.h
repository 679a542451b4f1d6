#pragma once
// What a coupled run needs to continue after a kill: the DEM state with its contact
// histories, the evaluation records, the worn sample (volume mesh, surface, accumulated
// fields), the per-face stress of the last stage and the stage records. Written to HDF5
// atomically after every stage; read back with every size checked.
#include "coupling/loop/stage_record.h"
#include "dem/engine/system.h"
#include "dem/tester/tester_evaluation.h"
#include "fem/worn_sample.h"

#include <string>
#include <vector>

namespace wear::coupling {

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
};

/// Writes atomically (a failed write leaves the previous checkpoint in place).
void write_checkpoint(const std::string& path, const Checkpoint& c);
/// Throws naming the file and what is missing or inconsistent.
Checkpoint read_checkpoint(const std::string& path);

/// Flat numeric forms of the records (also used by the run's history.h5).
std::vector<double> pack(const dem::RevolutionRecord& r);
std::vector<double> pack(const StageRecord& r);
/// Column names of pack(StageRecord), units in the names.
std::vector<std::string> stage_columns();

} // namespace wear::coupling

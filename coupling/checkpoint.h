#pragma once
// What a coupled run needs to continue after a kill: the DEM state with its contact
// histories, the evaluation records, the worn sample (volume mesh, surface, accumulated
// fields), the per-face stress of the last stage and the stage records. Written to HDF5
// atomically after every stage; read back with every size checked.
#include "dem/system.h"
#include "dem/tester_evaluation.h"
#include "fem/worn_sample.h"

#include <string>
#include <vector>

namespace wear::coupling {

/// One stage of a coupled run (one row of stages.csv).
struct StageRecord {
  int stage = 0;  ///< 1-based
  int scheme = 0; ///< Scheme as an integer
  int first_revolution = 0, last_revolution = 0;
  double time = 0;                   ///< [s] simulated, at the end of the stage
  double amplification = 1;          ///< [-] declared factor applied this stage
  double dem_wear_volume = 0;        ///< [m^3] wear-law volume on the wear faces (not amplified)
  double applied_volume = 0;         ///< [m^3] removed volume asked of the geometry (amplified)
  double geometry_volume_change = 0; ///< [m^3] FEM mesh volume (or DEM enclosed) before - after
  double cumulative_applied = 0;     ///< [m^3] sum of applied_volume so far
  double max_depth = 0;              ///< [m] deepest removal of one face this stage
  double max_depth_fraction = 0;     ///< [-] of that face's longest edge (largest over faces)
  double mean_stress_factor = 1;     ///< [-] area-weighted stress-informed factor on wear faces
  int increments = 0, n_remeshes = 0, total_remeshes = 0;
  double spread_volume = 0; ///< [m^3] moved between faces where the recession would fold
  /// [m^3] asked of faces worn through to the clamped bottom, not removed
  /// (geometry_volume_change = applied_volume - worn_through_volume)
  double worn_through_volume = 0;
  int n_worn_through = 0; ///< wear faces worn through at the end of the stage
  int n_tetrahedra = 0, n_surface_faces = 0, n_pushed = 0;
  double max_push = 0;            ///< [m] largest displacement of a pushed particle
  double min_scaled_jacobian = 0; ///< [-] of the mesh handed on
  double max_von_mises = 0;       ///< [Pa] under the stage-averaged loads (0: not solved)
  double safety_factor = 0;       ///< [-] yield / max von Mises
  double max_displacement = 0;    ///< [m]
  double mean_force_z = 0;        ///< [N] stage-averaged vertical load on the sample (sample frame)
  double wear_face_force_z = 0;   ///< [N] the same on the wear faces only
  double wear_face_normal_force = 0;       ///< [N] stage-averaged normal force on the wear faces
  int volume_points = 0, volume_cells = 0; ///< of the stage's volume output (0: none)
  double dem_seconds = 0, wear_seconds = 0, fem_solve_seconds = 0, motion_seconds = 0,
         remesh_seconds = 0, output_seconds = 0; ///< [s] wall clock per phase
  std::string distortion; ///< reference scheme: first distortion, empty if none
};

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

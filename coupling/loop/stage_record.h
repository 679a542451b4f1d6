#pragma once
// The figures of one stage of a coupled run: what it asked, what the geometry did, the
// stress, the loads, and the wall time of each phase. One row of stages.csv, one entry of
// history.h5 and of the checkpoint.
#include "coupling/parameters/coupling_parameters.h"

#include <string>

namespace wear::coupling {

/// One stage of a coupled run (one row of stages.csv).
struct StageRecord {
  int stage = 0; ///< 1-based
  Scheme scheme = Scheme::staged;
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
  int n_first_attempt_remeshes = 0; ///< remeshes of the stage gmsh's first attempt made
  double spread_volume = 0;         ///< [m^3] moved between faces where the recession would fold
  /// [m^3] asked of faces worn through to the clamped bottom, not removed
  /// (geometry_volume_change = applied_volume - worn_through_volume)
  double worn_through_volume = 0;
  int n_worn_through = 0; ///< wear faces worn through at the end of the stage
  int n_tetrahedra = 0, n_surface_faces = 0, n_pushed = 0;
  double max_push = 0;            ///< [m] largest displacement of a pushed particle
  double min_scaled_jacobian = 0; ///< [-] of the mesh handed on
  /// Von Mises under the stage-averaged loads (0: not solved), three measures [Pa]:
  double max_von_mises_ball = 0;      ///< [Pa] largest of the ball-averaged stress (converges)
  double von_mises_p99 = 0;           ///< [Pa] volume-weighted 99th percentile
  double von_mises_p999 = 0;          ///< [Pa] volume-weighted 99.9th percentile
  double max_von_mises_qp = 0;        ///< [Pa] largest at a quadrature point (mesh-dependent)
  double stress_averaging_radius = 0; ///< [m] radius of the ball average
  double safety_factor = 0;           ///< [-] yield / max_von_mises_qp
  double max_displacement = 0;        ///< [m]
  double mean_force_z = 0;      ///< [N] stage-averaged vertical load on the sample (sample frame)
  double wear_face_force_z = 0; ///< [N] the same on the wear faces only
  double wear_face_normal_force = 0;       ///< [N] stage-averaged normal force on the wear faces
  int volume_points = 0, volume_cells = 0; ///< of the stage's volume output (0: none)
  double dem_seconds = 0, wear_seconds = 0, fem_solve_seconds = 0, motion_seconds = 0,
         remesh_seconds = 0, output_seconds = 0; ///< [s] wall clock per phase
  std::string distortion; ///< reference scheme: first distortion, empty if none
};

} // namespace wear::coupling

#pragma once
// The wear increment of one stage: the volume per face the stage asks the geometry to lose.
//
//   dV_f = A * s(sigma_f) * V_f   on the wear faces (0 elsewhere)
//
// V_f [m^3] the wear law's volume over the stage's DEM window (Archard: alpha times the
// load-distance), A [-] the declared amplification, s the stress-informed factor
// 1 + c (sigma_vM,f / sigma_ref)^m from the previous stage's von Mises stress, ball-averaged
// at the face (fem/stress_measures.h; 1 when the law is off). The depth it recedes a vertex,
// sum(dV_f) / sum(A_f) over the wear faces around it, is checked against Coupling/Maximum depth
// fraction of the longest edge there; adaptive amplification lowers A until the deepest vertex
// meets the cap.
#include "coupling/parameters/coupling_parameters.h"
#include "meshes/face_field.h"

#include <vector>

namespace wear::coupling {

/// The deepest vertex recession of a per-face removed volume, against the local edge.
struct DepthCheck {
  double max_depth = 0;    ///< [m] deepest vertex recession
  double max_fraction = 0; ///< [-] largest depth / longest edge at the vertex
  long vertex = -1;        ///< where the fraction is largest
  double depth_there = 0;  ///< [m]
  int label = 0;           ///< a wear label at that vertex
};

/// The deepest vertex of the area-weighted recession sum(dV_f) / sum(A_f) over the wear faces
/// around each vertex (meshes::area_weighted_depth; a per-face depth dV_f / A_f would be noise
/// on small faces), against the longest edge at that vertex.
DepthCheck vertex_depths(const meshes::SurfaceMesh& surface, const std::vector<double>& removed);

/// The stress-informed law's factor on a face, s = 1 + c (max(sigma_vM, 0) / sigma_ref)^m,
/// or 1 when the law is off. [-]
double stress_factor(const StressInformedWear& law, double von_mises);

struct WearIncrement {
  meshes::FaceField<double> removed; ///< [m^3] asked of the geometry per face (extensive)
  double amplification = 1;          ///< [-] applied this stage
  double dem_wear_volume = 0;        ///< [m^3] wear-law volume on the wear faces (not amplified)
  double mean_stress_factor = 1;     ///< [-] area-weighted over the wear faces
  DepthCheck depth;                  ///< of `removed`
  /// When adaptive amplification lowered A: the declared A and the depth it would have asked.
  bool lowered = false;
  double declared_amplification = 1; ///< [-]
  DepthCheck declared_depth;
};

/// The increment of a stage on `surface` from the wear-law volume of its DEM window and the
/// previous stage's von Mises stress per face [Pa] (intensive; zeros before the first FEM
/// solve). `adaptive`: apply Coupling/Adaptive amplification (staged stages only).
WearIncrement wear_increment(const meshes::SurfaceMesh& surface,
                             const meshes::FaceField<double>& wear_volume,
                             const meshes::FaceField<double>& previous_stress,
                             const CouplingParameters& p, bool adaptive);

/// Throws std::runtime_error naming the parameters to change when the increment recedes a
/// vertex by more than Coupling/Maximum depth fraction of its longest edge.
void check_depth_cap(const WearIncrement& increment, const CouplingParameters& p, int stage);

} // namespace wear::coupling

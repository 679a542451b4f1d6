#pragma once
// What the DEM hands to the rest of the toolchain about a wearing wall: one window's
// extensive loads per face, as FaceFields tied to the revision of the mesh they were summed
// on, among them the coarse-grained impulse (meshes/coarse_graining.h) that the FEM
// receives. Only extensive, window-integrated quantities cross the module boundary;
// intensive ones (pressure, traction, wear depth) are derived where they are used.
#include "dem/engine/filling.h"
#include "dem/engine/system.h"
#include "dem/wear/wear_law.h"
#include "meshes/face_field.h"
#include "meshes/parameter_visitor.h"

#include <functional>

namespace wear::dem {

/// How a window's loads are laid on the wall's faces (DEM/Coarse-graining width, Wall
/// traction, Wear field). The default keeps every field per face.
struct LoadSpreading {
  double width = 0;      ///< [m] kernel width w
  bool traction = false; ///< traction_impulse coarse-grained (else the per-face impulse)
  bool wear = false;     ///< wear_volume coarse-grained (else per face)
};

/// How the DEM subsection asks a window's loads to be laid on a wall's faces.
struct WallLoadParameters {
  /// [m] width w of the kernel that coarse-grains the wall loads; 0: the number-mean particle
  /// radius at the scaling factor
  double coarse_graining_width = 0;
  bool coarse_grained_traction = true; ///< the FEM receives the coarse-grained traction
  bool coarse_grained_wear = false;    ///< the wear-law volume is coarse-grained too
};

/// The DEM subsection's entries of WallLoadParameters (inside the subsection).
template <typename Visitor>
void visit_parameters(WallLoadParameters& d, Visitor& v) {
  v.real("Coarse-graining width", d.coarse_graining_width,
         "[m] Width w of the Gaussian kernel, cut at 3w, that coarse-grains the contact loads "
         "on a wearing wall into continuum fields (force and moment kept exactly); 0 uses the "
         "number-mean particle radius at the Scaling factor.");
  v.choice("Wall traction", d.coarse_grained_traction, "coarse-grained", "per face",
           "The traction the FEM receives: the coarse-grained field of the contact forces, "
           "independent of the triangulation, or each face's own window impulse over its area "
           "(noisier on finer meshes).");
  v.choice("Wear field", d.coarse_grained_wear, "coarse-grained", "per face",
           "The wear-law volume: per face as the contacts fell, or coarse-grained with the "
           "same kernel over the faces of each contact's label (label totals kept).");
}

/// The spreading `p` declares for particles of size distribution `psd`: Coarse-graining
/// width (0: half the number-weighted mean diameter at the scaling factor), Wall traction,
/// Wear field.
LoadSpreading load_spreading(const WallLoadParameters& p, const SizeDistribution& psd);

struct WallLoads {
  meshes::FaceField<meshes::Vec3> impulse; ///< [N s] integral of the contact force
  /// [N s] the impulse the FEM receives: per face the integral of the coarse-grained
  /// traction over the face and the window, or the per-face impulse (LoadSpreading)
  meshes::FaceField<meshes::Vec3> traction_impulse;
  meshes::FaceField<double> normal_impulse; ///< [N s] integral of F_n
  meshes::FaceField<double> archard;        ///< [N m] Archard load-distance, integral of F_n |v_t|
  meshes::FaceField<double> sliding_work;   ///< [J] integral of |F_t . v_t|
  meshes::FaceField<double> contact_steps;  ///< [-] contact-steps (split contacts fractionally)
  meshes::FaceField<double> wear_volume;    ///< [m^3] the wear law applied to this window
  /// [m^3] the part of wear_volume the law books to impacts (WearLaw::removed_by_mechanism;
  /// zero for a sliding law), laid on the faces as wear_volume is
  meshes::FaceField<double> impact_volume;
  double duration = 0; ///< [s] of the window

  /// Zero loads on every face of `mesh`.
  static WallLoads zero(const meshes::SurfaceMesh& mesh);

  /// Adds another window on the same faces (same revision): the windows' sums and
  /// durations add. Throws when the faces differ.
  WallLoads& operator+=(const WallLoads& other);

  /// The same loads on `mesh`, a revision of the same triangles in another frame or after
  /// vertex moves: scalar fields follow their faces unchanged, impulse vectors are mapped by
  /// `rotate` (a rotation: vectors are never translated).
  WallLoads follow(const meshes::SurfaceMesh& mesh,
                   const std::function<meshes::Vec3(const meshes::Vec3&)>& rotate) const;
};

/// The loads of one window from the engine's per-face integrals of a wall with mesh `mesh`
/// and the wear law's removed volume per face [m^3] over the same window (and its impact
/// part, empty: none), the traction and the wear volumes laid on the faces as `spreading`
/// says. A coarse-grained field keeps the window's force and moment (the volume per label) to
/// round-off.
WallLoads wall_loads(const WearIntegrals& integrals, const std::vector<double>& wear_volume,
                     const meshes::SurfaceMesh& mesh, double duration,
                     const LoadSpreading& spreading = {},
                     const std::vector<double>& impact_volume = {});

/// The law's per-face volume of the mechanism "impact" (zeros when it has none).
std::vector<double> impact_part(const WearLaw& law, const WearIntegrals& integrals);

} // namespace wear::dem

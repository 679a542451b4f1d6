#pragma once
// The reference deformation method (docs/theory.md section 5): surface nodes of the wearing wall
// move inward by the local wear depth; the topology never changes, so the run is valid only
// until the surface distorts.
#include "meshes/mesh_quality.h"
#include "meshes/parameter_visitor.h"
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace wear::dem {

struct ReferenceDeformationParameters {
  bool enabled = false;
  std::uint64_t update_interval = 500; ///< [steps] N_update between node moves
  double amplification = 1;            ///< [-] multiplies every removed volume (declared)
};

/// The Deformation subsection of a case file (meshes/parameter_visitor.h).
template <typename Visitor>
void visit_parameters(ReferenceDeformationParameters& d, Visitor& v) {
  v.enter("Deformation");
  v.boolean("Reference method", d.enabled,
            "Move the sample's surface nodes inside the DEM by the local wear depth (the "
            "reference study's method); valid until the surface distorts.");
  v.count("Update interval", d.update_interval,
          "[steps] Node moves happen every this many DEM steps.");
  v.real("Amplification", d.amplification,
         "[-] Declared factor on the removed volume applied to the nodes (1: physical).");
  v.leave();
}

/// The first distortion found, with where and when.
struct Distortion {
  std::string kind; ///< "inverted face", "degenerate face" or "self-intersection"
  long face = -1;   ///< face index in the wall mesh
  int label = 0;    ///< its label id
  double time = 0;  ///< [s] simulated time of the update that produced it
};

/// What a ReferenceDeformation has done, for a checkpoint: the moved vertices and the sums.
struct ReferenceDeformationState {
  std::vector<meshes::Vec3> vertices; ///< [m] the surface as moved
  double swept_volume = 0;            ///< [m^3]
  double applied_volume = 0;          ///< [m^3]
  std::uint64_t n_updates = 0;
  std::optional<Distortion> distortion;
};

class ReferenceDeformation {
public:
  /// `mesh`: the wearing wall as placed; faces whose role is wearing (SurfaceMesh::roles)
  /// recede, the others (sides, bottom) hold still but their nodes follow shared corners.
  explicit ReferenceDeformation(const meshes::SurfaceMesh& mesh);

  /// One node update from removed volume per face [m^3] (extensive, same face order):
  /// dd_f = dV_f / A_f; each node moves along its inward area-weighted vertex normal by the
  /// area-weighted mean depth of the faces around it, sum(dV_f) / sum(A_f). Accumulates the
  /// swept volume sum_f |dp_c,f| A_f and checks the new surface. An update that distorts
  /// the surface is recorded and undone; later updates do nothing. Returns the vertices.
  const std::vector<meshes::Vec3>& update(const std::vector<double>& removed_volume, double time);

  const meshes::SurfaceMesh& mesh() const { return mesh_; }
  double swept_volume() const { return swept_volume_; }     ///< [m^3] sum |dp_c| A
  double applied_volume() const { return applied_volume_; } ///< [m^3] sum of removed volume
  /// Volume lost by the closed surface since the start [m^3] (enclosed-volume difference).
  double enclosed_volume_loss() const;
  std::uint64_t n_updates() const { return n_updates_; }
  const std::optional<Distortion>& first_distortion() const { return distortion_; }
  /// The first distortion as a sentence ("inverted face at face 12 (C23), t = 0.41 s"), empty
  /// while the surface holds.
  std::string distortion_text() const;
  const meshes::SurfaceQuality& quality() const { return quality_; }

  ReferenceDeformationState state() const;
  /// Continues from `s`, taken of a deformation of the same unworn mesh (vertex count checked).
  void resume(const ReferenceDeformationState& s);

private:
  meshes::SurfaceMesh mesh_;
  std::vector<meshes::Vec3> initial_normals_;
  std::vector<char> wears_;
  double initial_volume_ = 0, swept_volume_ = 0, applied_volume_ = 0;
  std::uint64_t n_updates_ = 0;
  std::optional<Distortion> distortion_;
  meshes::SurfaceQuality quality_;
};

} // namespace wear::dem

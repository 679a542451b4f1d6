#pragma once
// How a surface vertex may move without changing the shape of the surface that does not wear
// (the sample's flat sides and bottom): in the plane of one flat face group, along the crease
// where two meet, or not at all at a corner.
#include "meshes/surface_mesh.h"

#include <vector>

namespace wear::meshes {

struct SlidingConstraint {
  int n_free =
      3;     ///< 3 free (no unworn face), 2 in the plane normal to `axis`, 1 along `axis`, 0 fixed
  Vec3 axis; ///< unit plane normal (n_free = 2) or crease direction (n_free = 1)

  /// The part of a displacement [m] that keeps the vertex on its unworn faces.
  Vec3 apply(const Vec3& d) const {
    switch (n_free) {
    case 3:
      return d;
    case 2:
      return d - axis * dot(d, axis);
    case 1:
      return axis * dot(d, axis);
    default:
      return {};
    }
  }
};

/// One constraint per vertex from the non-wearing faces around it, grouped by normal: faces
/// whose normals lie within `crease_angle_deg` of a group's first face belong to that group.
/// One group: its plane; two: the line where the planes meet; three or more: fixed.
std::vector<SlidingConstraint> sliding_constraints(const SurfaceMesh& m,
                                                   double crease_angle_deg = 10);

} // namespace wear::meshes

#pragma once
// Structured triangulation of a parametric patch: the shared way to mesh walls, plates and
// test planes.
#include "meshes/surface_mesh.h"

#include <functional>

namespace wear::meshes {

enum class Diagonals {
  alternating, ///< quad (i, j) split along alternating diagonals: no directional bias
  uniform      ///< every quad split along (i, j) - (i + 1, j + 1)
};

/// Maps (u, v) in [0,1]^2 through `point` on an (n_u + 1) x (n_v + 1) vertex grid and splits
/// each quad into two triangles, counter-clockwise in (u, v) unless `flip`.
SurfaceMesh structured_grid(int n_u, int n_v, const std::function<Vec3(double, double)>& point,
                            bool flip, int label_id, Diagonals diagonals = Diagonals::alternating);

} // namespace wear::meshes

#pragma once
// Delaunay edge flips inside flat regions of a surface: the same surface, better triangles.
#include "meshes/surface_mesh.h"

namespace wear::meshes {

/// Flips every edge between two faces of one label that lie in one plane (normals within
/// `max_angle_deg`) and are not locally Delaunay (opposite angles summing to more than pi),
/// until none is left (Lawson). The surface's shape, closedness and orientation are kept;
/// vertices do not move; the face count is kept but faces are renumbered, so the revision
/// is bumped when anything flipped. Relaxing vertices within a flat side leaves triangles a
/// volume mesher cannot fill without flat tetrahedra; flipping restores them. Returns the
/// number of flips.
std::size_t flip_flat_edges(SurfaceMesh& m, double max_angle_deg = 1e-3);

} // namespace wear::meshes

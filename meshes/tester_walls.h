#pragma once
// Triangle meshes of the circular tester's walls over one periodic sector.
#include "meshes/geometry_parameters.h"
#include "meshes/surface_mesh.h"

#include <optional>

namespace wear::meshes {

/// Open wall meshes; normals point into the particle region.
struct TesterWalls {
  SurfaceMesh floor;                       ///< annular sector at z = 0, normal +z
  SurfaceMesh inner;                       ///< cylinder r = inner radius, normal +r
  SurfaceMesh outer;                       ///< cylinder r = outer radius, normal -r
  std::optional<SurfaceMesh> consolidator; ///< horizontal plate, normal -z
};

TesterWalls generate_tester_walls(const TesterGeometry& t);

/// A wall of the sector 0..angle stretched in angle about the z axis to span
/// [-margin, angle + margin] [rad]: particles may sit slightly beyond a periodic cut between
/// neighbour-list rebuilds and must still see the wall.
SurfaceMesh widen_sector(const SurfaceMesh& wall, double angle, double margin);

} // namespace wear::meshes

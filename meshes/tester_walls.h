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

/// The sample holder in the sample frame (x radial, y along the flow, z up, origin at the
/// centre of the sample's bottom face): a closed, outward-oriented box frame of wall
/// thickness t.holder_rim_width around and under the sample box [-W/2, W/2] x [-L/2, L/2] x
/// [0, thickness], its rim top at z = thickness, flush with the wear-face edge. The faces the
/// bed can reach (rim top, outer sides, underside) are label::wall; the pocket's faces, held
/// flush against the sample's sides and bottom, are label::pocket. Triangle edges at most
/// t.wall_mesh_size; every vertex lies on the box planes exactly, so the pocket coincides with
/// the sample's sides and bottom. Place it with SampleFrame::place_in_tester, as the sample.
SurfaceMesh generate_holder(const SampleGeometry& s, const TesterGeometry& t);

/// A wall of the sector 0..angle stretched in angle about the z axis to span
/// [-margin, angle + margin] [rad]: particles may sit slightly beyond a periodic cut between
/// neighbour-list rebuilds and must still see the wall.
SurfaceMesh widen_sector(const SurfaceMesh& wall, double angle, double margin);

} // namespace wear::meshes

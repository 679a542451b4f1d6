#pragma once
// Isotropic remeshing of a labelled surface (CGAL's Polygon Mesh Processing): triangles of one
// edge length, close to equilateral, on the input surface, the boundaries between labels kept
// as curves. A surface of that kind is one a volume mesher can keep as it is.
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace wear::meshes {

struct IsotropicRemeshParameters {
  double target_edge = 1e-3; ///< [m] edges are split above 4/3 of it, collapsed below 4/5
  int n_iterations = 5;      ///< rounds of split, collapse, flip and tangential relaxation
};

struct IsotropicRemeshReport {
  std::size_t n_faces_before = 0, n_faces_after = 0;
  double min_quality_before = 0, min_quality_after = 0; ///< 4 sqrt(3) A / sum of squared edges
  double seconds = 0;
};

/// Remeshes the closed surface `m` in place (Botsch and Kobbelt's scheme: split long edges,
/// collapse short ones, flip towards valence 6, relax each vertex to the centroid of its
/// neighbours and project it back onto the input). The edges between faces of different
/// labels are constraints: split and collapsed only along themselves, their vertices moved
/// only along them; so are the edges in `curves` (vertex pairs), which are replaced by the
/// new edges along them. A vertex where three or more labels meet, or where a curve ends or
/// branches, stays where it is. The new faces keep the labels of the input faces they cover.
IsotropicRemeshReport isotropic_remesh(SurfaceMesh& m,
                                       std::vector<std::pair<std::uint32_t, std::uint32_t>>& curves,
                                       const IsotropicRemeshParameters& p);

} // namespace wear::meshes

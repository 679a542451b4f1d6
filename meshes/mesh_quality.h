#pragma once
// Quality of a triangle surface: angles, aspect ratios, degenerate and inverted faces, and
// self-intersections found through a uniform grid (not all pairs).
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace wear::meshes {

/// The cosine between the normals of two faces across an edge below which the edge is a fold:
/// the faces lie nearly on each other, a flat fin that no volume mesher accepts (gmsh refused
/// a worn surface at -0.952 across an element's foot).
inline constexpr double volume_mesher_fold_cos = -0.95;

struct SurfaceQuality {
  double min_angle_deg = 180;           ///< smallest interior angle of any face [deg]
  double max_aspect_ratio = 0;          ///< longest edge / (2 sqrt(3) inradius); 1 = equilateral
  std::size_t n_degenerate = 0;         ///< faces with area below degenerate_area
  std::size_t n_inverted = 0;           ///< faces whose normal turned more than 90 deg
  std::size_t n_self_intersections = 0; ///< intersecting face pairs found
  std::size_t n_folded_edges = 0;       ///< edges whose two faces fold onto each other
  long first_bad_face = -1;             ///< a degenerate, inverted or intersecting face, or -1
  std::vector<std::uint32_t> bad_faces; ///< every such face (both of an intersecting pair)
  bool valid() const {
    return n_degenerate == 0 && n_inverted == 0 && n_self_intersections == 0 && n_folded_edges == 0;
  }
};

/// 4 sqrt(3) A / (sum of the squared edges): 1 for an equilateral triangle, 0 for a flat one.
double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c);
/// The smallest triangle_quality of the faces of m (infinity without faces).
double min_triangle_quality(const SurfaceMesh& m);

/// `reference_normals` (one per face, e.g. the unworn normals) enables the inverted-face
/// test; an edge whose two faces' normals are nearly opposite (cos < folded_edge_cos) is a
/// fold (the faces lie on each other: a flat fin that the self-intersection test, which
/// skips faces sharing an edge, cannot see, and that no volume mesher accepts); a face is
/// degenerate when its area is below `relative_area_tolerance` times the squared mean edge length.
SurfaceQuality surface_quality(const SurfaceMesh& m,
                               const std::vector<Vec3>* reference_normals = nullptr,
                               double relative_area_tolerance = 1e-10,
                               double folded_edge_cos = volume_mesher_fold_cos);

/// Pairs of faces across an edge of two faces whose normals' cosine is below fold_cos (a face
/// of zero area has no normal and folds nothing: it is degenerate).
std::vector<std::pair<std::uint32_t, std::uint32_t>>
find_folded_edges(const SurfaceMesh& m, double fold_cos = volume_mesher_fold_cos);

/// Pairs of faces (i < j) that cross each other. Faces sharing an edge are never tested;
/// faces sharing one vertex are tested with the edges that avoid the shared vertex.
/// Coplanar overlaps are not reported (a worn surface folds, it does not slide in-plane).
/// Stops after max_pairs pairs.
std::vector<std::pair<std::uint32_t, std::uint32_t>>
find_self_intersections(const SurfaceMesh& m, std::size_t max_pairs = 100);

} // namespace wear::meshes

#pragma once
// How much of a worn part is left: each convex element's height above its foot and volume
// above it, the thinnest the part has become over its clamped bottom, its volume, and whether
// it is worn through. What a stage records of the part's life and what a run's end criterion
// (Coupling/Worn out when) reads.
#include "meshes/surface_mesh.h"

#include <array>
#include <map>
#include <vector>

namespace wear::meshes {

/// A convex element (label C<j><k>) as it stands on the part, measured against its foot: the
/// surface its boundary spans (in plan view, the mean value interpolant of the boundary's
/// heights), which is the base's plane under an unworn element and follows the worn base's
/// tilt and waviness around a remnant.
struct ElementStanding {
  double height = 0; ///< [m] the most a vertex of it stands above its foot (z); 0 for a hollow
  double volume = 0; ///< [m^3] between its faces and its foot, negative below it
  std::map<int, int> neighbours; ///< the wearing labels around it, with the edges it shares
};

/// Every convex element label of `m` that still borders another wearing label.
std::map<int, ElementStanding> convex_element_standing(const SurfaceMesh& m);

/// The unworn footprints of a part's convex elements in plan view: each element's boundary,
/// where its faces meet another label, on the surface the part was first meshed with, as
/// directed edges {x0, y0, x1, y1} [m]. Unlike a worn surface's labels, which every stage hands
/// on to its new faces, a footprint stays where the element stood.
using ElementFootprints = std::map<int, std::vector<std::array<double, 4>>>;
ElementFootprints element_footprints(const SurfaceMesh& first);

/// Each footprint's element as it stands on `m`, whatever m's labels say: its foot is the
/// mean value interpolant of m's heights along the unworn outline (the worn base around where
/// the element stood); its volume that of m's upward faces whose plan centroid lies inside the
/// outline, between them and the foot; its height the most a vertex of those faces stands
/// above the foot. An element worn away leaves its footprint at about no height and volume.
/// `neighbours` stays empty.
std::map<int, ElementStanding> footprint_standing(const SurfaceMesh& m,
                                                  const ElementFootprints& footprints);

struct PartLife {
  std::map<int, ElementStanding> elements;
  /// [m] lowest vertex of a wearing face above the plane of the clamped faces' lowest vertex
  /// (the part's remaining thickness; 0 without wearing or clamped faces)
  double thinnest = 0;
  double volume = 0;          ///< [m^3] enclosed
  double clamped_area = 0;    ///< [m^2] of the clamped faces
  std::size_t n_standing = 0; ///< elements standing higher than the vanish height
};

/// The part's life figures; an element counts as standing when its height exceeds
/// `vanish_height` [m] (the implicit recession's, meshes/implicit_recession.h).
PartLife part_life(const SurfaceMesh& m, double vanish_height);

} // namespace wear::meshes

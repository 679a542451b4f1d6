#pragma once
// How much of a worn part is left: each convex element's height above its foot and volume
// above it, the thinnest the part has become over its clamped bottom, its volume, and whether
// it is worn through. What a stage records of the part's life and what a run's end criterion
// (Coupling/Worn out when) reads.
#include "meshes/surface_mesh.h"

#include <map>

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

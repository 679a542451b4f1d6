#pragma once
// How much of a worn part is left: each convex element's height above its foot and volume
// above it, the thinnest the part has become over its clamped bottom, its volume, and whether
// it is worn through. What a stage records of the part's life and what a run's end criterion
// (Coupling/Worn out when) reads.
#include "meshes/surface_mesh.h"

#include <map>

namespace wear::meshes {

/// A convex element (label C<j><k>) as it stands on the part.
struct ElementStanding {
  double top = 0;                ///< [m] its highest vertex (z)
  double foot = 0;               ///< [m] mean z of the vertices it shares with other wearing labels
  double volume = 0;             ///< [m^3] between its faces and the plane z = foot
  std::map<int, int> neighbours; ///< the wearing labels around it, with the edges it shares
  double height() const { return top - foot; } ///< [m]
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

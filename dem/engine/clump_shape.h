#pragma once
// A rigid clump of overlapping spheres: its members as given (a template), and the mass
// properties of their union in the body frame (the principal frame at the centre of mass).
#include "meshes/vec3.h"

#include <string>
#include <vector>

namespace wear::dem {

using meshes::Vec3;

struct ClumpMember {
  Vec3 centre;       ///< [m]
  double radius = 0; ///< [m]
};

/// A clump's geometry as given: any frame, any scale (the body frame and the size are derived).
struct ClumpTemplate {
  std::string name;
  std::vector<ClumpMember> members;
};

/// The union of a template's spheres as a rigid body at unit density. The body frame has its
/// origin at the centre of mass and its axes along the principal axes, the moments ascending.
struct ClumpShape {
  std::string name;
  std::vector<ClumpMember> members; ///< [m] in the body frame
  double volume = 0;                ///< [m^3] of the union (overlaps counted once)
  Vec3 moments;                     ///< [m^5] principal moments of inertia over density
  /// [-] The body axes as unit vectors of the template's frame (a right-handed triad).
  Vec3 axis[3];
  Vec3 centre; ///< [m] centre of mass in the template's frame
  /// [m] The diameter of the sphere of the same volume (a PSD's diameter of a clump).
  double equivalent_diameter() const;
  /// [m] The largest distance of a member's surface from the centre of mass.
  double reach() const;
  /// The same shape scaled by `factor` (members and reach x factor, volume x factor^3,
  /// moments x factor^5).
  ClumpShape scaled(double factor) const;
};

/// The mass properties of the union of t's spheres, integrated exactly along z over columns
/// of a regular grid in x and y (midpoint rule, `cells_per_radius` columns per smallest member
/// radius): the relative error of volume and moments falls as (1 / cells_per_radius)^1.5;
/// docs/theory.md states it. Throws std::invalid_argument naming the template and the member
/// for no members, a non-positive or non-finite radius or a non-finite centre.
ClumpShape clump_shape(const ClumpTemplate& t, int cells_per_radius = 200);

} // namespace wear::dem

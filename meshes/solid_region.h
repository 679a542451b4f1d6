#pragma once
// The solid a closed triangle surface encloses, as a region to fill with particles (a
// scene's Fill from a mesh file): whether a point lies inside, how far it is from the
// surface, and whether a triangle (a wall's) meets the solid.
#include "meshes/surface_locator.h"
#include "meshes/surface_mesh.h"

#include <string>

namespace wear::meshes {

class SolidRegion {
public:
  /// Takes a copy of `surface`, which must be closed (check_closed) and oriented outwards;
  /// throws std::invalid_argument naming `what` otherwise.
  SolidRegion(const SurfaceMesh& surface, const std::string& what);
  SolidRegion(const SolidRegion&) = delete; // the locator refers to the copy held here
  SolidRegion& operator=(const SolidRegion&) = delete;
  /// Winding number of the surface about p above one half (sum of the faces' signed solid
  /// angles, Van Oosterom and Strackee; exact for a closed surface, robust near it).
  bool contains(const Vec3& p) const;
  double distance(const Vec3& p) const; ///< [m] to the surface
  /// True when triangle abc and the closed solid share a point: a vertex of abc inside, an
  /// edge of abc through a face of the surface, or an edge of the surface through abc.
  bool cuts(const Vec3& a, const Vec3& b, const Vec3& c) const;
  const BoundingBox& box() const { return box_; }
  double volume() const { return volume_; } ///< [m^3]

private:
  SurfaceMesh surface_;
  SurfaceLocator locator_;
  BoundingBox box_;
  double volume_ = 0;
};

} // namespace wear::meshes

#pragma once
// Where a scene's fill places particles (Scene/Fill): the box, cylinder or solid of a mesh,
// for a bed height its loose part, checked clear of the walls. Built once by SceneRun
// (scene_run.h) before any particle exists.
#include "dem/engine/filling.h"
#include "dem/scene/scene_parameters.h"
#include "dem/scene/scene_walls.h"
#include "meshes/solid_region.h"

#include <memory>
#include <string>
#include <vector>

namespace wear::dem {

/// Where the fill places particles: the Fill box, cylinder or solid of a mesh, or for a bed
/// height its part up to DEM/Loose factor heights above its floor (loose, before settling).
struct SceneFillShape {
  bool cylinder = false;
  std::shared_ptr<const meshes::SolidRegion> solid; ///< Region = mesh
  std::string file;                                 ///< the mesh's, quoted, for messages
  Vec3 lo, hi;                                      ///< [m] the box; the cylinder's bounding box
  Vec3 base, axis;         ///< [m], [-] the cylinder's base centre and unit axis
  double length = 0;       ///< [m] the cylinder's
  double radius = 0;       ///< [m] the cylinder's
  double radius_inner = 0; ///< [m] the cylinder's hole
  double sector = 0;    ///< [rad] a cylinder about z filled only in 0 <= theta <= sector (0: all)
  double floor_z = 0;   ///< [m] the bed's floor
  double footprint = 0; ///< [m^2] horizontal area of a bed
  double full_top = 0;  ///< [m] the region's top before a bed height cuts it
  /// A wall wholly inside the region (submerged, like a sample in a bed): no centre is placed
  /// inside its solid or within a largest diameter of its surface when it is closed, within a
  /// largest diameter of its bounding box when it is not.
  struct Submerged {
    meshes::BoundingBox box;                          ///< [m]
    std::shared_ptr<const meshes::SolidRegion> solid; ///< none: an open surface
  };
  std::vector<Submerged> submerged;
  /// [m] bounding boxes of the submerged walls of Fill/Clear above: no centre above them
  std::vector<meshes::BoundingBox> cleared_above;
  double clearance = 0;        ///< [m] that diameter
  double submerged_volume = 0; ///< [m^3] the closed submerged walls' volume below the bed top
  /// The region in words, for messages.
  std::string describe() const;
  /// True when the triangle abc cuts the region (exact for a box and a cylinder).
  bool cuts(const Vec3& a, const Vec3& b, const Vec3& c) const;
  /// Centres admissible for spheres of radius `margin`, below z_top, clear of the submerged
  /// walls.
  FillRegion region(double margin, double z_top) const;
  /// True when every point of `points` lies inside the region (its loose part for a bed).
  bool contains_all(const std::vector<Vec3>& points) const;

private:
  FillRegion outline(double margin, double z_top) const;
};

/// The Fill region of scene s. In a periodic sector a cylinder about the z axis is filled in
/// the sector only (fills_sector_only), and its footprint is the sector's share. A fill to a
/// bed height is placed up to `loose_factor` heights above its floor.
SceneFillShape fill_shape(const SceneParameters& s, double loose_factor);

/// Throws when a triangle of a wall cuts the fill region, naming the wall and its file,
/// unless the whole wall lies inside the region: then it is submerged (a part standing in the
/// bed), recorded in `shape` (its volume below `bed_top` [m] counted) and left out of the fill.
/// Walls named in `clear_above_names` (Fill/Clear above) must be submerged; no centre is then
/// placed above them.
void require_clear_of_walls(const std::vector<SceneWall>& walls, SceneFillShape& shape,
                            double bed_top, const std::string& clear_above_names);

} // namespace wear::dem

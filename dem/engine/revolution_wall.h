#pragma once
// A wall that is a bounded surface of revolution (a cylinder, a cone frustum, a flat annulus or
// annular sector) with exact closest points: the tester's floor, cylinders and consolidator without
// triangles. Optional per-face wear accounting on a triangulation of the same surface.
#include "dem/engine/mesh_wall.h"

#include <cstdint>
#include <memory>
#include <string>

namespace wear::dem {

enum class RevolutionKind : std::uint8_t { cylinder, annulus, cone };
/// The two kinds of wall a System holds (System::wall_kind).
enum class WallKind : std::uint8_t { mesh, revolution };

/// The bounded surface, in coordinates about the axis: the axial coordinate
/// s = (x - axis_point) . axis, the distance rho from the axis, and the angle
/// theta = atan2((x - axis_point) . e2, (x - axis_point) . e1) in the wall's frame (e1, e2):
/// e1 is the x direction projected onto the plane normal to the axis (the y direction when
/// the axis lies within 25 degrees of x), e2 = axis x e1. For the z axis, theta = atan2(y, x).
struct RevolutionSurface {
  RevolutionKind kind = RevolutionKind::annulus;
  Vec3 axis_point;                     ///< [m]
  Vec3 axis{0, 0, 1};                  ///< [-] direction (normalised by the wall)
  double radius = 0;                   ///< [m] cylinder; cone: at s = axial_min
  double radius_top = 0;               ///< [m] cone: at s = axial_max
  double axial_min = 0, axial_max = 0; ///< [m] cylinder, cone: extent in s
  double height = 0;                   ///< [m] annulus: s of its plane
  double inner_radius = 0;             ///< [m] annulus (0: a disc)
  double outer_radius = 0;             ///< [m] annulus
  /// [rad] annulus: angular range theta_min <= theta <= theta_max; the full circle when it
  /// spans 2 pi (the default).
  double theta_min = 0, theta_max = 6.283185307179586;

  /// About the z axis through the origin: r = radius, axial_min <= z <= axial_max.
  static RevolutionSurface cylinder(double radius, double axial_min, double axial_max);
  /// About the z axis through the origin: axial_min <= z <= axial_max, the radius going
  /// linearly from r_min at axial_min to r_max at axial_max (either may be 0: an apex).
  static RevolutionSurface cone(double r_min, double r_max, double axial_min, double axial_max);
  /// About the z axis through the origin: z = height, r0 <= r <= r1, th0 <= atan2(y, x) <= th1
  /// (modulo 2 pi).
  static RevolutionSurface annulus(double height, double r0, double r1, double th0 = 0,
                                   double th1 = 6.283185307179586);
};

class RevolutionWall {
public:
  /// A `wearing` wall needs `accounting`, a triangulation of the same surface (e.g. from
  /// meshes::generate_tester_walls): each contact's wear integrals go to its face under the
  /// contact point. One triangle on the surface accounts the wall's loads as totals (every
  /// contact on face 0, no search). Throws std::invalid_argument naming the wall on bad input.
  RevolutionWall(const RevolutionSurface& surface, int material_id, const WallMotion& motion,
                 bool wearing, std::string name, const meshes::SurfaceMesh* accounting = nullptr);

  const std::string& name() const { return name_; }
  int material() const { return material_; }
  bool wearing() const { return wearing_; }
  RevolutionKind kind() const { return surface_.kind; }
  const RevolutionSurface& surface() const { return surface_; }
  const WallMotion& motion() const { return motion_; }
  /// Changes the rigid motion (e.g. start the floor's rotation after settling).
  void set_motion(const WallMotion& m) {
    motion_ = m;
    omega_ = meshes::normalized(m.axis) * m.angular_velocity;
  }
  Vec3 velocity_at(const Vec3& p) const {
    return meshes::cross(omega_, p - motion_.axis_point) + motion_.surface_velocity;
  }
  const Vec3& angular_velocity_vector() const { return omega_; }

  /// The closest point of the bounded surface to c (equations: revolution_wall.cc).
  Vec3 closest(const Vec3& c) const {
    switch (surface_.kind) {
    case RevolutionKind::cylinder:
      return closest_on_cylinder(c);
    case RevolutionKind::cone:
      return closest_on_cone(c);
    default:
      return closest_on_annulus(c);
    }
  }
  double distance(const Vec3& c) const { return meshes::norm(c - closest(c)); } ///< [m]

  /// The accounting triangulation (null without one).
  const MeshWall* accounting() const { return accounting_.get(); }
  /// Faces of the accounting triangulation (0 without one).
  std::size_t n_faces() const { return accounting_ ? accounting_->n_faces() : 0; }
  /// The accounting face under point p: the face whose closest point to p is nearest, the
  /// lowest index on ties. Needs an accounting triangulation.
  std::uint32_t accounting_face(const Vec3& p) const;

private:
  RevolutionSurface surface_;
  int material_;
  WallMotion motion_; ///< moves the surface velocity only: the geometry stays, as for MeshWall
  Vec3 omega_;        ///< [rad/s] angular velocity vector of the motion
  bool wearing_;
  std::string name_;
  Vec3 e1_, e2_;       ///< [-] the angle's frame in the plane normal to the axis
  Vec3 edge0_, edge1_; ///< [-] unit directions of the radial edges at theta_min, theta_max
  bool full_circle_ = true;
  bool wide_ = false;                          ///< the angular range spans more than pi
  double search_ = 0;                          ///< [m] reach of the accounting grid
  std::shared_ptr<const MeshWall> accounting_; ///< immutable, shared by copies
  /// Point c in the meridional half-plane of the axis: its axial coordinate [m], its distance
  /// from the axis [m] and the unit radial direction (e1 on the axis).
  struct Meridian {
    double along, rho;
    Vec3 radial;
  };
  Meridian meridian(const Vec3& c) const;
  Vec3 closest_on_cylinder(const Vec3& c) const;
  Vec3 closest_on_annulus(const Vec3& c) const;
  Vec3 closest_on_cone(const Vec3& c) const;
  bool within_angle(const Vec3& q) const;
  void check_surface() const;
  void set_accounting(const meshes::SurfaceMesh& mesh);
};

} // namespace wear::dem

#pragma once
// A triangle-mesh wall: geometry, the topology needed to count each physical contact once,
// a surface velocity or a rigid motion of the whole wall, a candidate-search grid, and
// optional per-face wear accumulation.
#include "dem/engine/rigid_motion.h"
#include "meshes/surface_mesh.h"
#include "meshes/triangle_geometry.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace wear::dem {

using meshes::Vec3;

/// Rigid rotation about an axis. The wall is treated as a surface of revolution about that
/// axis (floor and cylinders of the tester): its geometry is invariant, only the surface
/// velocity omega x (p - axis_point) enters the contacts.
struct WallMotion {
  Vec3 axis_point;             ///< [m]
  Vec3 axis{0, 0, 1};          ///< unit vector
  double angular_velocity = 0; ///< [rad/s], right-handed about axis
  /// Uniform translation velocity of the surface (conveyor), added to the rotation. [m/s]
  Vec3 surface_velocity;
};

using Feature = meshes::TriangleFeature;
/// Closest point of a sphere centre on one triangle, with the feature that holds it.
using ClosestFeature = meshes::TrianglePoint;

/// What the rejection tests of a candidate face read, in one cache line: the face's plane and
/// its bounding sphere. Most candidates are rejected by these tests, before the closest-point
/// search.
struct alignas(64) FaceBound {
  Vec3 normal;   ///< unit
  double offset; ///< [m] normal . (a corner): the plane is normal . x = offset
  Vec3 centre;   ///< [m] centroid
  double radius; ///< [m] largest centroid-corner distance, slightly widened

  /// Distance of c from the plane [m]: a lower bound of the distance to the triangle.
  double plane_distance(const Vec3& c) const { return std::abs(meshes::dot(c, normal) - offset); }
  /// True when no point of the triangle lies closer to c than r: c is at least r beyond the
  /// bounding sphere. It rejects the faces whose plane passes near c but which lie elsewhere
  /// on a curved surface.
  bool beyond_sphere(const Vec3& c, double r) const {
    const double reach = r + radius;
    return meshes::norm2(c - centre) >= reach * reach;
  }
  /// The same where h < r is c's distance from the plane: the ball of radius r meets the plane
  /// in the disc of radius sqrt(r^2 - h^2) about c's projection, and that disc misses the
  /// bounding circle (the bounding sphere's section through the centroid). Tighter than
  /// beyond_sphere when c lies about r from the plane, as over a flat patch of a fine mesh,
  /// where most candidate faces pass the other two tests. Widened by a relative 1e-9.
  bool beyond_disc(const Vec3& c, double r, double h) const {
    const double reach = std::sqrt(r * r - h * h) + radius;
    return meshes::norm2(c - centre) - h * h >= reach * reach * (1 + 1e-9);
  }
  /// True when the triangle cannot touch a sphere of radius r about c (the three tests).
  bool rejects(const Vec3& c, double r) const {
    const double h = plane_distance(c);
    return h >= r || beyond_sphere(c, r) || beyond_disc(c, r, h);
  }
};

/// How a triangle's closest feature counts as a contact (MeshWall::contact_ownership).
enum class ContactOwnership : std::uint8_t {
  none,    ///< not a contact of this triangle: another face reports it, or a closer point exists
  owned,   ///< a contact
  junction ///< a contact on the border of covered faces, dropped where another wall's is as deep
};

class MeshWall {
public:
  /// `covered_labels`: labels of faces held flush against another wall (the sample's sides
  /// and bottom in its holder, the holder's pocket), see contact_ownership.
  MeshWall(const meshes::SurfaceMesh& mesh, int material_id, const WallMotion& motion, bool wearing,
           std::string name, std::vector<int> covered_labels = {});

  const std::string& name() const { return name_; }
  int material() const { return material_; }
  bool wearing() const { return wearing_; }
  const std::vector<int>& covered_labels() const { return covered_labels_; }
  const WallMotion& motion() const { return motion_; }
  /// Changes the surface motion (e.g. start the floor's rotation after settling).
  void set_motion(const WallMotion& m) {
    motion_ = m;
    omega_ = meshes::normalized(m.axis) * m.angular_velocity;
  }
  const meshes::SurfaceMesh& mesh() const { return mesh_; }
  std::size_t n_faces() const { return mesh_.n_faces(); }

  /// Gives the wall a rigid motion of its geometry (rigid_motion.h): the mesh as given is its
  /// body frame, where it is at the motion's start time. Exclusive with a surface motion
  /// (WallMotion); throws std::invalid_argument naming the wall for both or a bad motion.
  void set_rigid_motion(const RigidMotion& m);
  const RigidMotion& rigid_motion() const { return rigid_; }
  /// True when the geometry moves: contact searches then take points into the body frame.
  bool moving() const { return moving_; }
  /// The pose at the time of the last move_to() (identity for a wall that does not move).
  const RigidPose& pose() const { return pose_; }
  /// Places a moving wall at time t [s]; nothing for another.
  void move_to(double t) {
    if (moving_)
      pose_ = pose_at(rigid_, t);
  }
  /// The current pose becomes the one displacement() measures from (a list rebuild).
  void mark_reference() { reference_pose_ = pose_; }
  /// [m] Upper bound of the distance any point of the wall moved since mark_reference().
  double displacement() const {
    return moving_ ? max_displacement(reference_pose_, pose_, axis_reach_) : 0.0;
  }
  /// A point of the mesh (body frame) where it is now (world frame), and back.
  Vec3 to_world(const Vec3& body) const { return moving_ ? pose_.to_world(body) : body; }
  Vec3 to_body(const Vec3& world) const { return moving_ ? pose_.to_body(world) : world; }
  /// The mesh's vertices where they are now [m].
  std::vector<Vec3> world_vertices() const;

  /// [m/s] Velocity of the wall's material point at mesh point p (body frame).
  Vec3 velocity_at(const Vec3& p) const {
    if (moving_)
      return pose_.velocity_at(pose_.to_world(p));
    return meshes::cross(omega_, p - motion_.axis_point) + motion_.surface_velocity;
  }
  /// [rad/s] The wall's angular velocity (for the rolling resistance).
  const Vec3& angular_velocity_vector() const { return moving_ ? pose_.omega : omega_; }

  /// Plane and bounding sphere of triangle f (FaceBound's rejection tests).
  const FaceBound& bound(std::uint32_t f) const { return bound_[f]; }

  /// Closest point of triangle f to c (meshes::closest_point_on_triangle).
  ClosestFeature closest(std::uint32_t f, const Vec3& c) const;

  /// Whether the closest feature found on triangle f is the mesh's own closest feature near
  /// that point (a local distance minimum over the faces sharing it) with f the one triangle
  /// that reports it. Face contacts always qualify; an edge or vertex contact is dropped
  /// (`none`) when moving into a neighbouring face brings the point closer to c. An edge or
  /// vertex where a covered face meets an uncovered one is judged on its uncovered faces only
  /// and reported as a `junction`: another wall covers the covered side, and where that wall
  /// continues the surface flush its own contact stands for this one (the force pass then
  /// drops the junction contact, see system_contacts.cc); where the surfaces have parted
  /// (a worn face below its holder's rim) the junction contact is the only one there. Face
  /// contacts on covered faces stay, so a particle that reaches one is seen.
  ContactOwnership contact_ownership(std::uint32_t f, const ClosestFeature& cf,
                                     const Vec3& c) const;

  /// Faces that share the contact's feature and each one's share of it (for splitting
  /// extensive wear quantities; shares sum to 1): a face contact stays on its face, an edge
  /// contact is halved between the two faces, a vertex contact is split by the faces'
  /// interior angles at the vertex. Writes up to max_out entries, returns the count.
  int faces_sharing(std::uint32_t f, const ClosestFeature& cf, std::uint32_t* out, double* weight,
                    int max_out) const;

  /// Moves the vertices (same count and topology, in the body frame), recomputes the geometry and
  /// the candidate grid and bumps the mesh revision. Throws if a triangle degenerates.
  void set_vertices(const std::vector<Vec3>& vertices);

  /// Builds the candidate grid (body frame): every face is registered in each cell its bounding
  /// box, inflated by `reach`, overlaps.
  void build_grid(double reach);
  /// Faces that may lie within `reach` of point c of the body frame (empty outside the grid).
  std::pair<const std::uint32_t*, const std::uint32_t*> candidates(const Vec3& c) const;

private:
  meshes::SurfaceMesh mesh_;
  int material_;
  WallMotion motion_;
  Vec3 omega_;
  RigidMotion rigid_;
  bool moving_ = false;
  RigidPose pose_, reference_pose_;
  double axis_reach_ = 0; ///< [m] largest vertex distance from the rigid motion's axis
  bool wearing_;
  std::string name_;
  std::vector<int> covered_labels_;
  std::vector<std::array<Vec3, 3>> corners_;
  std::vector<Vec3> normal_;
  std::vector<FaceBound> bound_;
  std::vector<std::array<std::uint32_t, 3>> face_edge_; // edge k of face f: global id
  std::vector<std::array<std::uint32_t, 2>> edge_face_; // adjacent faces (second = ~0u: none)
  std::vector<std::array<std::uint32_t, 2>> edge_vertex_;
  std::vector<std::array<Vec3, 3>> inward_; // in-plane unit normal of edge k, into f
  /// The face that reports a vertex contact: the lowest-numbered one at v, uncovered at a
  /// junction vertex.
  std::vector<std::uint32_t> vertex_first_face_;
  std::vector<std::uint32_t> vertex_edge_offset_, vertex_edge_; // CSR: edges at v
  std::vector<Vec3> vertex_edge_dir_;                           // unit, away from v
  std::vector<char> vertex_edge_open_; // the edge borders an uncovered face
  std::vector<char> face_covered_;
  std::vector<std::uint32_t> vertex_face_offset_, vertex_face_; // CSR: faces at v
  std::vector<double> vertex_face_weight_;                      // interior-angle share
  std::vector<char> edge_junction_, vertex_junction_; // joins a covered and an uncovered face
  void compute_geometry();
  // candidate grid
  Vec3 grid_min_;
  double cell_ = 0, reach_ = 0;
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<std::uint32_t> cell_offset_, cell_face_;
};

} // namespace wear::dem

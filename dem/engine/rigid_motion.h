#pragma once
// A wall's rigid-body motion (scene walls that rotate, translate or oscillate): the pose of
// its geometry as a function of time. The mesh as given is the wall's body frame; the engine
// moves particles into that frame for the contact search instead of moving the vertices.
#include "meshes/vec3.h"

#include <limits>
#include <string>

namespace wear::dem {

using meshes::Vec3;

/// x(X, t) = p + T(tau) + R(tau) (X - p) for a point X of the mesh as given, with
/// tau = min(max(0, t - start_time), end_time - start_time): a rotation by omega tau about
/// the axis through p, composed with the translation T(tau) = v tau + A (sin(2 pi f tau +
/// phi) - sin phi). Before start_time the wall rests where its mesh is, after end_time where
/// the motion left it (a gate that opens).
struct RigidMotion {
  Vec3 axis_point;             ///< [m] p
  Vec3 axis{0, 0, 1};          ///< [-] rotation axis, any length
  double angular_velocity = 0; ///< [rad/s] omega, right-handed about axis
  Vec3 velocity;               ///< [m/s] v
  Vec3 amplitude;              ///< [m] A
  double frequency = 0;        ///< [Hz] f
  double phase = 0;            ///< [rad] phi
  double start_time = 0;       ///< [s]
  double end_time = std::numeric_limits<double>::infinity(); ///< [s]
  /// True when the motion moves the geometry at all.
  bool moves() const;
};

/// A RigidMotion evaluated at one time: x = R X + offset.
struct RigidPose {
  Vec3 row[3]{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; ///< [-] rows of the rotation R
  Vec3 offset;                                  ///< [m]
  Vec3 centre;                                  ///< [m] p + T: where the axis point is now
  Vec3 translation;                             ///< [m] T
  Vec3 velocity;                                ///< [m/s] dT/dt
  Vec3 omega;                                   ///< [rad/s] angular velocity vector
  double angle = 0;                             ///< [rad] omega tau

  Vec3 rotate(const Vec3& v) const {
    return {meshes::dot(row[0], v), meshes::dot(row[1], v), meshes::dot(row[2], v)};
  }
  Vec3 rotate_back(const Vec3& v) const { return row[0] * v.x + row[1] * v.y + row[2] * v.z; }
  Vec3 to_world(const Vec3& body) const { return rotate(body) + offset; }
  Vec3 to_body(const Vec3& world) const { return rotate_back(world - offset); }
  /// [m/s] Velocity of the wall's material point now at world position x.
  Vec3 velocity_at(const Vec3& x) const { return velocity + meshes::cross(omega, x - centre); }
};

/// The pose of motion m at time t [s].
RigidPose pose_at(const RigidMotion& m, double t);

/// [m] An upper bound of the distance any point of the wall moved from pose a to pose b
/// (of one motion), for points at most `axis_reach` [m] from the rotation axis:
/// |T_b - T_a| + 2 |sin((angle_b - angle_a) / 2)| axis_reach.
double max_displacement(const RigidPose& a, const RigidPose& b, double axis_reach);

/// [m] The largest distance of the points [first, last) from the axis of m.
double axis_reach(const RigidMotion& m, const Vec3* first, const Vec3* last);

/// Checks the values (finite, an axis for a rotation, a frequency for an amplitude, f >= 0);
/// throws std::invalid_argument naming `what`.
void validate(const RigidMotion& m, const std::string& what);

} // namespace wear::dem

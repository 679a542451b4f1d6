#pragma once
// The orientation of a rigid body as a unit quaternion, and its free rotation over a time
// step by the symmetric splitting of the kinetic energy over the principal axes (Dullweber,
// Leimkuhler & McLachlan 1997; the NO_SQUISH scheme of Miller et al. 2002 is the same map).
#include "meshes/vec3.h"

#include <cstddef>

namespace wear::dem {

using meshes::Vec3;

/// q = w + x i + y j + z k; a unit quaternion turns the body frame into the space frame.
struct Quaternion {
  double w = 1, x = 0, y = 0, z = 0;
};

/// The Hamilton product a b (the rotation b, then a).
constexpr Quaternion operator*(const Quaternion& a, const Quaternion& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

/// The unit quaternion of a rotation by `angle` [rad] about the unit vector `axis`.
Quaternion rotation_about(const Vec3& axis, double angle);

/// q / |q|.
Quaternion normalized(const Quaternion& q);

/// The rotation of q applied to v: body frame -> space frame.
inline Vec3 rotate(const Quaternion& q, const Vec3& v) {
  // v + 2 w (u x v) + 2 u x (u x v), u the vector part (no matrix built).
  const Vec3 u{q.x, q.y, q.z};
  const Vec3 t = meshes::cross(u, v) * 2.0;
  return v + t * q.w + meshes::cross(u, t);
}

/// The inverse rotation: space frame -> body frame.
inline Vec3 rotate_back(const Quaternion& q, const Vec3& v) {
  return rotate({q.w, -q.x, -q.y, -q.z}, v);
}

/// [rad/s] The angular velocity in the space frame of a body of principal moments `moments`
/// [kg m^2] and orientation q with the angular momentum L [kg m^2/s] (space frame).
inline Vec3 angular_velocity(const Quaternion& q, const Vec3& moments, const Vec3& L) {
  const Vec3 l = rotate_back(q, L);
  return rotate(q, {l.x / moments.x, l.y / moments.y, l.z / moments.z});
}

/// [J] The rotational kinetic energy L_b . I^-1 L_b / 2.
inline double rotational_energy(const Quaternion& q, const Vec3& moments, const Vec3& L) {
  const Vec3 l = rotate_back(q, L);
  return 0.5 * (l.x * l.x / moments.x + l.y * l.y / moments.y + l.z * l.z / moments.z);
}

/// Advances the orientation q of a torque-free body with the angular momentum L (space
/// frame, constant in the exact flow and left as it is) over dt [s]. The kinetic energy is
/// split by body axis, T = sum_k L_k^2 / (2 I_k); each part's flow is exact (a rotation about
/// body axis k by L_k dt / I_k) and they are composed symmetrically, axis 1 and 2 over dt/2,
/// axis 3 over dt, then 2 and 1 over dt/2: second order, time-reversible and symplectic, the
/// angular momentum kept exactly and the energy error bounded (no drift). q is renormalized.
void rotate_freely(Quaternion& q, const Vec3& L, const Vec3& moments, double dt);

/// rotate_freely for n bodies, body b with q[b], L[b] and moments[b]: the same result per body
/// as n single calls, faster (the bodies' operations overlap).
void rotate_freely(std::size_t n, Quaternion* q, const Vec3* L, const Vec3* moments, double dt);

} // namespace wear::dem

// Free rotation of a rigid body over one step by the symmetric splitting of its kinetic energy.
//
// With L the angular momentum in the space frame and R(q) the body's rotation, the body-frame
// momentum is l = R^T L and T = sum_k l_k^2 / (2 I_k). Under T_k = l_k^2 / (2 I_k) alone, l_k
// is constant and the body turns about its own axis k at the rate l_k / I_k, so the exact
// flow over tau is q <- q r_k(l_k tau / I_k), r_k the rotation about the body axis e_k
// (right multiplication: a turn in the body frame). L is untouched by every part, so it is
// kept exactly; the composition 1(dt/2) 2(dt/2) 3(dt) 2(dt/2) 1(dt/2) is symmetric, hence
// second order and time-reversible, and as a composition of exact Hamiltonian flows it is
// symplectic: the energy error stays bounded, O((|omega| dt)^2), and does not drift.
// Torques enter as kicks of L around this map (the engine's half-steps).
#include "dem/engine/rigid_body.h"

#include <cmath>

namespace wear::dem {

Quaternion rotation_about(const Vec3& axis, double angle) {
  const double s = std::sin(0.5 * angle);
  return {std::cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s};
}

Quaternion normalized(const Quaternion& q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

namespace {

/// The exact flow of T_k over tau: q <- q r_k(l_k tau / I_k).
void turn_about_body_axis(Quaternion& q, const Vec3& L, const Vec3& moments, int k, double tau) {
  const double l_k = rotate_back(q, L)[k];
  const double half = 0.5 * l_k * tau / moments[k];
  const double c = std::cos(half), s = std::sin(half);
  Quaternion r{c, 0, 0, 0};
  (k == 0 ? r.x : k == 1 ? r.y : r.z) = s;
  q = q * r;
}

} // namespace

void rotate_freely(Quaternion& q, const Vec3& L, const Vec3& moments, double dt) {
  const double h = 0.5 * dt;
  turn_about_body_axis(q, L, moments, 0, h);
  turn_about_body_axis(q, L, moments, 1, h);
  turn_about_body_axis(q, L, moments, 2, dt);
  turn_about_body_axis(q, L, moments, 1, h);
  turn_about_body_axis(q, L, moments, 0, h);
  q = normalized(q);
}

} // namespace wear::dem

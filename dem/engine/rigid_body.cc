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

/// cos x and sin x; for |x| < 0.02 (a step's half-turn, |omega| dt / 2 is about 1e-3 in a
/// bed) by their series to x^8 and x^9, whose next terms are below 1e-19 relative: the same
/// values to round-off, without the library's range reduction (five per body and step).
void cos_sin(double x, double& c, double& s) {
  if (!(std::abs(x) < 0.02)) {
    c = std::cos(x), s = std::sin(x);
    return;
  }
  const double x2 = x * x;
  c = 1 + x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320))));
  s = x * (1 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880)))));
}

/// Component k of the vector part of q, k known at compile time.
template <int K>
double& component(Quaternion& q) {
  if constexpr (K == 0)
    return q.x;
  else if constexpr (K == 1)
    return q.y;
  else
    return q.z;
}

/// The exact flow of T_k over tau for N bodies: q <- q r_k(l_k tau / I_k), with l = R(q)^T L
/// the body-frame momentum, which the same turn carries along: it rotates by -theta about
/// e_k (theta the body's turn), so that it is computed from L once per step. The bodies'
/// turns are independent chains of dependent operations (a division, a series, products);
/// taken side by side, a core overlaps them.
template <int K, int N>
void turn_about_body_axis(Quaternion (&q)[N], Vec3 (&l)[N], const Vec3* moments, double tau) {
  constexpr int I = (K + 1) % 3, J = (K + 2) % 3; // e_i x e_j = e_k
  for (int n = 0; n < N; ++n) {
    const double half = 0.5 * l[n][K] * tau / moments[n][K];
    double c, s;
    cos_sin(half, c, s);
    // q r_k with r_k = cos(half) + sin(half) e_k: the product with two non-zero components.
    Quaternion& a = q[n];
    const double w = a.w * c - component<K>(a) * s;
    const double vk = component<K>(a) * c + a.w * s;
    const double vi = component<I>(a) * c + component<J>(a) * s;
    const double vj = component<J>(a) * c - component<I>(a) * s;
    a.w = w, component<K>(a) = vk, component<I>(a) = vi, component<J>(a) = vj;
    // l in the turned body frame: rotated by -theta about e_k, cos theta = c^2 - s^2,
    // sin theta = 2 s c.
    const double ct = c * c - s * s, st = 2 * s * c;
    const double li = l[n][I], lj = l[n][J];
    l[n][I] = ct * li + st * lj;
    l[n][J] = -st * li + ct * lj;
  }
}

/// rotate_freely for the N bodies at q, L and moments.
template <int N>
void rotate_bodies(Quaternion* q, const Vec3* L, const Vec3* moments, double dt) {
  const double h = 0.5 * dt;
  Quaternion a[N];
  Vec3 l[N];
  for (int n = 0; n < N; ++n) {
    a[n] = q[n];
    l[n] = rotate_back(q[n], L[n]);
  }
  turn_about_body_axis<0>(a, l, moments, h);
  turn_about_body_axis<1>(a, l, moments, h);
  turn_about_body_axis<2>(a, l, moments, dt);
  turn_about_body_axis<1>(a, l, moments, h);
  turn_about_body_axis<0>(a, l, moments, h);
  for (int n = 0; n < N; ++n)
    q[n] = normalized(a[n]);
}

} // namespace

void rotate_freely(Quaternion& q, const Vec3& L, const Vec3& moments, double dt) {
  rotate_bodies<1>(&q, &L, &moments, dt);
}

void rotate_freely(std::size_t n, Quaternion* q, const Vec3* L, const Vec3* moments, double dt) {
  // Four side by side; each body's operations are those of the single call, so the result
  // does not depend on where a body falls in the blocks.
  std::size_t b = 0;
  for (; b + 4 <= n; b += 4)
    rotate_bodies<4>(q + b, L + b, moments + b, dt);
  for (; b < n; ++b)
    rotate_bodies<1>(q + b, L + b, moments + b, dt);
}

} // namespace wear::dem

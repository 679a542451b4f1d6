#pragma once
// Hertz-Mindlin (no slip) contact with restitution-based viscous damping, tangential
// history with a Coulomb limit, and constant-directional-torque rolling friction
// (docs/theory.md section 2). The tangential force acts at the undeformed radius
// (rigid-body lever, as in the Chung & Ooi relations and EDEM); rolling friction uses the
// centre-to-contact distance as docs/theory.md section 2 states. Inline: called once per contact
// per step, never through a virtual function.
#include "dem/engine/material.h"
#include "meshes/vec3.h"

#include <cmath>

namespace wear::dem {

using meshes::Vec3;

struct ContactGeometry {
  Vec3 normal;        ///< unit, from the partner towards particle i
  double overlap = 0; ///< [m] > 0 in contact
  double r_eff = 0;   ///< [m] R* (R_i for a wall)
  double m_eff = 0;   ///< [kg] m* (m_i for a wall)
  double arm_i = 0;   ///< [m] centre of i to the contact point (rolling friction arm)
  double arm_j = 0;   ///< [m] centre of the partner to the contact point (0 for a wall)
  double lever_i = 0; ///< [m] lever of the tangential force on i: the undeformed radius
  double lever_j = 0; ///< [m] same for the partner (0 for a wall)
  Vec3 v_contact;     ///< [m/s] velocity of i's contact point minus the partner's
  Vec3 w_relative;    ///< [rad/s] angular velocity of i minus the partner's
};

struct ContactResult {
  Vec3 force;              ///< [N] on i (the partner gets the opposite)
  Vec3 torque_i;           ///< [N m] on i
  Vec3 torque_j;           ///< [N m] on the partner
  double normal_force = 0; ///< [N] |F_n| after the clamp
  Vec3 tangential_force;   ///< [N] on i
  Vec3 v_tangential;       ///< [m/s] tangential relative velocity at the contact
  double rotation_eps = 0; ///< [-] (delta . n)^2 / |delta|^2 of the history's rotation
};

/// The history's rotation into the tangent plane takes its series 1 + eps/2 + 3 eps^2/8 when
/// eps = (delta . n)^2 / |delta|^2 is below this; above it, the exact scale (1 - eps)^(-1/2).
constexpr double rotation_series_limit = 1e-4;

/// Updates the tangential history `delta_t` [m] and returns forces and torques.
/// Branch-free (every case computed, the valid one selected) so that the pair kernel can run
/// it in SIMD lanes, several contacts at once; the wall path calls it one contact at a time.
/// Square roots: sqrt(R* delta), sqrt(S_n m*) (the tangential damping follows from the
/// normal one: c_t / c_n = sqrt(S_t / S_n) = sqrt(4 G* / E*), a constant per pair type), one
/// for the spin direction, one for the Coulomb scaling and one for the history rotation.
/// `series_only`: the history's rotation by its series alone, one square root and one
/// division fewer; the law itself where ContactResult::rotation_eps < rotation_series_limit
/// (the SIMD lanes of the pair kernel redo the other contacts with series_only = false).
template <bool series_only = false>
__attribute__((always_inline)) inline ContactResult
hertz_mindlin(const ContactParameters& p, const ContactGeometry& g, double dt, Vec3& delta_t) {
  using meshes::cross;
  using meshes::dot;
  constexpr double tiny = 1e-300; // keeps the unselected branch of a select finite
  ContactResult r;
  const Vec3& n = g.normal;
  const double sqrt_rd = std::sqrt(g.r_eff * g.overlap);
  const double s_n = 2 * p.e_star * sqrt_rd;
  const double s_t = 8 * p.g_star * sqrt_rd;
  constexpr double two_sqrt_5_6 = 1.8257418583505538;                   // 2 sqrt(5/6)
  const double c_n = -two_sqrt_5_6 * p.beta * std::sqrt(s_n * g.m_eff); // >= 0
  const double c_t = c_n * p.tangential_damping_ratio;
  const double v_n = dot(g.v_contact, n);            // < 0 while approaching
  const double f_el = (2.0 / 3.0) * s_n * g.overlap; // 4/3 E* sqrt(R*) delta^(3/2)
  const double f_n = std::max(0.0, f_el - c_n * v_n);

  const Vec3 v_t = g.v_contact - n * v_n;
  // History into the current tangent plane, keeping its length (rigid rotation): scale
  // sqrt(d_len2 / l2) = (1 - eps)^(-1/2), eps = dn^2 / d_len2. The normal turns little per
  // step (eps ~ 1e-6), where the series 1 + eps/2 + 3 eps^2/8 is exact to eps^3 / 3 < 1e-12
  // relative. A zero history stays zero whatever the scale.
  const double d_len2 = dot(delta_t, delta_t);
  const double dn = dot(delta_t, n);
  const double l2 = d_len2 - dn * dn;
  const double eps = dn * dn / std::max(d_len2, tiny);
  const double series = 1 + eps * (0.5 + 0.375 * eps);
  double scale = series;
  r.rotation_eps = eps;
  if constexpr (!series_only) {
    const double exact = std::sqrt(d_len2 / std::max(l2, tiny));
    scale = eps < rotation_series_limit ? series : (l2 > 0 ? exact : 0.0);
  }
  delta_t = (delta_t - n * dn) * scale + v_t * dt;
  Vec3 f_t = delta_t * (-s_t) - v_t * c_t;
  // Coulomb limit: scaled onto the cone, the spring alone carrying the limit.
  const double f_t2 = dot(f_t, f_t), f_max = p.friction * f_n;
  const bool sliding = f_t2 > f_max * f_max;
  const double to_cone = f_max / std::sqrt(std::max(f_t2, tiny));
  f_t = f_t * (sliding ? to_cone : 1.0);
  const double inv_st = -1.0 / std::max(s_t, tiny);
  const Vec3 slid = f_t * (s_t > 0 ? inv_st : 0.0);
  delta_t.x = sliding ? slid.x : delta_t.x;
  delta_t.y = sliding ? slid.y : delta_t.y;
  delta_t.z = sliding ? slid.z : delta_t.z;
  r.normal_force = f_n;
  r.tangential_force = f_t;
  r.v_tangential = v_t;
  r.force = n * f_n + f_t;
  const Vec3 nxf = cross(n, f_t);
  // Rolling friction: a torque of mu_r F_n against the relative spin, on both lever arms.
  const double w2 = dot(g.w_relative, g.w_relative);
  const double m_r = p.rolling_friction * f_n / std::sqrt(std::max(w2, tiny));
  const Vec3 w_hat = g.w_relative * (w2 > 0 ? m_r : 0.0);
  r.torque_i = nxf * (-g.lever_i) - w_hat * g.arm_i;
  r.torque_j = nxf * (-g.lever_j) + w_hat * g.arm_j;
  return r;
}

} // namespace wear::dem

#pragma once
// Hertz-Mindlin (no slip) contact with restitution-based viscous damping, tangential
// history with a Coulomb limit, and constant-directional-torque rolling friction
// (shared/spec/model.md section 2). The tangential force acts at the undeformed radius
// (rigid-body lever, as in the Chung & Ooi relations and EDEM); rolling friction uses the
// centre-to-contact distance as model.md asks. Inline: called once per contact per step, never
// through a virtual function.
#include "dem/material.h"
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
};

/// Updates the tangential history `delta_t` [m] and returns forces and torques.
inline ContactResult hertz_mindlin(const ContactParameters& p, const ContactGeometry& g, double dt,
                                   Vec3& delta_t) {
  using meshes::cross;
  using meshes::dot;
  using meshes::norm;
  ContactResult r;
  const Vec3& n = g.normal;
  const double sqrt_rd = std::sqrt(g.r_eff * g.overlap);
  const double s_n = 2 * p.e_star * sqrt_rd;
  const double s_t = 8 * p.g_star * sqrt_rd;
  constexpr double two_sqrt_5_6 = 1.8257418583505538; // 2 sqrt(5/6)
  const double v_n = dot(g.v_contact, n);             // < 0 while approaching
  const double f_el = 4.0 / 3.0 * p.e_star * sqrt_rd * g.overlap;
  const double f_damp = two_sqrt_5_6 * p.beta * std::sqrt(s_n * g.m_eff) * v_n;
  const double f_n = std::max(0.0, f_el + f_damp);

  const Vec3 v_t = g.v_contact - n * v_n;
  // History into the current tangent plane, keeping its length (rigid rotation).
  const double d_len2 = dot(delta_t, delta_t);
  if (d_len2 > 0) {
    Vec3 d = delta_t - n * dot(delta_t, n);
    const double l2 = dot(d, d);
    delta_t = l2 > 0 ? d * std::sqrt(d_len2 / l2) : Vec3{};
  }
  delta_t += v_t * dt;
  const double c_t = -two_sqrt_5_6 * p.beta * std::sqrt(s_t * g.m_eff);
  Vec3 f_t = delta_t * (-s_t) - v_t * c_t;
  const double f_t_len = norm(f_t), f_max = p.friction * f_n;
  if (f_t_len > f_max) {
    f_t = f_t_len > 0 ? f_t * (f_max / f_t_len) : Vec3{};
    delta_t = s_t > 0 ? f_t * (-1.0 / s_t) : Vec3{}; // spring alone carries the limit
  }
  r.normal_force = f_n;
  r.tangential_force = f_t;
  r.v_tangential = v_t;
  r.force = n * f_n + f_t;
  r.torque_i = cross(n * (-g.lever_i), f_t);
  r.torque_j = cross(n * g.lever_j, f_t * -1.0);
  if (p.rolling_friction > 0) {
    const double w = norm(g.w_relative);
    if (w > 0) {
      const Vec3 w_hat = g.w_relative / w;
      r.torque_i -= w_hat * (p.rolling_friction * f_n * g.arm_i);
      r.torque_j += w_hat * (p.rolling_friction * f_n * g.arm_j);
    }
  }
  return r;
}

} // namespace wear::dem

// Rigid clumps in the System's step: the bodies' velocity Verlet and rotation, their members
// placed by the pose, the members' contact forces gathered onto the bodies.
//
// Per step, for body b with force F_b and torque T_b (gravity and the members' contacts of
// the last evaluation):
//   v_b += dt/2 F_b / m_b,  L_b += dt/2 T_b            (opening half-kick)
//   x_b += dt v_b,  q_b <- free rotation over dt        (rigid_body.h, L_b kept)
//   members placed: x_i = x_b + R(q_b) c_i, v_i = v_b + omega_b x (x_i - x_b), spin omega_b
//   contact forces on the members, F_b = m_b g + sum F_i, T_b = sum (x_i - x_b) x F_i + T_i
//   v_b += dt/2 F_b / m_b,  L_b += dt/2 T_b            (closing half-kick)
// As for spheres, the closing half-kick of a step and the opening one of the next are one
// pass in run(), the same operations in the same order as step() by step(). Members are
// particles for everything else: lists, contacts, walls, wear integrals, the speed and domain
// checks and the rebuild trigger (their displacement since the last rebuild).
#include "dem/engine/system.h"

#include <omp.h>

#include <cmath>
#include <stdexcept>

namespace wear::dem {

std::size_t System::add_clump(const ClumpShape& shape, double density, int material, const Vec3& x,
                              const Quaternion& q, const Vec3& v, const Vec3& w) {
  if (set_up_)
    throw std::logic_error("System::add_clump() after setup()");
  const std::string what =
      "DEM: clump " + std::to_string(clumps_.size()) + " ('" + shape.name + "')";
  if (shape.members.empty() || !(shape.volume > 0))
    throw std::invalid_argument(what + " has no members");
  if (!(density > 0) || !std::isfinite(density))
    throw std::invalid_argument(what + " has a non-positive density");
  if (material < 0 || material >= materials.n_materials())
    throw std::invalid_argument(what + " refers to an unknown material");
  const double norm_q = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  if (!(norm_q > 0) || !std::isfinite(norm_q))
    throw std::invalid_argument(what + " has no orientation (a zero quaternion)");
  place_clump(shape, density, material, x, normalized(q), v, w, false);
  return clumps_.size() - 1;
}

void System::place_clump(const ClumpShape& shape, double density, int material, const Vec3& x,
                         const Quaternion& qn, const Vec3& v, const Vec3& w, bool new_ids) {
  const double m = density * shape.volume;
  const Vec3 moments = shape.moments * density;
  auto& p = particles;
  std::vector<std::int64_t> ids;
  std::vector<Vec3> offsets;
  for (const ClumpMember& c : shape.members) {
    const Vec3 arm = rotate(qn, c.centre);
    p.add(x + arm, v + meshes::cross(w, arm), c.radius, density, material);
    // A member carries its body's mass: a contact's effective mass is that of the bodies.
    p.angular_velocity.back() = w;
    p.mass.back() = m;
    p.inertia.back() = (moments.x + moments.y + moments.z) / 3;
    if (new_ids)
      p.id.back() = next_id_++;
    ids.push_back(p.id.back());
    offsets.push_back(c.centre);
  }
  const Vec3 wb = rotate_back(qn, w);
  const Vec3 L = rotate(qn, {moments.x * wb.x, moments.y * wb.y, moments.z * wb.z});
  clumps_.add_body(x, v, qn, L, m, moments, ids, offsets);
  if (new_ids) // inserted between steps: the next half-kick takes gravity on the body
    clumps_.force.back() = settings.gravity * m;
}

void System::add_state_clumps(const ClumpsState& state) {
  if (set_up_)
    throw std::logic_error("System::add_state_clumps() after setup()");
  if (!clumps_.empty())
    throw std::logic_error("System::add_state_clumps() on a system with clumps");
  clumps_.restore(state);
}

std::pair<std::size_t, std::size_t> System::body_range(int thread) const {
  const std::size_t n = clumps_.size();
  return {n * thread / n_threads_, n * (thread + 1) / n_threads_};
}

void System::drift_clumps(int thread, bool close_previous, double& max_moved2) {
  auto& c = clumps_;
  auto& p = particles;
  const double h = 0.5 * dt_, vmax2 = settings.max_speed * settings.max_speed;
  const auto [b0, b1] = body_range(thread);
  // Three passes over the bodies, each body's operations in the order of one pass: the kicks
  // and the drift, the rotations side by side (rigid_body.h), the members placed.
  for (std::size_t b = b0; b < b1; ++b) {
    const double im = 1.0 / c.mass[b];
    const Vec3 f = c.force[b], t = c.torque[b];
    if (close_previous) {
      c.velocity[b] += f * (h * im);
      c.angular_momentum[b] += t * h;
    }
    c.velocity[b] += f * (h * im);
    c.angular_momentum[b] += t * h;
    c.position[b] += c.velocity[b] * dt_;
  }
  rotate_freely(b1 - b0, c.orientation.data() + b0, c.angular_momentum.data() + b0,
                c.moments.data() + b0, dt_);
  double moved2 = max_moved2; // a local: the reference would be stored at every member
  for (std::size_t b = b0; b < b1; ++b) {
    // The force is used; it restarts from gravity for this step's evaluation.
    c.force[b] = settings.gravity * c.mass[b];
    c.torque[b] = {};
    c.place_members(b, p);
    for (std::uint32_t k = c.member_begin[b]; k < c.member_begin[b + 1]; ++k) {
      const std::uint32_t i = c.member_slot[k];
      packed_position_[i] = {p.position[i].x, p.position[i].y, p.position[i].z, p.radius[i]};
      pack_motion(i);
      p.force[i] = {};
      p.torque[i] = {};
      const double v2 = meshes::norm2(p.velocity[i]);
      if (!(v2 <= vmax2) && (error_particle_[thread] < 0 || long(i) < error_particle_[thread])) {
        error_particle_[thread] = long(i);
        error_kind_[thread] = std::isfinite(v2) ? too_fast : not_finite;
      }
      moved2 = std::max(moved2, meshes::norm2(p.position[i] - reference_position_[i]));
    }
  }
  max_moved2 = moved2;
}

void System::close_clumps(int thread) {
  auto& c = clumps_;
  const double h = 0.5 * dt_;
  const auto [b0, b1] = body_range(thread);
  for (std::size_t b = b0; b < b1; ++b) {
    c.velocity[b] += c.force[b] * (h * (1.0 / c.mass[b]));
    c.angular_momentum[b] += c.torque[b] * h;
  }
}

void System::gather_clump_forces() {
  if (clumps_.empty())
    return;
  const double t_begin = omp_get_wtime();
#pragma omp parallel num_threads(n_threads_)
  {
    const auto [b0, b1] = body_range(omp_get_thread_num());
    for (std::size_t b = b0; b < b1; ++b)
      clumps_.gather_forces(b, particles);
  }
  phase_times_.integration += omp_get_wtime() - t_begin;
}

} // namespace wear::dem

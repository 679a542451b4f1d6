// Contact detection and contact forces of the DEM System.
//
// Rebuild (when a particle moved more than half the skin): wrap particles back into the
// periodic sector, create ghost images of particles near the theta = angle cut (rotated by
// -angle, so they sit next to the theta = 0 cut), build the pair list, carry the tangential
// histories over, index each particle's pairs, and list candidate wall faces.
//
// Histories across the cut: a pair's history is stored relative to the frame in which the
// lower-index particle sits at its real position ("canonical frame"). A pair computed with
// a ghost of the lower-index particle lives in a frame rotated by -angle, so its history is
// rotated by +angle into the canonical frame and back; a wrap of the lower-index particle
// rotates the canonical frame with it. Wall histories are kept in fixed slots per particle
// and matched by wall and contact normal (within about 25 degrees), so sliding across
// triangle boundaries of a smooth or flat wall keeps the history.
//
// Pair forces go to per-pair arrays and are gathered per particle through an incidence
// index, so there are no write races and the sums do not depend on the thread count.
// Wear integrals are accumulated per thread and summed in thread order.
#include "dem/contact_law.h"
#include "dem/system.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace wear::dem {

namespace {
inline Vec3 rotate_z(const Vec3& v, double c, double s) {
  return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}
} // namespace

void System::rebuild() {
  auto& p = particles;
  const std::size_t n = p.n_real;
  const bool periodic = settings.periodic.enabled;
  const double c = cos_t_, s = sin_t_;

  // 1. Old histories into the canonical frame, keyed by (lower, higher) owner index.
  struct Entry {
    std::uint64_t key;
    Vec3 h;
  };
  std::vector<Entry> old;
  old.reserve(neighbors_.n_pairs() / 2 + 1);
  for (std::size_t k = 0; k < neighbors_.n_pairs(); ++k) {
    if (meshes::norm2(pair_history_[k]) == 0)
      continue;
    const std::uint32_t i = neighbors_.pair_i[k], j = neighbors_.pair_j[k];
    const bool ghost = j >= n;
    const std::uint32_t b = ghost ? ghost_owner_[j - n] : j;
    Vec3 h = pair_history_[k];
    if (ghost && b < i)
      h = rotate_z(h, c, s);
    old.push_back({(std::uint64_t(std::min(i, b)) << 32) | std::max(i, b), h});
  }

  // 2. Wrap particles into [0, angle); rotate their state and what is tied to their frame.
  if (periodic) {
    std::vector<signed char> wrap(n, 0);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& x = p.position[i];
      const double th = std::atan2(x.y, x.x);
      const double theta = th < 0 && th < -0.5 * (2 * 3.141592653589793 - settings.periodic.angle)
                               ? th + 2 * 3.141592653589793
                               : th;
      signed char w = 0;
      if (theta < 0)
        w = +1;
      else if (theta >= settings.periodic.angle)
        w = -1;
      if (w != 0) {
        const double cs = c, sn = w > 0 ? s : -s;
        p.position[i] = rotate_z(p.position[i], cs, sn);
        p.velocity[i] = rotate_z(p.velocity[i], cs, sn);
        p.angular_velocity[i] = rotate_z(p.angular_velocity[i], cs, sn);
        for (int k = 0; k < wall_slots; ++k) {
          slot_normal_[wall_slots * i + k] = rotate_z(slot_normal_[wall_slots * i + k], cs, sn);
          slot_delta_[wall_slots * i + k] = rotate_z(slot_delta_[wall_slots * i + k], cs, sn);
        }
      }
      wrap[i] = w;
    }
    for (auto& e : old) {
      const auto a = std::uint32_t(e.key >> 32);
      if (wrap[a] != 0)
        e.h = rotate_z(e.h, c, wrap[a] > 0 ? s : -s);
    }
  }
  std::sort(old.begin(), old.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });

  // 3. Ghosts: images of particles within reach of the theta = angle plane.
  ghost_owner_.clear();
  if (periodic) {
    const double reach = 2 * r_max_ + skin_;
    for (std::uint32_t i = 0; i < n; ++i) {
      const Vec3& x = p.position[i];
      const double dist = s * x.x - c * x.y;  // distance to the cut plane theta = angle
      const double along = c * x.x + s * x.y; // position along the cut plane direction
      if (dist < reach && along > -reach)
        ghost_owner_.push_back(i);
    }
  }
  p.resize_ghosts(ghost_owner_.size());
  for (std::size_t g = 0; g < ghost_owner_.size(); ++g) {
    const auto o = ghost_owner_[g];
    p.radius[n + g] = p.radius[o];
    p.mass[n + g] = p.mass[o];
    p.inertia[n + g] = p.inertia[o];
    p.material[n + g] = p.material[o];
    p.id[n + g] = p.id[o];
  }
  refresh_ghosts();
  check_particles_or_throw("at a neighbour-list rebuild");

  // 4. Pairs and their histories.
  neighbors_.build(p, skin_);
  const std::size_t np = neighbors_.n_pairs();
  pair_history_.assign(np, {});
  pair_force_.assign(np, {});
  pair_torque_i_.assign(np, {});
  pair_torque_j_.assign(np, {});
  if (!old.empty()) {
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < np; ++k) {
      const std::uint32_t i = neighbors_.pair_i[k], j = neighbors_.pair_j[k];
      const bool ghost = j >= n;
      const std::uint32_t b = ghost ? ghost_owner_[j - n] : j;
      const std::uint64_t key = (std::uint64_t(std::min(i, b)) << 32) | std::max(i, b);
      const auto it = std::lower_bound(old.begin(), old.end(), key,
                                       [](const Entry& e, std::uint64_t v) { return e.key < v; });
      if (it != old.end() && it->key == key)
        pair_history_[k] = ghost && b < i ? rotate_z(it->h, c, -s) : it->h;
    }
  }
  // 5. Incidence: entry 2 k for i of pair k, 2 k + 1 for the owner of j; stable order.
  incidence_offset_.assign(n + 1, 0);
  for (std::size_t k = 0; k < np; ++k) {
    ++incidence_offset_[neighbors_.pair_i[k] + 1];
    const auto j = neighbors_.pair_j[k];
    ++incidence_offset_[(j < n ? j : ghost_owner_[j - n]) + 1];
  }
  for (std::size_t i = 0; i < n; ++i)
    incidence_offset_[i + 1] += incidence_offset_[i];
  incidence_.resize(incidence_offset_[n]);
  {
    std::vector<std::uint32_t> fill(incidence_offset_.begin(), incidence_offset_.end() - 1);
    for (std::size_t k = 0; k < np; ++k) {
      incidence_[fill[neighbors_.pair_i[k]]++] = std::uint32_t(2 * k);
      const auto j = neighbors_.pair_j[k];
      incidence_[fill[j < n ? j : ghost_owner_[j - n]]++] = std::uint32_t(2 * k + 1);
    }
  }

  // 6. Wall candidates: faces within radius + skin of each particle centre.
  wall_candidate_offset_.assign(n + 1, 0);
  std::vector<std::uint32_t> count(n, 0);
  const auto scan = [&](std::size_t i, auto&& emit) {
    const Vec3& x = p.position[i];
    const double reach = p.radius[i] + skin_;
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      auto [b, e] = walls_[w].candidates(x);
      for (; b != e; ++b)
        if (meshes::norm2(walls_[w].closest(*b, x).point - x) < reach * reach)
          emit(std::uint32_t(w << 24) | *b);
    }
  };
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t m = 0;
    scan(i, [&](std::uint32_t) { ++m; });
    count[i] = m;
  }
  for (std::size_t i = 0; i < n; ++i)
    wall_candidate_offset_[i + 1] = wall_candidate_offset_[i] + count[i];
  wall_candidate_.resize(wall_candidate_offset_[n]);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t at = wall_candidate_offset_[i];
    scan(i, [&](std::uint32_t v) { wall_candidate_[at++] = v; });
  }
  reference_position_.assign(p.position.begin(), p.position.begin() + n);
  ++n_rebuilds_;
}

void System::refresh_ghosts() {
  auto& p = particles;
  const std::size_t n = p.n_real;
  const double c = cos_t_, s = -sin_t_; // ghosts are rotated by -angle
  for (std::size_t g = 0; g < ghost_owner_.size(); ++g) {
    const auto o = ghost_owner_[g];
    p.position[n + g] = rotate_z(p.position[o], c, s);
    p.velocity[n + g] = rotate_z(p.velocity[o], c, s);
    p.angular_velocity[n + g] = rotate_z(p.angular_velocity[o], c, s);
  }
}

void System::pair_forces() {
  auto& p = particles;
  const std::size_t np = neighbors_.n_pairs();
  const std::uint32_t* pi = neighbors_.pair_i.data();
  const std::uint32_t* pj = neighbors_.pair_j.data();
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < np; ++k) {
    const std::uint32_t i = pi[k], j = pj[k];
    const Vec3 d = p.position[i] - p.position[j];
    const double dist2 = meshes::norm2(d), rs = p.radius[i] + p.radius[j];
    if (dist2 >= rs * rs) {
      pair_history_[k] = {};
      pair_force_[k] = {};
      pair_torque_i_[k] = {};
      pair_torque_j_[k] = {};
      continue;
    }
    const double dist = std::sqrt(dist2);
    ContactGeometry g;
    g.normal = d / dist;
    g.overlap = rs - dist;
    g.r_eff = p.radius[i] * p.radius[j] / rs;
    g.m_eff = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
    g.arm_i = p.radius[i] - 0.5 * g.overlap;
    g.arm_j = p.radius[j] - 0.5 * g.overlap;
    g.lever_i = p.radius[i];
    g.lever_j = p.radius[j];
    g.v_contact = p.velocity[i] - p.velocity[j] +
                  meshes::cross(p.angular_velocity[i], g.normal * -g.lever_i) -
                  meshes::cross(p.angular_velocity[j], g.normal * g.lever_j);
    g.w_relative = p.angular_velocity[i] - p.angular_velocity[j];
    const auto r =
        hertz_mindlin(contact_[p.material[i] * n_mat_ + p.material[j]], g, dt_, pair_history_[k]);
    pair_force_[k] = r.force;
    pair_torque_i_[k] = r.torque_i;
    pair_torque_j_[k] = r.torque_j;
  }
}

void System::wall_forces() {
  if (walls_.empty())
    return;
  auto& p = particles;
  const std::size_t n = p.n_real;
  const double dt = dt_;
#pragma omp parallel
  {
    const int thread = omp_get_thread_num();
    auto& acc = wear_acc_[thread];
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const auto b = wall_candidate_offset_[i], e = wall_candidate_offset_[i + 1];
      if (b == e)
        continue;
      const Vec3 x = p.position[i];
      const double r = p.radius[i];
      std::int16_t new_wall[wall_slots];
      Vec3 new_normal[wall_slots], new_delta[wall_slots];
      bool taken[wall_slots] = {};
      int n_new = 0;
      Vec3 f_sum{}, t_sum{};
      for (auto k = b; k < e; ++k) {
        const std::uint32_t w = wall_candidate_[k] >> 24, f = wall_candidate_[k] & 0xFFFFFFu;
        const MeshWall& wall = walls_[w];
        const ClosestFeature cf = wall.closest(f, x);
        const Vec3 d = x - cf.point;
        const double dist2 = meshes::norm2(d);
        if (dist2 >= r * r || dist2 == 0 || !wall.owns_contact(f, cf, x))
          continue;
        if (n_new == wall_slots) {
          if (error_particle_[thread] < 0 || long(i) < error_particle_[thread]) {
            error_particle_[thread] = long(i);
            error_kind_[thread] = 4;
          }
          break;
        }
        const double dist = std::sqrt(dist2);
        ContactGeometry g;
        g.normal = d / dist;
        g.overlap = r - dist;
        g.r_eff = r;
        g.m_eff = p.mass[i];
        g.arm_i = dist;
        g.arm_j = 0;
        g.lever_i = r;
        g.v_contact = p.velocity[i] + meshes::cross(p.angular_velocity[i], g.normal * -r) -
                      wall.velocity_at(cf.point);
        g.w_relative = p.angular_velocity[i] - wall.angular_velocity_vector();
        // Carry the history of the old slot of this wall with the closest normal.
        Vec3 delta{};
        int best = -1;
        double best_dot = 0.9;
        for (int s = 0; s < wall_slots; ++s) {
          const std::size_t q = wall_slots * i + s;
          if (slot_wall_[q] == std::int16_t(w) && !taken[s]) {
            const double cd = meshes::dot(slot_normal_[q], g.normal);
            if (cd > best_dot) {
              best_dot = cd;
              best = s;
            }
          }
        }
        if (best >= 0) {
          taken[best] = true;
          delta = slot_delta_[wall_slots * i + best];
        }
        const auto res =
            hertz_mindlin(contact_[p.material[i] * n_mat_ + wall.material()], g, dt, delta);
        f_sum += res.force;
        t_sum += res.torque_i;
        new_wall[n_new] = std::int16_t(w);
        new_normal[n_new] = g.normal;
        new_delta[n_new] = delta;
        ++n_new;
        if (wall.wearing()) {
          std::uint32_t faces[32];
          const int n_faces = wall.faces_sharing(f, cf, faces, 32);
          const double share = 1.0 / n_faces;
          const Vec3 impulse = res.force * (-dt);
          const double fn_dt = res.normal_force * dt;
          const double archard = fn_dt * meshes::norm(res.v_tangential);
          const double work = std::abs(meshes::dot(res.tangential_force, res.v_tangential)) * dt;
          auto& a = acc[w];
          for (int q = 0; q < n_faces; ++q) {
            double* v = &a[8 * faces[q]];
            v[0] += impulse.x * share;
            v[1] += impulse.y * share;
            v[2] += impulse.z * share;
            v[3] += fn_dt * share;
            v[4] += archard * share;
            v[5] += work * share;
            v[6] += share;
          }
          double* tot = &a[8 * wall.n_faces()];
          tot[0] += impulse.x;
          tot[1] += impulse.y;
          tot[2] += impulse.z;
          tot[3] += fn_dt;
          tot[4] += archard;
          tot[5] += work;
        }
      }
      for (int s = 0; s < wall_slots; ++s) {
        const std::size_t q = wall_slots * i + s;
        slot_wall_[q] = s < n_new ? new_wall[s] : std::int16_t(-1);
        if (s < n_new) {
          slot_normal_[q] = new_normal[s];
          slot_delta_[q] = new_delta[s];
        }
      }
      p.force[i] += f_sum;
      p.torque[i] += t_sum;
    }
  }
}

} // namespace wear::dem

// Contact detection and contact forces of the DEM System.
//
// Rebuild (when a particle moved more than half the skin): wrap particles back into the
// periodic sector, create ghost images of particles near the theta = angle cut (rotated by
// -angle, so they sit next to the theta = 0 cut), build the pair list, carry the tangential
// histories over, index each particle's pairs, and list candidate wall faces.
//
// Histories across the cut: a pair's history is stored relative to the frame in which the
// particle with the lower stable id sits at its real position ("canonical frame"). A pair
// computed with a ghost of that particle lives in a frame rotated by -angle, so its history
// is rotated by +angle into the canonical frame and back; a wrap of that particle rotates the
// canonical frame with it. Keys are stable ids, so the periodic spatial reordering of the
// particle arrays (for cache locality) keeps every history. Wall histories are kept in fixed slots
// per particle and matched by wall and contact normal (within about 25 degrees), so sliding across
// triangle boundaries of a smooth or flat wall keeps the history. Contacts of one wall whose
// normals lie within 25 degrees are merged into the deepest: on a finely tessellated concave
// surface (a worn fillet) each triangle's interior is its own distance minimum, and counting
// them all would stiffen the contact several times and overflow the slots; distinct contacts
// (a particle in a corner between an element flank and the base) differ by more.
//
// Pair forces are accumulated per thread (thread 0 into the particles' own arrays) and
// summed in thread order, so a run is bitwise reproducible for a given thread count.
// Wear integrals are accumulated per thread and summed in thread order.
#include "dem/contact_law.h"
#include "dem/pair_kernel.h"
#include "dem/system.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace wear::dem {

namespace {
inline Vec3 rotate_z(const Vec3& v, double c, double s) {
  return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

/// A particle-wall contact found on a candidate face, before merging.
struct Candidate {
  ClosestFeature feature;
  Vec3 normal; ///< unit, wall to particle centre
  double dist; ///< [m] centre to closest point
  std::uint32_t wall, face;
};
constexpr int max_wall_candidates = 32;
/// Contacts of one wall whose normals differ by less than 25 degrees are one contact.
const double cos_merge_angle = std::cos(25.0 * 3.14159265358979323846 / 180.0);
} // namespace

void System::rebuild() {
  auto& p = particles;
  const std::size_t n = p.n_real;
  const bool periodic = settings.periodic.enabled;
  const double c = cos_t_, s = sin_t_;

  // 1. Old histories into the canonical frame (that of the particle with the lower stable
  //    id), keyed by the two ids, so they survive wrapping and reordering.
  struct Entry {
    std::uint64_t key;
    std::uint32_t lower; // current index of the lower-id particle
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
    const auto id_i = std::uint64_t(p.id[i]), id_b = std::uint64_t(p.id[b]);
    Vec3 h = pair_history_[k];
    if (ghost && id_b < id_i)
      h = rotate_z(h, c, s);
    old.push_back({(std::min(id_i, id_b) << 32) | std::max(id_i, id_b), id_b < id_i ? b : i, h});
  }

  // Where each particle's wall-contact slots are now (by stable id).
  slot_q_of_id_.assign(n, -1);
  for (std::size_t q = 0; q < wall_particles_.size(); ++q)
    slot_q_of_id_[p.id[wall_particles_[q]]] = std::int32_t(q);

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
        // Forces too: after import_state() they are used for the next half-kick as stored.
        p.force[i] = rotate_z(p.force[i], cs, sn);
        p.torque[i] = rotate_z(p.torque[i], cs, sn);
        const std::int32_t q = slot_q_of_id_[p.id[i]];
        for (int k = 0; q >= 0 && k < wall_slots; ++k) {
          WallSlot& sl = slots_[wall_slots * q + k];
          sl.normal = rotate_z(sl.normal, cs, sn);
          sl.delta = rotate_z(sl.delta, cs, sn);
        }
      }
      wrap[i] = w;
    }
    for (auto& e : old)
      if (wrap[e.lower] != 0)
        e.h = rotate_z(e.h, c, wrap[e.lower] > 0 ? s : -s);
  }
  // Bucket the entries by the lower id (counting sort, O(n)); a bucket holds a few entries.
  std::vector<std::uint32_t> bucket(n + 1, 0);
  for (const auto& e : old)
    ++bucket[(e.key >> 32) + 1];
  for (std::size_t i = 0; i < n; ++i)
    bucket[i + 1] += bucket[i];
  std::vector<Entry> by_id(old.size());
  {
    std::vector<std::uint32_t> fill(bucket.begin(), bucket.end() - 1);
    for (const auto& e : old)
      by_id[fill[e.key >> 32]++] = e;
  }

  // 2b. Every few rebuilds, reorder particles along the cell grid so that neighbours are
  //     neighbours in memory (histories are keyed by id, so nothing is lost).
  if (n >= 1000 && n_rebuilds_ % 10 == 0)
    sort_spatially();

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
  pair_const_.resize(np);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < np; ++k) {
    const std::uint32_t i = neighbors_.pair_i[k], j = neighbors_.pair_j[k];
    const double rs = p.radius[i] + p.radius[j];
    pair_const_[k] = {rs, p.radius[i] * p.radius[j] / rs,
                      p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]),
                      p.material[i] * n_mat_ + p.material[j]};
  }
  if (!old.empty()) {
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < np; ++k) {
      const std::uint32_t i = neighbors_.pair_i[k], j = neighbors_.pair_j[k];
      const bool ghost = j >= n;
      const std::uint32_t b = ghost ? ghost_owner_[j - n] : j;
      const auto id_i = std::uint64_t(p.id[i]), id_b = std::uint64_t(p.id[b]);
      const std::uint64_t key = (std::min(id_i, id_b) << 32) | std::max(id_i, id_b);
      const std::size_t lower = std::min(id_i, id_b);
      for (auto q = bucket[lower]; q < bucket[lower + 1]; ++q)
        if (by_id[q].key == key) {
          pair_history_[k] = ghost && id_b < id_i ? rotate_z(by_id[q].h, c, -s) : by_id[q].h;
          break;
        }
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
  // One pass: each thread scans a contiguous range into its own buffer; concatenated in
  // thread order, the buffers give the serial order.
  std::vector<std::vector<std::uint32_t>> found(n_threads_);
#pragma omp parallel num_threads(n_threads_)
  {
    auto& mine = found[omp_get_thread_num()];
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t before = mine.size();
      scan(i, [&](std::uint32_t v) { mine.push_back(v); });
      count[i] = std::uint32_t(mine.size() - before);
    }
  }
  wall_particles_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    wall_candidate_offset_[i + 1] = wall_candidate_offset_[i] + count[i];
    if (count[i] > 0)
      wall_particles_.push_back(std::uint32_t(i));
  }
  {
    std::vector<WallSlot> slots(wall_slots * wall_particles_.size());
    for (std::size_t q = 0; q < wall_particles_.size(); ++q) {
      const std::int32_t old_q = slot_q_of_id_[p.id[wall_particles_[q]]];
      if (old_q >= 0)
        std::copy_n(slots_.begin() + wall_slots * old_q, wall_slots,
                    slots.begin() + wall_slots * q);
    }
    slots_.swap(slots);
  }
  wall_candidate_.clear();
  for (const auto& f : found)
    wall_candidate_.insert(wall_candidate_.end(), f.begin(), f.end());
  split_wall_particles();
  count_block_contacts();
  reference_position_.assign(p.position.begin(), p.position.begin() + n);
  ++n_rebuilds_;
}

void System::sort_spatially() {
  auto& p = particles;
  const std::size_t n = p.n_real;
  Vec3 lo = p.position[0];
  for (std::size_t i = 1; i < n; ++i)
    for (int d = 0; d < 3; ++d)
      lo[d] = std::min(lo[d], p.position[i][d]);
  const double cell = 2 * r_max_ + skin_;
  std::vector<std::uint64_t> key(n);
  std::vector<std::uint32_t> perm(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 q = (p.position[i] - lo) / cell;
    key[i] = (std::uint64_t(q.z) << 42) | (std::uint64_t(q.y) << 21) | std::uint64_t(q.x);
    perm[i] = std::uint32_t(i);
  }
  std::stable_sort(perm.begin(), perm.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  const auto apply = [&](auto& v, std::size_t per) {
    auto copy = v;
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t q = 0; q < per; ++q)
        v[per * k + q] = copy[per * perm[k] + q];
  };
  apply(p.position, 1);
  apply(p.velocity, 1);
  apply(p.angular_velocity, 1);
  apply(p.force, 1);
  apply(p.torque, 1);
  apply(p.radius, 1);
  apply(p.mass, 1);
  apply(p.inertia, 1);
  apply(p.material, 1);
  apply(p.id, 1);
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

void System::count_block_contacts() {
  const auto& p = particles;
  const std::size_t np = neighbors_.n_pairs();
  const std::size_t n_blocks = (np + pair_block_size - 1) / pair_block_size;
  block_contacts_.assign(n_blocks, 0);
#pragma omp parallel for schedule(static) num_threads(n_threads_)
  for (std::size_t b = 0; b < n_blocks; ++b) {
    std::uint32_t m = 0;
    for (std::size_t k = b * pair_block_size; k < std::min(np, (b + 1) * pair_block_size); ++k) {
      const double rs = pair_const_[k].r_sum;
      m += meshes::norm2(p.position[neighbors_.pair_i[k]] - p.position[neighbors_.pair_j[k]]) <
           rs * rs;
    }
    block_contacts_[b] = m;
  }
}

void System::split_wall_particles() {
  // A near-wall particle costs its closest-feature tests, one per candidate face, plus a
  // little of its own.
  wall_split_.assign(n_threads_ + 1, wall_particles_.size());
  wall_split_[0] = 0;
  const double total = double(wall_candidate_.size() + 2 * wall_particles_.size());
  double sum = 0;
  int t = 1;
  for (std::size_t q = 0; q < wall_particles_.size() && t < n_threads_; ++q) {
    const std::size_t i = wall_particles_[q];
    sum += double(wall_candidate_offset_[i + 1] - wall_candidate_offset_[i] + 2);
    while (t < n_threads_ && sum >= total * t / n_threads_)
      wall_split_[t++] = q + 1;
  }
}

void System::split_pair_blocks() {
  // A listed pair costs its distance test; a contact costs about four times that (the law,
  // its gathers and the scatter), as measured on a settled bed.
  const std::size_t np = neighbors_.n_pairs(), n_blocks = block_contacts_.size();
  const auto cost = [&](std::size_t b) {
    return double(std::min<std::size_t>(pair_block_size, np - b * pair_block_size)) +
           4.0 * block_contacts_[b];
  };
  double total = 0;
  for (std::size_t b = 0; b < n_blocks; ++b)
    total += cost(b);
  block_split_.assign(n_threads_ + 1, n_blocks);
  block_split_[0] = 0;
  double sum = 0;
  int t = 1;
  for (std::size_t b = 0; b < n_blocks && t < n_threads_; ++b) {
    sum += cost(b);
    while (t < n_threads_ && sum >= total * t / n_threads_)
      block_split_[t++] = b + 1;
  }
}

void System::pair_forces() {
  auto& p = particles;
  const std::size_t n = p.n_real, np = neighbors_.n_pairs();
  const std::uint32_t* pi = neighbors_.pair_i.data();
  const std::uint32_t* pj = neighbors_.pair_j.data();
  const Vec3 gravity = settings.gravity;
  const PairKernelData kernel{p.position.data(),
                              p.velocity.data(),
                              p.angular_velocity.data(),
                              p.radius.data(),
                              pi,
                              pj,
                              pair_const_.data(),
                              contact_.data(),
                              pair_history_.data(),
                              ghost_owner_.data(),
                              n,
                              cos_t_,
                              sin_t_,
                              dt_};
  std::size_t n_contacts = 0;
  split_pair_blocks();
#pragma omp parallel num_threads(n_threads_) reduction(+ : n_contacts)
  {
    const int thread = omp_get_thread_num();
    Vec3* F = thread == 0 ? p.force.data() : force_buffer_[thread].data();
    Vec3* T = thread == 0 ? p.torque.data() : torque_buffer_[thread].data();
    if (thread == 0)
      for (std::size_t i = 0; i < n; ++i) {
        F[i] = gravity * p.mass[i];
        T[i] = {};
      }
    else
      for (std::size_t i = 0; i < n; ++i)
        F[i] = T[i] = {};
    PairBlock& bl = pair_block_[thread];
    for (std::size_t b = block_split_[thread]; b < block_split_[thread + 1]; ++b) {
      const std::size_t k0 = b * pair_block_size;
      const int m = pair_block_forces(
          kernel, k0, int(std::min<std::size_t>(pair_block_size, np - k0)), bl, F, T);
      block_contacts_[b] = std::uint32_t(m);
      n_contacts += m;
    }
  }
  n_pair_contacts_ = n_contacts;
  if (n_threads_ > 1) {
#pragma omp parallel for schedule(static) num_threads(n_threads_)
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 f = p.force[i], t = p.torque[i];
      for (int th = 1; th < n_threads_; ++th) {
        f += force_buffer_[th][i];
        t += torque_buffer_[th][i];
      }
      p.force[i] = f;
      p.torque[i] = t;
    }
  }
}

void System::wall_forces() {
  if (walls_.empty())
    return;
  if (wall_split_.size() != std::size_t(n_threads_) + 1)
    split_wall_particles(); // the thread count changed since the last rebuild
  auto& p = particles;
  const double dt = dt_;
#pragma omp parallel num_threads(n_threads_)
  {
    const int thread = omp_get_thread_num();
    auto& acc = wear_acc_[thread];
    // Only particles near a wall, in contiguous ranges of equal cost (split_wall_particles).
    // Scratch of one particle, declared once per thread: default-initialising it per particle
    // cost more than the contacts themselves.
    std::int32_t new_wall[wall_slots];
    Vec3 new_normal[wall_slots], new_delta[wall_slots];
    Candidate found[max_wall_candidates];
    for (std::size_t q = wall_split_[thread]; q < wall_split_[thread + 1]; ++q) {
      const std::size_t i = wall_particles_[q];
      const auto b = wall_candidate_offset_[i], e = wall_candidate_offset_[i + 1];
      const Vec3 x = p.position[i];
      const double r = p.radius[i];
      bool taken[wall_slots] = {};
      int n_new = 0;
      Vec3 f_sum{}, t_sum{};
      // Gather the owned contacts, then merge those of one wall whose normals lie within
      // merge_angle: they are one contact with a finely tessellated concave surface (a worn
      // fillet), where every triangle's interior is a local minimum of the distance.
      int n_found = 0;
      bool overflow = false;
      for (auto k = b; k < e && !overflow; ++k) {
        const std::uint32_t w = wall_candidate_[k] >> 24, f = wall_candidate_[k] & 0xFFFFFFu;
        const MeshWall& wall = walls_[w];
        if (wall.plane_distance(f, x) >= r)
          continue;
        const ClosestFeature cf = wall.closest(f, x);
        const Vec3 d = x - cf.point;
        const double dist2 = meshes::norm2(d);
        if (dist2 >= r * r || dist2 == 0 || !wall.owns_contact(f, cf, x))
          continue;
        if (n_found == max_wall_candidates) {
          overflow = true;
          break;
        }
        const double dist = std::sqrt(dist2);
        found[n_found++] = {cf, d / dist, dist, w, f};
      }
      for (int c = 0; c < n_found && !overflow; ++c) {
        const Candidate& cand = found[c];
        bool merged = false;
        for (int o = 0; o < n_found && !merged; ++o)
          merged = o != c && found[o].wall == cand.wall &&
                   meshes::dot(found[o].normal, cand.normal) > cos_merge_angle &&
                   (found[o].dist < cand.dist || (found[o].dist == cand.dist && o < c));
        if (merged)
          continue;
        if (n_new == wall_slots) {
          overflow = true;
          break;
        }
        const std::uint32_t w = cand.wall, f = cand.face;
        const MeshWall& wall = walls_[w];
        const ClosestFeature& cf = cand.feature;
        const double dist = cand.dist;
        ContactGeometry g;
        g.normal = cand.normal;
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
        const WallSlot* old = &slots_[wall_slots * q];
        for (int s = 0; s < wall_slots && old[s].wall >= 0; ++s) {
          if (old[s].wall == std::int32_t(w) && !taken[s]) {
            const double cd = meshes::dot(old[s].normal, g.normal);
            if (cd > best_dot) {
              best_dot = cd;
              best = s;
            }
          }
        }
        if (best >= 0) {
          taken[best] = true;
          delta = old[best].delta;
        }
        const auto res =
            hertz_mindlin(contact_[p.material[i] * n_mat_ + wall.material()], g, dt, delta);
        f_sum += res.force;
        t_sum += res.torque_i;
        new_wall[n_new] = std::int32_t(w);
        new_normal[n_new] = g.normal;
        new_delta[n_new] = delta;
        ++n_new;
        if (wall.wearing()) {
          std::uint32_t faces[32];
          double shares[32];
          const int n_faces = wall.faces_sharing(f, cf, faces, shares, 32);
          const Vec3 impulse = res.force * (-dt);
          const double fn_dt = res.normal_force * dt;
          const double archard = fn_dt * meshes::norm(res.v_tangential);
          const double work = std::abs(meshes::dot(res.tangential_force, res.v_tangential)) * dt;
          auto& a = acc[w];
          for (int q = 0; q < n_faces; ++q) {
            double* v = &a[8 * faces[q]];
            const double share = shares[q];
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
      if (overflow && (error_particle_[thread] < 0 || long(i) < error_particle_[thread])) {
        error_particle_[thread] = long(i);
        error_kind_[thread] = 4;
      }
      WallSlot* slot = &slots_[wall_slots * q];
      for (int s = 0; s < n_new; ++s)
        slot[s] = {new_normal[s], new_delta[s], new_wall[s]};
      if (n_new < wall_slots)
        slot[n_new].wall = -1;
      p.force[i] += f_sum;
      p.torque[i] += t_sum;
    }
  }
}

} // namespace wear::dem

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
// canonical frame with it. A history is the tangential displacement of the listed first
// particle relative to the second, so it is stored oriented from the lower id to the higher
// (negated when listed the other way) and re-oriented to the new list: the spatial reordering
// and a wrap across the cut change which of the two is listed first. Keys are stable ids, so
// the periodic spatial reordering of the particle arrays (for cache locality) keeps every
// history. Wall histories are kept in fixed slots
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
#include "meshes/surface_mesh.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace wear::dem {

namespace {
inline Vec3 rotate_z(const Vec3& v, double c, double s) {
  return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

/// A pair history between its listing (i, j) and the canonical frame and orientation (those
/// of the lower-id particle): with s = sin(angle) from the listing to canonical, with -s
/// back. Nothing changes when the lower id is listed first; listed second, the history is
/// negated, and rotated by the sector angle when that particle is present as a ghost.
inline Vec3 reorient_history(const Vec3& h, bool lower_second, bool ghost, double c, double s) {
  if (!lower_second)
    return h;
  return ghost ? rotate_z(-h, c, s) : -h;
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

void System::rebuild(bool in_step) {
  auto& p = particles;
  const std::size_t n = p.n_real;
  const bool periodic = settings.periodic.enabled;
  const double c = cos_t_, s = sin_t_;

  // 1. Old histories into the canonical frame and orientation (those of the particle with
  //    the lower stable id), keyed by the two ids, so they survive wrapping and reordering.
  struct Entry {
    std::uint64_t key;
    std::uint32_t lower; // current index of the lower-id particle
    Vec3 h;
  };
  std::vector<Entry> old;
  {
    // Each thread collects a contiguous range; the order of `old` does not matter (lookups
    // match the whole key).
    std::vector<std::vector<Entry>> part(n_threads_);
#pragma omp parallel num_threads(n_threads_)
    {
      auto& mine = part[omp_get_thread_num()];
#pragma omp for schedule(static)
      for (std::size_t k = 0; k < neighbors_.n_pairs(); ++k) {
        if (meshes::norm2(pair_history_[k]) == 0)
          continue;
        const std::uint32_t i = neighbors_.pair_i[k], j = neighbors_.pair_j[k];
        const bool ghost = j >= n;
        const std::uint32_t b = ghost ? ghost_owner_[j - n] : j;
        const auto id_i = std::uint64_t(p.id[i]), id_b = std::uint64_t(p.id[b]);
        const Vec3 h = reorient_history(pair_history_[k], id_b < id_i, ghost, c, s);
        mine.push_back(
            {(std::min(id_i, id_b) << 32) | std::max(id_i, id_b), id_b < id_i ? b : i, h});
      }
    }
    std::size_t total = 0;
    for (const auto& v : part)
      total += v.size();
    old.reserve(total);
    for (const auto& v : part)
      old.insert(old.end(), v.begin(), v.end());
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
        // Forces too, between steps: they are used for the next half-kick as stored (within a
        // step they hold gravity only, the pair loop's start, which the sector keeps along z).
        if (!in_step) {
          p.force[i] = rotate_z(p.force[i], cs, sn);
          p.torque[i] = rotate_z(p.torque[i], cs, sn);
        }
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
          pair_history_[k] = reorient_history(by_id[q].h, id_b < id_i, ghost, c, -s);
          break;
        }
    }
  }
  // 6. Wall candidates: faces within radius + skin/2 of each particle centre. Until the next
  //    rebuild no particle moves more than skin/2 from here (the rebuild trigger), and wall
  //    geometry changes only through set_wall_vertices, which rebuilds; so no other face can
  //    be touched. (A pair needs the whole skin: both partners move.) Widened by a relative
  //    1e-9 against round-off.
  wall_candidate_offset_.assign(n + 1, 0);
  std::vector<std::uint32_t> count(n, 0);
  const auto scan = [&](std::size_t i, auto&& emit) {
    const Vec3& x = p.position[i];
    const double reach = (p.radius[i] + 0.5 * skin_) * (1 + 1e-9);
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      auto [b, e] = walls_[w].candidates(x);
      for (; b != e; ++b)
        if (meshes::norm2(walls_[w].closest(*b, x).point - x) < reach * reach)
          emit(std::uint32_t(w << 24) | *b);
    }
  };
  // Near-wall particles cluster (the floor's are all at the start of the spatial order), so
  // the scan goes in chunks handed out dynamically; each chunk has its own buffer and they
  // are concatenated in chunk order, which is the serial order.
  constexpr std::size_t chunk = 512;
  const std::size_t n_chunks = (n + chunk - 1) / chunk;
  if (wall_chunk_found_.size() < n_chunks)
    wall_chunk_found_.resize(n_chunks);
#pragma omp parallel for schedule(dynamic) num_threads(n_threads_)
  for (std::size_t ch = 0; ch < n_chunks; ++ch) {
    auto& mine = wall_chunk_found_[ch];
    mine.clear();
    for (std::size_t i = ch * chunk; i < std::min(n, (ch + 1) * chunk); ++i) {
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
  for (std::size_t ch = 0; ch < n_chunks; ++ch)
    wall_candidate_.insert(wall_candidate_.end(), wall_chunk_found_[ch].begin(),
                           wall_chunk_found_[ch].end());
  count_particle_costs();
  split_ownership();
  reference_position_.assign(p.position.begin(), p.position.begin() + n);
  ++n_rebuilds_;
}

void System::sort_spatially() {
  auto& p = particles;
  const std::size_t n = p.n_real;
  const auto box = meshes::bounding_box(p.position.data(), n);
  const Vec3 lo = box.min, extent = box.extent();
  // Cells in lexicographic order with the longest axis slowest and the shortest fastest: a
  // cell's stencil then spans the fewest cells of the order (for a flat bed, plus or minus a
  // layer of columns instead of a whole horizontal layer), and the threads' contiguous ranges
  // meet across vertical planes instead of one horizontal plane through the whole bed.
  int axis[3] = {0, 1, 2};
  std::stable_sort(axis, axis + 3, [&](int a, int b) { return extent[a] > extent[b]; });
  const double cell = 2 * r_max_ + skin_;
  std::vector<std::uint64_t> key(n);
  std::vector<std::uint32_t> perm(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 q = (p.position[i] - lo) / cell;
    key[i] = (std::uint64_t(q[axis[0]]) << 42) | (std::uint64_t(q[axis[1]]) << 21) |
             std::uint64_t(q[axis[2]]);
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

void System::count_particle_costs() {
  // Estimated cost of each particle's share of the force evaluation, in units of one listed
  // pair's distance test, as measured on a settled bed: a contact costs 4 more (the law, its
  // gathers and the scatter), a wall candidate face 4 (closest feature), a near-wall particle
  // 8 of its own.
  const auto& p = particles;
  const std::size_t n = p.n_real, np = neighbors_.n_pairs();
  pair_touch_.resize(np);
#pragma omp parallel for schedule(static) num_threads(n_threads_)
  for (std::size_t k = 0; k < np; ++k) {
    const double rs = p.radius[neighbors_.pair_i[k]] + p.radius[neighbors_.pair_j[k]];
    pair_touch_[k] = meshes::norm2(p.position[neighbors_.pair_i[k]] -
                                   p.position[neighbors_.pair_j[k]]) < rs * rs;
  }
  particle_cost_.resize(n);
#pragma omp parallel for schedule(static) num_threads(n_threads_)
  for (std::size_t i = 0; i < n; ++i) {
    const auto n_candidates = wall_candidate_offset_[i + 1] - wall_candidate_offset_[i];
    particle_cost_[i] = 4.0 * n_candidates + (n_candidates > 0 ? 8.0 : 0.0);
  }
  for (std::size_t k = 0; k < np; ++k)
    particle_cost_[neighbors_.pair_i[k]] += 1.0 + 4.0 * pair_touch_[k];
}

void System::split_ownership() {
  // In the force evaluation each thread owns a contiguous range of particles of equal
  // estimated cost: the pairs listed under them and their wall contacts. With the pairs and
  // the walls split together, the threads meet once per evaluation instead of twice, and a
  // particle's wall contacts stay with the thread that owns its pairs. The split is a
  // function of the state at the last rebuild, so a run stays bitwise reproducible.
  const std::size_t n = particles.n_real;
  double total = 0;
  for (std::size_t i = 0; i < n; ++i)
    total += particle_cost_[i];
  owner_split_.assign(n_threads_ + 1, n);
  owner_split_[0] = 0;
  double sum = 0;
  int t = 1;
  for (std::size_t i = 0; i < n && t < n_threads_; ++i) {
    sum += particle_cost_[i];
    while (t < n_threads_ && sum >= total * t / n_threads_)
      owner_split_[t++] = i + 1;
  }
  // Pairs are listed by their first particle, near-wall particles in index order.
  pair_split_.resize(n_threads_ + 1);
  wall_split_.resize(n_threads_ + 1);
  for (int t = 0; t <= n_threads_; ++t) {
    const auto first = std::uint32_t(owner_split_[t]);
    pair_split_[t] =
        std::size_t(std::lower_bound(neighbors_.pair_i.begin(), neighbors_.pair_i.end(), first) -
                    neighbors_.pair_i.begin());
    wall_split_[t] =
        std::size_t(std::lower_bound(wall_particles_.begin(), wall_particles_.end(), first) -
                    wall_particles_.begin());
  }
}

std::size_t System::pair_forces(int thread, Vec3* F, Vec3* T) {
  auto& p = particles;
  const PairKernelData kernel{p.position.data(),
                              p.velocity.data(),
                              p.angular_velocity.data(),
                              p.radius.data(),
                              p.mass.data(),
                              p.material.data(),
                              neighbors_.pair_i.data(),
                              neighbors_.pair_j.data(),
                              contact_.data(),
                              n_mat_,
                              pair_history_.data(),
                              ghost_owner_.data(),
                              p.n_real,
                              cos_t_,
                              sin_t_,
                              dt_};
  std::size_t n_contacts = 0;
  PairBlock& bl = pair_block_[thread];
  for (std::size_t k0 = pair_split_[thread]; k0 < pair_split_[thread + 1]; k0 += pair_block_size) {
    const std::size_t m = std::min<std::size_t>(pair_block_size, pair_split_[thread + 1] - k0);
    n_contacts += std::size_t(pair_block_forces(kernel, k0, int(m), bl, F, T));
  }
  return n_contacts;
}

void System::wall_forces(int thread, Vec3* F, Vec3* T) {
  auto& p = particles;
  const double dt = dt_;
  auto& acc = wear_acc_[thread];
  // Scratch of one particle, declared once: default-initialising it per particle cost more
  // than the contacts themselves.
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
      if (wall.plane_distance(f, x) >= r || wall.beyond_bound(f, x, r))
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
    F[i] += f_sum;
    T[i] += t_sum;
  }
}

} // namespace wear::dem

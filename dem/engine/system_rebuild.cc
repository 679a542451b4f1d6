// Neighbour-list rebuild of the DEM System (when a particle moved more than half the skin).
//
// In order: take the pair histories out of the old list into a frame-free form; wrap the
// particles back into the periodic sector; every few rebuilds reorder them along the cell grid;
// create ghost images of the particles near the theta = angle cut (rotated by -angle, so they
// sit next to the theta = 0 cut); build the pair list and carry the histories over to it;
// list candidate wall faces per particle and carry the wall-contact slots over; split the
// force evaluation between the threads.
//
// A periodic slab (DemSettings::periodic_slab) is the same with a shift for the rotation:
// particles are wrapped by +-L along its axis, ghosts are the images shifted by -L of the
// particles within reach of the upper plane, and vectors (velocities, forces, histories) are
// not turned (the rotation is the identity, cos_t_ = 1, sin_t_ = 0).
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
// history. Wall-contact slots are per particle, found again by stable id.
#include "dem/engine/reused_buffer.h"
#include "dem/engine/system.h"
#include "meshes/constants.h"
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

/// The wrap that brings x back into the sector 0 <= theta < angle: +1 (rotate by +angle) when
/// it lies before theta = 0, -1 beyond theta = angle, 0 inside. The gap outside the sector is
/// split at its middle.
inline signed char sector_wrap(const Vec3& x, double angle) {
  const double th = std::atan2(x.y, x.x);
  const double theta = th < 0 && th < -0.5 * (2 * pi - angle) ? th + 2 * pi : th;
  if (theta < 0)
    return +1;
  if (theta >= angle)
    return -1;
  return 0;
}

/// The wrap that brings x back into the slab lo <= x_axis < hi: +1 (shift by +L) below it, -1
/// (by -L) at or above hi, 0 inside.
inline signed char slab_wrap(const Vec3& x, const PeriodicSlab& slab) {
  if (x[slab.axis] < slab.lo)
    return +1;
  if (x[slab.axis] >= slab.hi)
    return -1;
  return 0;
}

/// The wrap that brings x back into the periodic slab, or else the periodic sector.
inline signed char periodic_wrap(const Vec3& x, const PeriodicSlab& slab, double angle) {
  return slab.enabled ? slab_wrap(x, slab) : sector_wrap(x, angle);
}

/// Near-wall particles cluster (the floor's are all at the start of the spatial order), so
/// the wall-candidate scan goes in chunks of this many particles handed out dynamically.
constexpr std::size_t wall_scan_chunk = 512;
} // namespace

void System::rebuild(bool in_step, const ParticleChanges* changes) {
  // Pair histories and wall slots leave the old lists keyed by stable id: the wrap, the
  // reordering, inserted and removed particles and the new lists keep them.
  key_by_id(in_step);
  std::vector<CarriedHistory>& old = rebuild_scratch_.old_histories;
  std::vector<std::int32_t>& slots_of_id = rebuild_scratch_.slots_of_id;
  if (rank_link_)
    migrate_over_ranks(slots_of_id, old);
  if (changes) {
    apply_particle_changes(*changes);
    slots_of_id.resize(std::size_t(next_id_), -1); // the new ids own no slots
  }
  relist(old, slots_of_id);
}

void System::key_by_id(bool in_step) {
  RebuildScratch& scratch = rebuild_scratch_;
  canonical_pair_histories(scratch.old_histories);
  wall_slots_by_id(scratch.slots_of_id);
  if (periodic())
    wrap_into_sector(in_step, scratch.slots_of_id, scratch.old_histories);
}

void System::relist(const std::vector<CarriedHistory>& old,
                    const std::vector<std::int32_t>& slots_of_id) {
  RebuildScratch& scratch = rebuild_scratch_;
  const std::size_t n = particles.n_real;
  HistoryTable& old_by_id = scratch.old_by_id;
  bucket_by_lower_id(old, old_by_id);
  // Every few rebuilds, reorder particles along the cell grid so that neighbours are
  // neighbours in memory (histories are keyed by id, so nothing is lost).
  const bool sorted = n >= 1000 && n_rebuilds_ % 10 == 0;
  if (sorted && !clumps_.empty() && body_of_slot_.size() != n) // the first rebuild
    clumps_.index_members(particles, scratch.clump_slot_of_id, body_of_slot_);
  if (sorted)
    sort_spatially();
  make_ghosts();
  check_particles_or_throw("at a neighbour-list rebuild");
  neighbors_.build(particles, skin_);
  if (!clumps_.empty()) {
    // The members of one body never touch: their pairs leave the list.
    clumps_.index_members(particles, scratch.clump_slot_of_id, body_of_slot_);
    if (sorted) // the bodies follow their members' new order
      clumps_.order_by_members(body_of_slot_);
    neighbors_.drop_pairs_within(body_of_slot_);
  }
  carry_pair_histories(old_by_id);
  find_wall_candidates(scratch.n_candidates);
  index_wall_particles(scratch.n_candidates);
  carry_wall_slots(slots_of_id);
  count_particle_costs();
  split_ownership();
  pack_particles();
  reference_position_.assign(particles.position.begin(), particles.position.begin() + n);
  for (auto& w : walls_)
    w.mark_reference();
  wall_reference_time_ = wall_time_;
  ++n_rebuilds_;
}

void System::canonical_pair_histories(std::vector<CarriedHistory>& old) {
  const auto& p = particles;
  const std::size_t n = p.n_real, np = neighbors_.n_pairs();
  const double c = cos_t_, s = sin_t_;
  // Each thread counts the histories of its static range of the list, then writes them at its
  // offset: the result is in list order, for any thread count (lookups match the whole key).
  auto& offset = rebuild_scratch_.thread_offset;
  offset.assign(std::size_t(n_threads_) + 1, 0);
#pragma omp parallel num_threads(n_threads_)
  {
    const std::size_t t = std::size_t(omp_get_thread_num());
    std::size_t count = 0;
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < np; ++k)
      count += meshes::norm2(pair_history_[k]) != 0;
    offset[t + 1] = count;
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t u = 0; u < std::size_t(n_threads_); ++u)
        offset[u + 1] += offset[u];
      resize_reusing(old, offset.back());
    }
    std::size_t at = offset[t];
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < np; ++k) {
      if (meshes::norm2(pair_history_[k]) == 0)
        continue;
      const std::uint32_t i = neighbors_.pair_i[k], j = neighbors_.pair_j[k];
      const std::uint32_t b = j >= n ? ghost_owner_[j - n] : j;
      const auto id_i = std::uint64_t(p.id[i]), id_b = std::uint64_t(p.id[b]);
      // Only the periodic images are rotated (ghosts of another rank are not).
      const bool rotated = j >= n && j < n + n_image_ghosts_;
      const Vec3 h = reorient_history(pair_history_[k], id_b < id_i, rotated, c, s);
      old[at++] = {(std::min(id_i, id_b) << 32) | std::max(id_i, id_b), id_b < id_i ? b : i, h};
    }
  }
}

void System::wall_slots_by_id(std::vector<std::int32_t>& slots_of_id) const {
  assign_reusing(slots_of_id, std::size_t(next_id_), std::int32_t(-1)); // ids grow with inlets
  for (std::size_t q = 0; q < wall_particles_.size(); ++q)
    slots_of_id[particles.id[wall_particles_[q]]] = std::int32_t(q);
}

void System::wrap_into_sector(bool in_step, const std::vector<std::int32_t>& slots_of_id,
                              std::vector<CarriedHistory>& old) {
  auto& p = particles;
  const std::size_t n = p.n_real;
  const double c = cos_t_, s = sin_t_, angle = settings.periodic.angle;
  const PeriodicSlab& slab = settings.periodic_slab;
  std::vector<signed char>& wrap = rebuild_scratch_.wrap;
  wrap.resize(n);
  // A body wraps as one, by its centre: its members with it, wherever they lie.
  std::vector<signed char>& body_wrap = rebuild_scratch_.body_wrap;
  if (!clumps_.empty()) {
    if (body_of_slot_.size() != n) // the first rebuild
      clumps_.index_members(particles, rebuild_scratch_.clump_slot_of_id, body_of_slot_);
    wrap_bodies(in_step, body_wrap);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t body = clumps_.empty() ? -1 : body_of_slot_[i];
    const signed char w =
        body >= 0 ? body_wrap[std::size_t(body)] : periodic_wrap(p.position[i], slab, angle);
    if (w != 0) {
      const double cs = c, sn = w > 0 ? s : -s;
      p.position[i] = rotate_z(p.position[i], cs, sn) + (w > 0 ? shift_ : -shift_);
      p.velocity[i] = rotate_z(p.velocity[i], cs, sn);
      p.angular_velocity[i] = rotate_z(p.angular_velocity[i], cs, sn);
      // Forces too, between steps: they are used for the next half-kick as stored (within a
      // step they hold gravity only, the pair loop's start, which the sector keeps along z).
      if (!in_step) {
        p.force[i] = rotate_z(p.force[i], cs, sn);
        p.torque[i] = rotate_z(p.torque[i], cs, sn);
      }
      const std::int32_t q = slots_of_id[p.id[i]];
      for (int k = 0; q >= 0 && k < wall_slots; ++k) {
        WallSlot& sl = slots_[wall_slots * q + k];
        sl.normal = rotate_z(sl.normal, cs, sn);
        sl.delta = rotate_z(sl.delta, cs, sn);
      }
    }
    wrap[i] = w;
  }
  for (auto& e : old)
    if (e.lower < n && wrap[e.lower] != 0) // (over ranks a ghost's owner wraps it)
      e.h = rotate_z(e.h, c, wrap[e.lower] > 0 ? s : -s);
}

void System::wrap_bodies(bool in_step, std::vector<signed char>& body_wrap) {
  auto& c = clumps_;
  const double cs = cos_t_, angle = settings.periodic.angle;
  const PeriodicSlab& slab = settings.periodic_slab;
  body_wrap.resize(c.size());
  for (std::size_t b = 0; b < c.size(); ++b) {
    const signed char w = periodic_wrap(c.position[b], slab, angle);
    body_wrap[b] = w;
    if (w == 0)
      continue;
    const double sn = w > 0 ? sin_t_ : -sin_t_;
    c.position[b] = rotate_z(c.position[b], cs, sn) + (w > 0 ? shift_ : -shift_);
    c.velocity[b] = rotate_z(c.velocity[b], cs, sn);
    c.angular_momentum[b] = rotate_z(c.angular_momentum[b], cs, sn);
    if (!in_step) {
      c.force[b] = rotate_z(c.force[b], cs, sn);
      c.torque[b] = rotate_z(c.torque[b], cs, sn);
    }
    if (!slab.enabled) // turned about z with the sector: q <- R_z(+-angle) q
      c.orientation[b] =
          normalized(rotation_about({0, 0, 1}, w > 0 ? angle : -angle) * c.orientation[b]);
  }
}

void System::bucket_by_lower_id(const std::vector<CarriedHistory>& old, HistoryTable& table) {
  const std::size_t n = std::size_t(next_id_); // ids lie below it
  assign_reusing(table.bucket, n + 1, 0u);
  for (const auto& e : old)
    ++table.bucket[(e.key >> 32) + 1];
  for (std::size_t i = 0; i < n; ++i)
    table.bucket[i + 1] += table.bucket[i];
  resize_reusing(table.entry, old.size());
  std::vector<std::uint32_t>& fill = rebuild_scratch_.bucket_fill;
  resize_reusing(fill, n);
  std::copy(table.bucket.begin(), table.bucket.end() - 1, fill.begin());
  for (const auto& e : old)
    table.entry[fill[e.key >> 32]++] = e;
}

void System::make_ghosts() {
  auto& p = particles;
  const std::size_t n = p.n_real;
  const double c = cos_t_, s = sin_t_;
  ghost_owner_.clear();
  const PeriodicSlab& slab = settings.periodic_slab;
  if (slab.enabled && !rank_link_) { // over ranks the seam is a cut between ranks
    const double reach = ghost_reach();
    for (std::uint32_t i = 0; i < n; ++i)
      if (slab.hi - p.position[i][slab.axis] < reach) // near the upper plane
        ghost_owner_.push_back(i);
  } else if (settings.periodic.enabled && !rank_link_) {
    const double reach = ghost_reach();
    for (std::uint32_t i = 0; i < n; ++i) {
      const Vec3& x = p.position[i];
      const double dist = s * x.x - c * x.y;  // distance to the cut plane theta = angle
      const double along = c * x.x + s * x.y; // position along the cut plane direction
      if (dist < reach && along > -reach)
        ghost_owner_.push_back(i);
    }
  }
  n_periodic_ghosts_ = n_image_ghosts_ = ghost_owner_.size();
  if (rank_link_)
    exchange_rank_ghosts();
  fill_ghost_slots();
  if (rank_link_)
    place_rank_ghosts(rank_scratch_.from_below);
}

void System::fill_ghost_slots() {
  auto& p = particles;
  const std::size_t n = p.n_real;
  p.resize_ghosts(ghost_owner_.size());
  packed_position_.resize(p.position.size());
  packed_motion_.resize(p.position.size());
  for (std::size_t g = 0; g < n_periodic_ghosts_; ++g) {
    const auto o = ghost_owner_[g];
    p.radius[n + g] = p.radius[o];
    p.mass[n + g] = p.mass[o];
    p.inertia[n + g] = p.inertia[o];
    p.material[n + g] = p.material[o];
    p.id[n + g] = p.id[o];
  }
  refresh_ghosts();
}

void System::carry_pair_histories(const HistoryTable& old) {
  const auto& p = particles;
  const std::size_t n = p.n_real, np = neighbors_.n_pairs();
  const double c = cos_t_, s = sin_t_;
  assign_reusing(pair_history_, np, Vec3{});
  if (old.entry.empty())
    return;
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < np; ++k) {
    const std::uint32_t i = neighbors_.pair_i[k], j = neighbors_.pair_j[k];
    const std::uint32_t b = j >= n ? ghost_owner_[j - n] : j;
    const bool rotated = j >= n && j < n + n_image_ghosts_;
    const auto id_i = std::uint64_t(p.id[i]), id_b = std::uint64_t(p.id[b]);
    const std::uint64_t key = (std::min(id_i, id_b) << 32) | std::max(id_i, id_b);
    const std::size_t lower = std::min(id_i, id_b);
    for (auto q = old.bucket[lower]; q < old.bucket[lower + 1]; ++q)
      if (old.entry[q].key == key) {
        pair_history_[k] = reorient_history(old.entry[q].h, id_b < id_i, rotated, c, -s);
        break;
      }
  }
}

void System::find_wall_candidates(std::vector<std::uint32_t>& count) {
  // Faces within radius + skin/2 of each particle centre (of a revolution wall, its surface).
  // Until the next rebuild no particle moves more than skin/2 from here (the rebuild
  // trigger, which counts a moving wall's displacement too), and wall geometry changes only
  // through set_wall_vertices, which rebuilds; so no other face can be touched. A moving wall
  // is searched in its body frame. (A pair needs the whole skin: both partners move.) Widened by a
  // relative 1e-9 against round-off.
  const auto& p = particles;
  const std::size_t n = p.n_real;
  count.resize(n);
  const auto scan = [&](std::size_t i, auto&& emit) {
    const Vec3& x = p.position[i];
    const double reach = (p.radius[i] + 0.5 * skin_) * (1 + 1e-9);
    // A grid cell lists every face within reach of any of its points: on the 1 mm sample mesh
    // several hundred (a flat patch through a cell and its reach is about 20 x 20 mm at s = 3),
    // nearly all beyond reach of a given centre. The face bounds' tests
    // (lower bounds of the distance, as in the step) skip those first; widened by a further
    // 1e-9, far above their round-off, they skip only faces the closest-point test would
    // reject too, so the candidates are the same.
    const double cull = reach * (1 + 1e-9);
    for (std::size_t w = 0; w < wall_kind_.size(); ++w) {
      const std::size_t local = std::size_t(wall_local_[w]);
      if (wall_kind_[w] == WallKind::revolution) {
        if (meshes::norm2(revolution_walls_[local].closest(x) - x) < reach * reach)
          emit(std::uint32_t(w << 24)); // its one "face", 0: the exact closest point
        continue;
      }
      const MeshWall& wall = walls_[local];
      const Vec3 xb = wall.to_body(x);
      auto [b, e] = wall.candidates(xb);
      for (; b != e; ++b)
        if (!wall.bound(*b).rejects(xb, cull) &&
            meshes::norm2(wall.closest(*b, xb).point - xb) < reach * reach)
          emit(std::uint32_t(w << 24) | *b);
    }
  };
  // Each chunk has its own buffer and they are concatenated in chunk order, which is the
  // serial order.
  const std::size_t n_chunks = (n + wall_scan_chunk - 1) / wall_scan_chunk;
  auto& found = rebuild_scratch_.chunk_candidates;
  if (found.size() < n_chunks)
    found.resize(n_chunks);
#pragma omp parallel for schedule(dynamic) num_threads(n_threads_)
  for (std::size_t ch = 0; ch < n_chunks; ++ch) {
    auto& mine = found[ch];
    mine.clear();
    for (std::size_t i = ch * wall_scan_chunk; i < std::min(n, (ch + 1) * wall_scan_chunk); ++i) {
      const std::size_t before = mine.size();
      scan(i, [&](std::uint32_t v) { mine.push_back(v); });
      count[i] = std::uint32_t(mine.size() - before);
    }
  }
  wall_candidate_.clear();
  for (std::size_t ch = 0; ch < n_chunks; ++ch)
    wall_candidate_.insert(wall_candidate_.end(), found[ch].begin(), found[ch].end());
}

void System::index_wall_particles(const std::vector<std::uint32_t>& n_candidates) {
  const std::size_t n = particles.n_real;
  wall_candidate_offset_.assign(n + 1, 0);
  wall_particles_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    wall_candidate_offset_[i + 1] = wall_candidate_offset_[i] + n_candidates[i];
    if (n_candidates[i] > 0)
      wall_particles_.push_back(std::uint32_t(i));
  }
}

void System::carry_wall_slots(const std::vector<std::int32_t>& slots_of_id) {
  std::vector<WallSlot>& slots = rebuild_scratch_.slots;
  assign_reusing(slots, wall_slots * wall_particles_.size(), WallSlot{});
  for (std::size_t q = 0; q < wall_particles_.size(); ++q) {
    const std::int32_t old_q = slots_of_id[particles.id[wall_particles_[q]]];
    if (old_q >= 0)
      std::copy_n(slots_.begin() + wall_slots * old_q, wall_slots, slots.begin() + wall_slots * q);
  }
  slots_.swap(slots);
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
  for (int k = 1; k < 3; ++k) // a stable insertion sort (std::stable_sort allocates a buffer)
    for (int m = k; m > 0 && extent[axis[m]] > extent[axis[m - 1]]; --m)
      std::swap(axis[m], axis[m - 1]);
  const double cell = 2 * r_max_ + skin_;
  std::vector<std::uint64_t>& key = rebuild_scratch_.sort_key;
  std::vector<std::uint32_t>& perm = rebuild_scratch_.sort_perm;
  key.resize(n);
  perm.resize(n);
  // A clump's members take its centre's cell, so that they stay together (equal keys keep
  // their order, and a clump's members are inserted together).
  const bool clumps = !clumps_.empty();
#pragma omp parallel for schedule(static) num_threads(n_threads_)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = clumps && body_of_slot_[i] >= 0
                        ? clumps_.position[std::size_t(body_of_slot_[i])]
                        : p.position[i];
    // (A clump's centre may lie outside its members' centres' box: clamped to it.)
    const Vec3 q{std::max(0.0, x.x - lo.x) / cell, std::max(0.0, x.y - lo.y) / cell,
                 std::max(0.0, x.z - lo.z) / cell};
    key[i] = (std::uint64_t(q[axis[0]]) << 42) | (std::uint64_t(q[axis[1]]) << 21) |
             std::uint64_t(q[axis[2]]);
    perm[i] = std::uint32_t(i);
  }
  // The order of a stable sort by key (equal keys keep their index order), without the
  // buffer std::stable_sort allocates.
  std::sort(perm.begin(), perm.end(), [&](std::uint32_t a, std::uint32_t b) {
    return key[a] < key[b] || (key[a] == key[b] && a < b);
  });
  // Each array is gathered into a buffer of its type and copied back (its ghost slots, beyond
  // n, are left as they are: make_ghosts() fills them anew).
  const auto apply = [&](auto& v, auto& gathered) {
    gathered.resize(n);
#pragma omp parallel num_threads(n_threads_)
    {
#pragma omp for schedule(static)
      for (std::size_t k = 0; k < n; ++k)
        gathered[k] = v[perm[k]];
#pragma omp for schedule(static)
      for (std::size_t k = 0; k < n; ++k)
        v[k] = gathered[k];
    }
  };
  RebuildScratch& scratch = rebuild_scratch_;
  apply(p.position, scratch.gather_vec3);
  apply(p.velocity, scratch.gather_vec3);
  apply(p.angular_velocity, scratch.gather_vec3);
  apply(p.force, scratch.gather_vec3);
  apply(p.torque, scratch.gather_vec3);
  apply(p.radius, scratch.gather_double);
  apply(p.mass, scratch.gather_double);
  apply(p.inertia, scratch.gather_double);
  apply(p.material, scratch.gather_int);
  apply(p.id, scratch.gather_id);
}

void System::refresh_ghosts() {
  auto& p = particles;
  const std::size_t n = p.n_real;
  const double c = cos_t_, s = -sin_t_; // ghosts are rotated by -angle
  for (std::size_t g = 0; g < n_periodic_ghosts_; ++g) {
    const auto o = ghost_owner_[g];
    p.position[n + g] = rotate_z(p.position[o], c, s) - shift_;
    packed_position_[n + g] = {p.position[n + g].x, p.position[n + g].y, p.position[n + g].z,
                               p.radius[n + g]};
    p.velocity[n + g] = rotate_z(p.velocity[o], c, s);
    p.angular_velocity[n + g] = rotate_z(p.angular_velocity[o], c, s);
    pack_motion(n + g);
  }
}

void System::count_particle_costs() {
  // Estimated cost of each particle's share of the force evaluation, in units of one listed
  // pair's distance test, as measured on a settled bed: a contact costs 4 more (the law, its
  // gathers and the scatter), a wall candidate face 4 (closest feature), a near-wall particle
  // 8 of its own.
  const auto& p = particles;
  const std::size_t n = p.n_real, np = neighbors_.n_pairs();
  std::vector<std::uint8_t>& pair_touch = rebuild_scratch_.pair_touch;
  pair_touch.resize(np);
#pragma omp parallel for schedule(static) num_threads(n_threads_)
  for (std::size_t k = 0; k < np; ++k) {
    const double rs = p.radius[neighbors_.pair_i[k]] + p.radius[neighbors_.pair_j[k]];
    pair_touch[k] = meshes::norm2(p.position[neighbors_.pair_i[k]] -
                                  p.position[neighbors_.pair_j[k]]) < rs * rs;
  }
  particle_cost_.resize(n);
#pragma omp parallel for schedule(static) num_threads(n_threads_)
  for (std::size_t i = 0; i < n; ++i) {
    const auto n_candidates = wall_candidate_offset_[i + 1] - wall_candidate_offset_[i];
    particle_cost_[i] = 4.0 * n_candidates + (n_candidates > 0 ? 8.0 : 0.0);
  }
  // Pairs are listed by their first particle: each thread adds the pairs of a contiguous
  // range of particles, in list order.
  const auto& pi = neighbors_.pair_i;
#pragma omp parallel num_threads(n_threads_)
  {
    const std::size_t t = std::size_t(omp_get_thread_num()), nt = std::size_t(n_threads_);
    const auto first = std::uint32_t(n * t / nt), last = std::uint32_t(n * (t + 1) / nt);
    const auto k0 = std::size_t(std::lower_bound(pi.begin(), pi.end(), first) - pi.begin());
    const auto k1 = std::size_t(std::lower_bound(pi.begin(), pi.end(), last) - pi.begin());
    for (std::size_t k = k0; k < k1; ++k)
      particle_cost_[pi[k]] += 1.0 + 4.0 * pair_touch[k];
  }
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
  size_foreign_forces();
}

void System::size_foreign_forces() {
  // Room for every listed pair of a thread whose partner (a ghost's owner) another thread
  // owns: the most its evaluation can keep aside.
  const std::size_t n = particles.n_real;
  foreign_.resize(n_threads_);
#pragma omp parallel for schedule(static, 1) num_threads(n_threads_)
  for (int t = 0; t < n_threads_; ++t) {
    const std::size_t begin = owner_split_[t], end = owner_split_[t + 1];
    std::size_t count = 0;
    for (std::size_t k = pair_split_[t]; k < pair_split_[t + 1]; ++k) {
      const std::uint32_t j = neighbors_.pair_j[k];
      const std::size_t o = j < n ? j : ghost_owner_[j - n];
      count += o < begin || o >= end;
    }
    ForeignForces& f = foreign_[t];
    f.target.resize(count);
    f.force.resize(count);
    f.torque.resize(count);
    f.n = 0;
  }
}

void System::pack_particles() {
  const auto& p = particles;
  const auto m0 = p.n_real > 0 ? p.material[0] : -1;
  const bool uniform =
      std::all_of(p.material.begin(), p.material.begin() + std::ptrdiff_t(p.n_real),
                  [m0](int m) { return m == m0; });
  uniform_material_ = uniform ? m0 : -1;
  packed_position_.resize(p.position.size());
  packed_motion_.resize(p.position.size());
  pair_touching_.resize(pair_history_.size());
  wall_candidate_bound_.resize(wall_candidate_.size());
#pragma omp parallel num_threads(n_threads_)
  {
#pragma omp for schedule(static) nowait
    for (std::size_t i = 0; i < p.position.size(); ++i) {
      packed_position_[i] = {p.position[i].x, p.position[i].y, p.position[i].z, p.radius[i]};
      pack_motion(i);
    }
    // A pair holds a history only while it touches (the kernel clears it when it stops).
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < pair_history_.size(); ++k)
      pair_touching_[k] = meshes::norm2(pair_history_[k]) != 0;
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < wall_candidate_.size(); ++k) {
      const std::uint32_t w = wall_candidate_[k] >> 24, f = wall_candidate_[k] & 0xFFFFFFu;
      if (wall_kind_[w] == WallKind::mesh)
        wall_candidate_bound_[k] = walls_[std::size_t(wall_local_[w])].bound(f);
    }
  }
}

} // namespace wear::dem

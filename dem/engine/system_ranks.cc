// A DEM bed decomposed over ranks (docs/dem.md, "A bed decomposed over ranks"): one slab per
// rank (SlabCuts), the messages through a RankLink.
//
// Ownership: rank r owns the particles whose centre lay in its slab at the last list rebuild
// and computes their walls, kicks and drift. Between rebuilds a particle moves at most half a
// skin; every slab is at least the reach 2 r_max + skin wide (checked at setup), so a
// particle only ever passes to an adjacent rank, and only adjacent ranks' particles interact.
//
// Ghosts go up: rank r receives, at each rebuild, copies of the particles of rank r - 1 within
// the reach of its lower cut (position, velocity, spin, radius, mass, inertia, material, id)
// and lists every pair across that cut, each once over all ranks: a pair within the list's
// cut-off r_i + r_j + skin has its lower particle within reach of the cut. Each step the
// ghosts' positions, velocities and spins are refreshed from their owners, and the forces and
// torques on them go back down to the owners, which add them after their own contacts (in the
// order the ghosts were sent). Ghosts of another rank follow the periodic ghosts in the ghost
// slots and own their slot, so the pair kernel sends their forces to the threads' lists
// (ForeignForces), added into their slots; off the seam they are plain copies, not rotated.
//
// At a rebuild, particles whose centre left the slab go to the neighbour with their state,
// last forces and wall-contact slots; the tangential histories of every listed pair with a
// leaving particle go to both neighbours, keyed by the two stable ids in the canonical
// orientation (CarriedHistory): the pair is listed next by the rank owning its upper
// particle, which changes by at most one rank, and only when one of the two leaves. The
// rebuild decision is the same on every rank (the largest displacement over all ranks), so all
// rebuild on the same step.
//
// Periodic seam: a periodic sector or slab decomposed over ranks is a ring whose slabs span
// the period (so are angular slabs round a full circle, whose seam turns by 2 pi: the identity);
// the last rank's ghosts reach rank 0 as periodic images (x -> R(-angle) x - L, vectors rotated),
// flagged as images in rank 0's ghost slots, so the kernel returns their forces rotated by +angle
// and their histories are turned as a periodic ghost's. A particle wraps on its own rank
// (wrap_into_sector) and passes round the seam; the receiver turns its own histories in the
// particle's frame by the wrap, which travels with it.
//
// Clumps: a body is owned by the rank whose slab holds its centre, and its members with it
// wherever they lie (owner_rank); at a rebuild a body whose centre left the slab goes to the
// neighbour whole (its pose, momenta, last force and torque, mass properties and members' ids
// and offsets), its members as particles with their slots and histories. A member lies at most
// the overhang (its largest distance from its body's centre) beyond its rank's slab: the ghosts
// reach that much further (ghost_reach) and a slab holds two overhangs besides the contact
// reach. The forces on member ghosts go back to their owners before the bodies gather them.
//
// Assumptions: stable ids unique over all ranks (checked at setup) unless every rank holds
// the same bed, of which each then keeps its own; an exception on one rank (a particle too
// fast, outside the domain) leaves the others waiting in the next message: the caller aborts
// the ranks.
#include "dem/engine/reused_buffer.h"
#include "dem/engine/system.h"
#include "meshes/constants.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace wear::dem {

namespace {
/// Doubles per record: a migrating particle (position, velocity, spin, force, torque, radius,
/// mass, inertia, material, id, the wrap it took across the seam, slot count; then its slots), a
/// wall slot (normal, delta, wall), a history (lower id, higher id, vector), a ghost (position,
/// velocity, spin, radius, mass, inertia, material, id), a ghost's motion each step, the load going
/// back.
constexpr std::size_t particle_values = 22, slot_values = 7, history_values = 5, ghost_values = 14,
                      motion_values = 9, load_values = 6;
/// Doubles per migrating body (position, velocity, orientation, angular momentum, force, torque,
/// mass, principal moments, member count) and per member after it (id, body-frame centre).
constexpr std::size_t body_values = 24, member_values = 4;

inline void put(std::vector<double>& b, const Vec3& v) {
  b.push_back(v.x);
  b.push_back(v.y);
  b.push_back(v.z);
}
inline Vec3 vec(const double* a) {
  return {a[0], a[1], a[2]};
}
inline Vec3 rotate_z(const Vec3& v, double c, double s) {
  return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

/// An order-free fingerprint of the particles (ids and position bits), below 2^52 so that it
/// travels exactly as a double.
double fingerprint(const Particles& p) {
  std::uint64_t h = 0;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    std::uint64_t x = std::uint64_t(p.id[i]) * 0x9E3779B97F4A7C15ull;
    for (double c : {p.position[i].x, p.position[i].y, p.position[i].z}) {
      std::uint64_t bits;
      std::copy_n(reinterpret_cast<const unsigned char*>(&c), 8,
                  reinterpret_cast<unsigned char*>(&bits));
      x = (x ^ bits) * 0xBF58476D1CE4E5B9ull;
      x ^= x >> 31;
    }
    h += x;
  }
  return double(h & ((std::uint64_t(1) << 52) - 1));
}
} // namespace

void System::set_rank_link(RankLink* link, const RankSlabs* slabs) {
  if (set_up_)
    throw std::logic_error("System::set_rank_link() after setup()");
  if (link && link->n_ranks() > 1 && !slabs)
    throw std::invalid_argument("System::set_rank_link(): the slabs of the ranks are missing");
  const bool ranked = link && link->n_ranks() > 1;
  rank_link_ = ranked ? link : nullptr;
  rank_slabs_ = ranked ? slabs : nullptr;
  if (ranked) {
    slab_cuts_ = slabs->cuts();
    if (slab_cuts_.n_ranks() != link->n_ranks())
      throw std::invalid_argument(
          "System::set_rank_link(): " + std::to_string(slab_cuts_.n_ranks()) + " slabs for " +
          std::to_string(link->n_ranks()) + " ranks");
  }
}

void System::distribute_over_ranks() {
  auto& p = particles;
  RankLink& link = *rank_link_;
  const double n = double(p.n_real), h = fingerprint(p);
  double stats[4] = {n, -n, h, -h};
  link.max_over_ranks(stats, 4);
  if (stats[0] == 0)
    throw std::invalid_argument("DEM: no particles (on any rank)");
  std::vector<std::int32_t> no_slots;
  std::vector<CarriedHistory> no_histories;
  if (!clumps_.empty())
    clumps_.index_members(p, rebuild_scratch_.clump_slot_of_id, body_of_slot_);
  if (stats[0] == -stats[1] && stats[2] == -stats[3]) {
    // Every rank holds the same bed: each keeps its own (a migration that sends nothing).
    std::size_t kept = 0;
    for (std::size_t i = 0; i < p.n_real; ++i)
      if (owner_rank(i) == link.rank())
        move_particle(kept++, i);
    p.n_real = kept;
    p.resize_ghosts(0);
    keep_own_bodies();
  } else {
    // Passed along rank by rank until every particle is with its owner.
    for (int hop = 0;; ++hop) {
      double misplaced = 0;
      for (std::size_t i = 0; i < p.n_real; ++i)
        misplaced += owner_rank(i) != link.rank();
      link.max_over_ranks(&misplaced, 1);
      if (misplaced == 0 || hop > link.n_ranks())
        break;
      migrate_over_ranks(no_slots, no_histories);
    }
  }
}

// A whole bed (one process's layout) over ranks: every rank takes all of it and keys its
// histories and wall slots by id and wraps it into the sector, as a rebuild of one process
// would; then keeps the particles its slab owns and the histories of the pairs with one of
// them (a pair is listed on the rank of one of its particles), and lists them as a rebuild
// does (the ghost exchange is the ranks' common one). Nothing migrates: every rank cut the
// same whole bed by the same slabs.
void System::import_whole_state(const SystemState& s) {
  check_importable(s, true);
  take_particles(s);
  reset_wear_integrals();
  move_walls(time_);
  key_by_id(false);
  std::vector<CarriedHistory>& old = rebuild_scratch_.old_histories;
  auto& p = particles;
  std::vector<std::uint8_t> here(std::size_t(next_id_), 0);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < p.n_real; ++i)
    if (owner_rank(i) == rank_link_->rank()) {
      here[std::size_t(p.id[i])] = 1;
      move_particle(kept++, i);
    }
  p.n_real = kept;
  p.resize_ghosts(0);
  keep_own_bodies();
  ghost_owner_.clear();
  n_periodic_ghosts_ = n_image_ghosts_ = 0;
  std::size_t n_old = 0;
  for (const CarriedHistory& e : old)
    if (here[e.key >> 32] || here[e.key & 0xFFFFFFFFull])
      old[n_old++] = e;
  old.resize(n_old);
  relist(old, rebuild_scratch_.slots_of_id);
}

void System::keep_own_bodies() {
  if (clumps_.empty())
    return;
  RankScratch& rs = rank_scratch_;
  resize_reusing(rs.body_stays, clumps_.size());
  for (std::size_t b = 0; b < clumps_.size(); ++b)
    rs.body_stays[b] = slab_cuts_.owner(clumps_.position[b]) == rank_link_->rank();
  clumps_.keep_bodies(rs.body_stays);
  clumps_.index_members(particles, rebuild_scratch_.clump_slot_of_id, body_of_slot_);
}

void System::check_ranks_at_setup() {
  RankLink& link = *rank_link_;
  double clumps = has_clumps_ ? 1 : 0;
  link.max_over_ranks(&clumps, 1);
  has_clumps_ = clumps > 0;
  // A periodic boundary is the seam between the last rank and rank 0: the ranks form a ring
  // and the slabs span the period exactly.
  const std::vector<double>& b = slab_cuts_.bound;
  const auto at = [](double x, double y) { return std::abs(x - y) <= 1e-12 * (1 + std::abs(y)); };
  const std::string what = "DEM over " + std::to_string(link.n_ranks()) + " ranks: ";
  // Angular slabs round the full circle (an annulus) are a ring too, whose seam turns by
  // 2 pi: the identity of a system without a periodic boundary (cos_t_ = 1, sin_t_ = 0).
  constexpr double two_pi = 2 * pi;
  const bool full_circle = slab_cuts_.angular && at(b.back() - b.front(), two_pi);
  if (settings.periodic.enabled && full_circle)
    throw std::invalid_argument(what + "the slabs of a periodic sector span the sector, not the "
                                       "full circle");
  if (link.ring() != (periodic() || full_circle))
    throw std::invalid_argument(
        what + (link.ring() ? "ranks in a ring need a periodic boundary or slabs round the full "
                              "circle"
                            : "a periodic boundary or slabs round the full circle need the ranks "
                              "in a ring (MpiRankLink's `ring`)"));
  if (settings.periodic.enabled &&
      !(slab_cuts_.angular && at(b.front(), 0) && at(b.back(), settings.periodic.angle)))
    throw std::invalid_argument(what + "the slabs of a periodic sector must be angular and span "
                                       "it, 0 to its angle");
  const PeriodicSlab& sl = settings.periodic_slab;
  if (sl.enabled && !(!slab_cuts_.angular && slab_cuts_.axis == sl.axis && at(b.front(), sl.lo) &&
                      at(b.back(), sl.hi)))
    throw std::invalid_argument(what + "the slabs of a periodic slab must lie along its axis and "
                                       "span it, lo to hi");
  double next = double(next_id_);
  link.max_over_ranks(&next, 1);
  next_id_ = std::int64_t(next);
  // Ids unique over the ranks: each id counted once in a sum over the ranks.
  std::vector<double> count(std::size_t(next_id_), 0.0);
  for (std::size_t i = 0; i < particles.n_real; ++i)
    count[std::size_t(particles.id[i])] += 1;
  link.sum_in_rank_order(count.data(), count.size());
  for (std::size_t k = 0; k < count.size(); ++k)
    if (count[k] > 1)
      throw std::invalid_argument("DEM: particle id " + std::to_string(k) + " is held by " +
                                  std::to_string(int(count[k])) +
                                  " ranks (ids must be unique over the ranks)");
  // Members of the bodies of rank r - 1 and of rank r + 1 may each overhang into rank r's slab:
  // it must hold the members' two overhangs besides the contact reach, so that only adjacent
  // ranks meet.
  rank_slabs_->check_widths(2 * r_max_ + skin_ + 2 * member_overhang_);
}

void System::reduce_setup_values(double& t_r, double& r_max, double& r_min, double& overhang) {
  double v[4] = {-t_r, r_max, -r_min, overhang};
  rank_link_->max_over_ranks(v, 4);
  t_r = -v[0];
  r_max = v[1];
  r_min = -v[2];
  overhang = v[3];
}

void System::migrate_over_ranks(std::vector<std::int32_t>& slots_of_id,
                                std::vector<CarriedHistory>& old) {
  auto& p = particles;
  RankScratch& rs = rank_scratch_;
  const int rank = rank_link_->rank(), n_ranks = rank_link_->n_ranks();
  const bool ring = rank_link_->ring();
  const std::size_t n = p.n_real;
  // A member goes where its body's centre goes (owner_rank).
  if (!clumps_.empty())
    clumps_.index_members(p, rebuild_scratch_.clump_slot_of_id, body_of_slot_);
  // Round the seam on a ring (a particle that wrapped), else towards the owner (at setup,
  // over several ranks).
  const auto direction = [&](int o) -> signed char {
    const bool up = ring ? o == (rank + 1) % n_ranks : o > rank;
    const bool down = ring ? o == (rank + n_ranks - 1) % n_ranks : o < rank;
    return o == rank ? 0 : up ? 1 : down ? -1 : o > rank ? 1 : -1;
  };
  resize_reusing(rs.leaving, n);
  std::size_t n_leaving = 0;
  for (std::size_t i = 0; i < n; ++i) {
    rs.leaving[i] = direction(owner_rank(i));
    n_leaving += rs.leaving[i] != 0;
  }
  // The wrap each particle took in this rebuild (wrap_into_sector): the receiver turns its own
  // histories of it alike.
  const std::vector<signed char>* wrapped = periodic() ? &rebuild_scratch_.wrap : nullptr;
  // Messages: [particle count, particles with their slots..., history count, histories...].
  rs.up.assign(1, 0.0);
  rs.down.assign(1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (rs.leaving[i] == 0)
      continue;
    std::vector<double>& b = rs.leaving[i] > 0 ? rs.up : rs.down;
    b[0] += 1;
    put(b, p.position[i]);
    put(b, p.velocity[i]);
    put(b, p.angular_velocity[i]);
    put(b, p.force[i]);
    put(b, p.torque[i]);
    b.push_back(p.radius[i]);
    b.push_back(p.mass[i]);
    b.push_back(p.inertia[i]);
    b.push_back(double(p.material[i]));
    b.push_back(double(p.id[i]));
    b.push_back(wrapped && i < wrapped->size() ? double((*wrapped)[i]) : 0.0);
    const std::int32_t q = slots_of_id.empty() ? -1 : slots_of_id[std::size_t(p.id[i])];
    int k = 0;
    while (q >= 0 && k < wall_slots && slots_[wall_slots * std::size_t(q) + k].wall >= 0)
      ++k;
    b.push_back(double(k));
    for (int s = 0; s < k; ++s) {
      const WallSlot& sl = slots_[wall_slots * std::size_t(q) + s];
      put(b, sl.normal);
      put(b, sl.delta);
      b.push_back(double(sl.wall));
    }
  }
  // Histories of the pairs with a leaving particle, to both neighbours.
  const std::size_t history_at = rs.up.size();
  rs.up.push_back(0.0);
  if (n_leaving > 0 && !old.empty()) {
    if (rs.leaves_by_id.size() < std::size_t(next_id_))
      resize_reusing(rs.leaves_by_id, std::size_t(next_id_));
    for (std::size_t i = 0; i < n; ++i)
      rs.leaves_by_id[std::size_t(p.id[i])] = rs.leaving[i] != 0;
    for (const CarriedHistory& e : old) {
      const std::uint64_t lower = e.key >> 32, higher = e.key & 0xFFFFFFFFull;
      if (!rs.leaves_by_id[lower] && !rs.leaves_by_id[higher])
        continue;
      rs.up[history_at] += 1;
      rs.up.push_back(double(lower));
      rs.up.push_back(double(higher));
      put(rs.up, e.h);
    }
    for (std::size_t i = 0; i < n; ++i)
      rs.leaves_by_id[std::size_t(p.id[i])] = 0;
  }
  rs.down.insert(rs.down.end(), rs.up.begin() + std::ptrdiff_t(history_at), rs.up.end());
  // Bodies: [count, bodies with their members...] after the histories, each to its side.
  const std::size_t bodies_up = rs.up.size(), bodies_down = rs.down.size();
  rs.up.push_back(0.0);
  rs.down.push_back(0.0);
  const Clumps& c = clumps_;
  resize_reusing(rs.body_stays, c.size());
  for (std::size_t b = 0; b < c.size(); ++b) {
    const signed char d = direction(slab_cuts_.owner(c.position[b]));
    rs.body_stays[b] = d == 0;
    if (d == 0)
      continue;
    std::vector<double>& m = d > 0 ? rs.up : rs.down;
    m[d > 0 ? bodies_up : bodies_down] += 1;
    put(m, c.position[b]);
    put(m, c.velocity[b]);
    const Quaternion& q = c.orientation[b];
    m.insert(m.end(), {q.w, q.x, q.y, q.z});
    put(m, c.angular_momentum[b]);
    put(m, c.force[b]);
    put(m, c.torque[b]);
    m.push_back(c.mass[b]);
    put(m, c.moments[b]);
    m.push_back(double(c.member_begin[b + 1] - c.member_begin[b]));
    for (std::uint32_t k = c.member_begin[b]; k < c.member_begin[b + 1]; ++k) {
      m.push_back(double(c.member_id[k]));
      put(m, c.member_offset[k]);
    }
  }
  rank_link_->shift(+1, rs.up, rs.from_below);
  rank_link_->shift(-1, rs.down, rs.from_above);

  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (rs.leaving[i] == 0)
      move_particle(kept++, i);
  p.n_real = kept;
  p.resize_ghosts(0);
  clumps_.keep_bodies(rs.body_stays); // those that stay, before those that arrive
  const std::size_t n_local_histories = old.size();
  for (const std::vector<double>* message : {&rs.from_below, &rs.from_above}) {
    if (message->empty())
      continue;
    const double* a = message->data();
    const std::size_t n_particles = std::size_t(*a++);
    for (std::size_t k = 0; k < n_particles; ++k) {
      p.position.push_back(vec(a));
      p.velocity.push_back(vec(a + 3));
      p.angular_velocity.push_back(vec(a + 6));
      p.force.push_back(vec(a + 9));
      p.torque.push_back(vec(a + 12));
      p.radius.push_back(a[15]);
      p.mass.push_back(a[16]);
      p.inertia.push_back(a[17]);
      p.material.push_back(int(a[18]));
      p.id.push_back(std::int64_t(a[19]));
      ++p.n_real;
      const int wrap = int(a[20]), n_slots = int(a[21]);
      if (wrap != 0) {
        // It crossed the seam: this rank's own histories in its frame (it was a ghost here)
        // turn with it, as wrap_into_sector turns those of a particle wrapping on its rank.
        const auto id = std::uint64_t(p.id.back());
        for (std::size_t e = 0; e < n_local_histories; ++e)
          if ((old[e].key >> 32) == id)
            old[e].h = rotate_z(old[e].h, cos_t_, wrap > 0 ? sin_t_ : -sin_t_);
      }
      a += particle_values;
      if (n_slots > 0) {
        // Its slots after the others, found by id (wall_slots_by_id's table).
        const std::size_t q = slots_.size() / wall_slots;
        resize_reusing(slots_, slots_.size() + wall_slots);
        for (int s = 0; s < n_slots; ++s, a += slot_values)
          slots_[wall_slots * q + std::size_t(s)] = {vec(a), vec(a + 3), std::int32_t(a[6])};
        slots_of_id[std::size_t(p.id.back())] = std::int32_t(q);
      }
    }
    const std::size_t n_histories = std::size_t(*a++);
    reserve_reusing(old, old.size() + n_histories);
    for (std::size_t k = 0; k < n_histories; ++k, a += history_values)
      old.push_back({(std::uint64_t(a[0]) << 32) | std::uint64_t(a[1]), 0, vec(a + 2)});
    const std::size_t n_bodies = std::size_t(*a++);
    for (std::size_t k = 0; k < n_bodies; ++k) {
      const std::size_t n_members = std::size_t(a[body_values - 1]);
      rs.member_ids.clear();
      rs.member_offsets.clear();
      for (std::size_t e = 0; e < n_members; ++e) {
        const double* mb = a + body_values + member_values * e;
        rs.member_ids.push_back(std::int64_t(mb[0]));
        rs.member_offsets.push_back(vec(mb + 1));
      }
      clumps_.add_body(vec(a), vec(a + 3), {a[6], a[7], a[8], a[9]}, vec(a + 10), a[19],
                       vec(a + 20), rs.member_ids, rs.member_offsets);
      clumps_.force.back() = vec(a + 13);
      clumps_.torque.back() = vec(a + 16);
      a += body_values + member_values * n_members;
    }
  }
  if (!clumps_.empty())
    clumps_.index_members(p, rebuild_scratch_.clump_slot_of_id, body_of_slot_);
}

void System::exchange_rank_ghosts() {
  auto& p = particles;
  RankScratch& rs = rank_scratch_;
  const int rank = rank_link_->rank(), n_ranks = rank_link_->n_ranks();
  const bool ring = rank_link_->ring();
  // A member may lie its overhang beyond the cut on the other side: the ghosts' reach.
  const double reach = ghost_reach();
  // Across the seam the ghosts are the periodic images (rotated by -angle, shifted by -L).
  const bool seam = ring && rank + 1 == n_ranks;
  const double c = cos_t_, s = seam ? -sin_t_ : 0.0;
  const Vec3 shift = seam ? shift_ : Vec3{0, 0, 0};
  rs.sent_up.clear();
  rs.up.clear();
  if (ring || rank + 1 < n_ranks)
    for (std::size_t i = 0; i < p.n_real; ++i) {
      if (!(slab_cuts_.below_upper_cut(rank, p.position[i]) < reach))
        continue;
      rs.sent_up.push_back(std::uint32_t(i));
      put(rs.up, seam ? rotate_z(p.position[i], c, s) - shift : p.position[i]);
      put(rs.up, seam ? rotate_z(p.velocity[i], c, s) : p.velocity[i]);
      put(rs.up, seam ? rotate_z(p.angular_velocity[i], c, s) : p.angular_velocity[i]);
      rs.up.push_back(p.radius[i]);
      rs.up.push_back(p.mass[i]);
      rs.up.push_back(p.inertia[i]);
      rs.up.push_back(double(p.material[i]));
      rs.up.push_back(double(p.id[i]));
    }
  rank_link_->shift(+1, rs.up, rs.from_below);
  // The ghosts of the rank below own their slots: their forces stay there and go back down.
  const std::size_t first = p.n_real + ghost_owner_.size(), m = rs.from_below.size() / ghost_values;
  for (std::size_t g = 0; g < m; ++g)
    ghost_owner_.push_back(std::uint32_t(first + g));
  if (ring && rank == 0) // the last rank's, across the seam
    n_image_ghosts_ += m;
}

void System::place_rank_ghosts(const std::vector<double>& m) {
  auto& p = particles;
  const std::size_t first = p.n_real + n_periodic_ghosts_;
  for (std::size_t g = 0; g < m.size() / ghost_values; ++g) {
    const double* a = &m[ghost_values * g];
    const std::size_t k = first + g;
    p.position[k] = vec(a);
    p.velocity[k] = vec(a + 3);
    p.angular_velocity[k] = vec(a + 6);
    p.radius[k] = a[9];
    p.mass[k] = a[10];
    p.inertia[k] = a[11];
    p.material[k] = int(a[12]);
    p.id[k] = std::int64_t(a[13]);
    p.force[k] = {};
    p.torque[k] = {};
  }
}

void System::refresh_rank_ghosts() {
  auto& p = particles;
  RankScratch& rs = rank_scratch_;
  resize_reusing(rs.up, motion_values * rs.sent_up.size());
  const bool seam = rank_link_->ring() && rank_link_->rank() + 1 == rank_link_->n_ranks();
  const double c = cos_t_, s = seam ? -sin_t_ : 0.0;
  const Vec3 shift = seam ? shift_ : Vec3{0, 0, 0};
  for (std::size_t g = 0; g < rs.sent_up.size(); ++g) {
    const std::size_t i = rs.sent_up[g];
    double* a = &rs.up[motion_values * g];
    // Exact copies off the seam (c = 1, s = 0, no shift: the same bits).
    const Vec3 x = seam ? rotate_z(p.position[i], c, s) - shift : p.position[i];
    const Vec3 v = seam ? rotate_z(p.velocity[i], c, s) : p.velocity[i];
    const Vec3 w = seam ? rotate_z(p.angular_velocity[i], c, s) : p.angular_velocity[i];
    a[0] = x.x, a[1] = x.y, a[2] = x.z, a[3] = v.x, a[4] = v.y, a[5] = v.z;
    a[6] = w.x, a[7] = w.y, a[8] = w.z;
  }
  rank_link_->shift(+1, rs.up, rs.from_below);
  const std::size_t first = p.n_real + n_periodic_ghosts_, n_rank = p.position.size() - first;
  if (rs.from_below.size() != motion_values * n_rank)
    throw std::logic_error("DEM over ranks: the ghosts of the rank below do not match its message");
  for (std::size_t g = 0; g < n_rank; ++g) {
    const double* a = &rs.from_below[motion_values * g];
    const std::size_t k = first + g;
    p.position[k] = vec(a);
    p.velocity[k] = vec(a + 3);
    p.angular_velocity[k] = vec(a + 6);
    packed_position_[k] = {a[0], a[1], a[2], p.radius[k]};
    pack_motion(k);
    p.force[k] = {};
    p.torque[k] = {};
  }
}

void System::return_ghost_forces() {
  auto& p = particles;
  RankScratch& rs = rank_scratch_;
  const std::size_t first = p.n_real + n_periodic_ghosts_, n_rank = p.position.size() - first;
  resize_reusing(rs.down, load_values * n_rank);
  for (std::size_t g = 0; g < n_rank; ++g) {
    const Vec3 &f = p.force[first + g], &t = p.torque[first + g];
    double* a = &rs.down[load_values * g];
    a[0] = f.x, a[1] = f.y, a[2] = f.z, a[3] = t.x, a[4] = t.y, a[5] = t.z;
  }
  rank_link_->shift(-1, rs.down, rs.from_above);
  if (rs.from_above.size() != load_values * rs.sent_up.size())
    throw std::logic_error("DEM over ranks: the forces of the rank above do not match its ghosts");
  for (std::size_t g = 0; g < rs.sent_up.size(); ++g) {
    const double* a = &rs.from_above[load_values * g];
    p.force[rs.sent_up[g]] += vec(a);
    p.torque[rs.sent_up[g]] += vec(a + 3);
  }
}

void System::ranked_forces(bool need_rebuild, double t_drift) {
  double rebuild_now = need_rebuild ? 1 : 0;
  rank_link_->max_over_ranks(&rebuild_now, 1);
  if (rebuild_now > 0) {
    rebuild(true);
    phase_times_.rebuild += omp_get_wtime() - t_drift;
  } else {
    refresh_ghosts();
    refresh_rank_ghosts();
    phase_times_.integration += omp_get_wtime() - t_drift;
  }
  compute_forces();
  return_ghost_forces();
}

std::size_t System::n_particles_over_ranks() const {
  double n = double(particles.n_real);
  if (rank_link_)
    rank_link_->sum_in_rank_order(&n, 1);
  return std::size_t(n);
}

std::size_t System::n_grains_over_ranks() const {
  std::size_t members = 0;
  for (std::size_t b = 0; b < clumps_.size(); ++b)
    members += clumps_.member_begin[b + 1] - clumps_.member_begin[b];
  double n = double(particles.n_real - members + clumps_.size());
  if (rank_link_)
    rank_link_->sum_in_rank_order(&n, 1);
  return std::size_t(n);
}

WearIntegrals System::wear_integrals_over_ranks(int wall) const {
  WearIntegrals w = wear_integrals(wall);
  if (!rank_link_)
    return w;
  const std::size_t nf = w.archard.size();
  // Flattened in WearIntegrals' order, then the totals.
  std::vector<double> v;
  v.reserve(n_wear_values * nf + 15);
  for (std::size_t f = 0; f < nf; ++f)
    v.insert(v.end(),
             {w.impulse[f].x, w.impulse[f].y, w.impulse[f].z, w.normal_impulse[f], w.archard[f],
              w.sliding_work[f], w.contact_steps[f], w.normal_moment[f].x, w.normal_moment[f].y,
              w.normal_moment[f].z, w.impulse_moment[f].x, w.impulse_moment[f].y,
              w.impulse_moment[f].z, w.impacts[f], w.impact_energy[f], w.impact_measure[f]});
  v.insert(v.end(), {w.total_archard, w.total_normal_impulse, w.total_sliding_work,
                     w.total_impulse.x, w.total_impulse.y, w.total_impulse.z,
                     w.total_normal_moment.x, w.total_normal_moment.y, w.total_normal_moment.z,
                     w.total_impulse_moment.x, w.total_impulse_moment.y, w.total_impulse_moment.z,
                     w.total_impacts, w.total_impact_energy, w.total_impact_measure});
  rank_link_->sum_in_rank_order(v.data(), v.size());
  for (std::size_t f = 0; f < nf; ++f) {
    const double* a = &v[n_wear_values * f];
    w.impulse[f] = vec(a);
    w.normal_impulse[f] = a[3];
    w.archard[f] = a[4];
    w.sliding_work[f] = a[5];
    w.contact_steps[f] = a[6];
    w.normal_moment[f] = vec(a + 7);
    w.impulse_moment[f] = vec(a + 10);
    w.impacts[f] = a[13];
    w.impact_energy[f] = a[14];
    w.impact_measure[f] = a[15];
  }
  const double* t = &v[n_wear_values * nf];
  w.total_archard = t[0];
  w.total_normal_impulse = t[1];
  w.total_sliding_work = t[2];
  w.total_impulse = vec(t + 3);
  w.total_normal_moment = vec(t + 6);
  w.total_impulse_moment = vec(t + 9);
  w.total_impacts = t[12];
  w.total_impact_energy = t[13];
  w.total_impact_measure = t[14];
  return w;
}

} // namespace wear::dem

// A bed decomposed over ranks as one state: packing a rank's part into a message, gathering
// the parts to rank 0, and merging them into the layout of one process.
//
// Merging. Rank r's part lists its pairs (i, j) with i one of its particles and j one of its
// particles, a periodic image of one (slot j - n < n_periodic_ghosts) or a ghost of the rank
// below (the ghost message names its id). In the merged layout the particles follow one
// another in rank order (offset o_r), so i -> o_r + i and a particle of the same rank j ->
// o_r + j. A ghost of the rank below is the particle with its id, unless it came across the
// periodic seam (slot below n_image_ghosts: rank 0's ghosts of the last rank, turned by -angle
// and shifted by -L), which makes it that particle's periodic image: one ghost slot per imaged
// particle. The history stays as its rank listed it, because a ghost of the rank below is not
// turned and an image across the seam is turned exactly as one process turns its images; the
// import keys every history by the two ids in the canonical frame (System::rebuild), so the
// order of the merged list decides nothing. A full circle without a periodic boundary has a
// seam that turns by 2 pi (the identity): its images are plain copies, which the import keys
// alike. Clumps: each rank's bodies follow one another in rank order; their members are named
// by stable id, so they need no renumbering.
//
// The wear window (the open revolution's integrals, per thread per wearing wall) is summed
// over ranks in rank order and over each rank's threads in thread order, into one thread's
// layout; sums of the window are therefore the same up to the order of additions.
#include "dem/engine/rank_states.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace wear::dem {

namespace {

/// Appends the bodies of `from` to `to`, their member ranges shifted past those of `to`.
void append_bodies(ClumpsState& to, const ClumpsState& from) {
  const auto append = [](auto& a, const auto& b) { a.insert(a.end(), b.begin(), b.end()); };
  append(to.position, from.position);
  append(to.velocity, from.velocity);
  append(to.orientation, from.orientation);
  append(to.angular_momentum, from.angular_momentum);
  append(to.force, from.force);
  append(to.torque, from.torque);
  append(to.mass, from.mass);
  append(to.moments, from.moments);
  const auto first = std::uint32_t(to.member_id.size());
  for (std::size_t b = 1; b < from.member_begin.size(); ++b)
    to.member_begin.push_back(first + from.member_begin[b]);
  append(to.member_id, from.member_id);
  append(to.member_offset, from.member_offset);
}

/// The fields of a body state, packed and unpacked in one order.
template <class V>
void visit_bodies(ClumpsState& c, V& v) {
  v(c.position), v(c.velocity), v(c.orientation), v(c.angular_momentum), v(c.force), v(c.torque);
  v(c.mass), v(c.moments), v(c.member_begin), v(c.member_id), v(c.member_offset);
}

// One list of the fields drives packing and unpacking (SystemState's order).
template <class V>
void visit(SystemState& s, V& v) {
  v(s.position), v(s.velocity), v(s.angular_velocity), v(s.force), v(s.torque);
  v(s.radius), v(s.mass), v(s.inertia), v(s.material), v(s.id);
  v(s.ghost_owner), v(s.pair_i), v(s.pair_j), v(s.pair_history);
  v(s.wall_particles), v(s.slot_normal), v(s.slot_delta), v(s.slot_wall);
  v(s.time), v(s.n_steps), v(s.n_rebuilds);
  v(s.reference_position), v(s.wall_candidate_offset), v(s.wall_candidate), v(s.particle_cost);
  v(s.next_id), v(s.wall_reference_time), v(s.wear_window), v(s.n_threads);
  v(s.rank), v(s.n_ranks), v(s.n_periodic_ghosts), v(s.n_image_ghosts);
  v(s.rank_ghosts), v(s.rank_sent_up);
  visit_bodies(s.clumps, v);
}

struct Packer {
  std::vector<double>& out;
  template <class T>
  void operator()(const std::vector<T>& v) {
    out.push_back(double(v.size()));
    for (const auto& x : v)
      (*this)(x);
  }
  void operator()(const Vec3& x) { out.insert(out.end(), {x.x, x.y, x.z}); }
  void operator()(const Quaternion& q) { out.insert(out.end(), {q.w, q.x, q.y, q.z}); }
  template <class T, class = std::enable_if_t<std::is_arithmetic_v<T>>>
  void operator()(const T& x) {
    out.push_back(double(x));
  }
};

struct Unpacker {
  const double* at;
  const double* end;
  double next() {
    if (at == end)
      throw std::invalid_argument("DEM state message: shorter than its sizes say");
    return *at++;
  }
  template <class T>
  void operator()(std::vector<T>& v) {
    const double n = next();
    if (!(n >= 0) || n > double(end - at))
      throw std::invalid_argument("DEM state message: a size out of range");
    v.resize(std::size_t(n));
    for (auto& x : v)
      (*this)(x);
  }
  void operator()(Vec3& x) {
    x.x = next();
    x.y = next();
    x.z = next();
  }
  void operator()(Quaternion& q) {
    q.w = next();
    q.x = next();
    q.y = next();
    q.z = next();
  }
  template <class T, class = std::enable_if_t<std::is_arithmetic_v<T>>>
  void operator()(T& x) {
    x = T(next());
  }
};

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("DEM states of the ranks: " + what);
}

} // namespace

std::vector<double> pack_state(const SystemState& s) {
  std::vector<double> out;
  Packer packer{out};
  visit(const_cast<SystemState&>(s), packer); // the packer only reads
  return out;
}

SystemState unpack_state(const double* values, std::size_t n) {
  SystemState s;
  Unpacker unpacker{values, values + n};
  visit(s, unpacker);
  if (unpacker.at != unpacker.end)
    throw std::invalid_argument("DEM state message: longer than its sizes say");
  return s;
}

std::vector<SystemState> gather_rank_states(const SystemState& mine, RankLink& link) {
  std::vector<double> all;
  std::vector<std::size_t> counts;
  link.gather_to_first(pack_state(mine), all, counts);
  std::vector<SystemState> parts;
  std::size_t at = 0;
  for (const std::size_t n : counts) {
    parts.push_back(unpack_state(all.data() + at, n));
    at += n;
  }
  return parts;
}

bool continues_exactly(const SystemState& s, int rank, int n_ranks) {
  return s.rank == rank && s.n_ranks == n_ranks &&
         s.reference_position.size() == s.position.size() &&
         s.wall_candidate_offset.size() == s.position.size() + 1;
}

SystemState merge_rank_states(const std::vector<SystemState>& parts) {
  require(!parts.empty(), "none given");
  const int n_ranks = int(parts.size());
  for (int r = 0; r < n_ranks; ++r) {
    const SystemState& s = parts[std::size_t(r)];
    require(s.rank == r && s.n_ranks == n_ranks,
            "part " + std::to_string(r) + " was written by rank " + std::to_string(s.rank) +
                " of " + std::to_string(s.n_ranks) + ", not rank " + std::to_string(r) + " of " +
                std::to_string(n_ranks));
    require(s.time == parts[0].time && s.n_steps == parts[0].n_steps &&
                s.n_rebuilds == parts[0].n_rebuilds,
            "rank " + std::to_string(r) + " stands at another step than rank 0");
    require(s.n_threads > 0 && s.wear_window.size() % std::size_t(s.n_threads) == 0 &&
                s.wear_window.size() / std::size_t(s.n_threads) ==
                    parts[0].wear_window.size() / std::size_t(std::max(1, parts[0].n_threads)),
            "rank " + std::to_string(r) + "'s wear window does not match rank 0's");
  }
  SystemState m;
  for (const SystemState& s : parts) {
    m.position.insert(m.position.end(), s.position.begin(), s.position.end());
    m.velocity.insert(m.velocity.end(), s.velocity.begin(), s.velocity.end());
    m.angular_velocity.insert(m.angular_velocity.end(), s.angular_velocity.begin(),
                              s.angular_velocity.end());
    m.force.insert(m.force.end(), s.force.begin(), s.force.end());
    m.torque.insert(m.torque.end(), s.torque.begin(), s.torque.end());
    m.radius.insert(m.radius.end(), s.radius.begin(), s.radius.end());
    m.mass.insert(m.mass.end(), s.mass.begin(), s.mass.end());
    m.inertia.insert(m.inertia.end(), s.inertia.begin(), s.inertia.end());
    m.material.insert(m.material.end(), s.material.begin(), s.material.end());
    m.id.insert(m.id.end(), s.id.begin(), s.id.end());
    m.next_id = std::max(m.next_id, s.next_id);
    // Bodies in rank order; their members are named by id, which the merge keeps.
    append_bodies(m.clumps, s.clumps);
  }
  m.clumps.check();
  const std::size_t n = m.position.size();
  require(n < std::numeric_limits<std::uint32_t>::max(), "too many particles for one process");
  std::vector<std::int64_t> index_of;
  for (std::size_t k = 0; k < n; ++k) {
    const std::int64_t id = m.id[k];
    require(id >= 0 && id < std::numeric_limits<std::uint32_t>::max(),
            "particle id " + std::to_string(id) + " out of range");
    if (std::size_t(id) >= index_of.size())
      index_of.resize(std::size_t(id) + 1, -1);
    require(index_of[std::size_t(id)] < 0,
            "particle id " + std::to_string(id) + " is held by two ranks");
    index_of[std::size_t(id)] = std::int64_t(k);
  }
  // One image slot per imaged particle.
  std::vector<std::int64_t> image_of(n, -1);
  const auto image = [&](std::size_t owner) {
    if (image_of[owner] < 0) {
      image_of[owner] = std::int64_t(m.ghost_owner.size());
      m.ghost_owner.push_back(std::uint32_t(owner));
    }
    return std::uint32_t(n + std::size_t(image_of[owner]));
  };
  std::size_t offset = 0;
  for (std::size_t r = 0; r < parts.size(); ++r) {
    const SystemState& s = parts[r];
    const std::size_t n_r = s.position.size(), n_ghosts = s.ghost_owner.size();
    // One process (no rank fields): every ghost is a periodic image of its owner.
    const bool ranked = s.n_ranks > 1;
    const std::size_t n_periodic = ranked ? std::size_t(s.n_periodic_ghosts) : n_ghosts;
    const std::size_t n_image = ranked ? std::size_t(s.n_image_ghosts) : n_ghosts;
    require(n_periodic <= n_ghosts && s.rank_ghosts.size() == 14 * (n_ghosts - n_periodic),
            "rank " + std::to_string(r) + "'s ghosts do not match its ghost slots");
    std::vector<std::uint32_t> slot(n_ghosts); // merged index of each ghost slot
    for (std::size_t g = 0; g < n_ghosts; ++g) {
      std::size_t owner;
      if (g < n_periodic) {
        require(s.ghost_owner[g] < n_r, "rank " + std::to_string(r) + ": a ghost without owner");
        owner = offset + s.ghost_owner[g];
      } else {
        const auto id = std::int64_t(s.rank_ghosts[14 * (g - n_periodic) + 13]);
        require(id >= 0 && std::size_t(id) < index_of.size() && index_of[std::size_t(id)] >= 0,
                "rank " + std::to_string(r) + " holds a ghost of particle " + std::to_string(id) +
                    ", which no rank holds");
        owner = std::size_t(index_of[std::size_t(id)]);
      }
      slot[g] = g < n_image ? image(owner) : std::uint32_t(owner);
    }
    for (std::size_t k = 0; k < s.pair_i.size(); ++k) {
      const std::uint32_t i = s.pair_i[k], j = s.pair_j[k];
      require(i < n_r && j < n_r + n_ghosts, "rank " + std::to_string(r) + ": pair " +
                                                 std::to_string(k) +
                                                 " refers to a missing particle");
      m.pair_i.push_back(std::uint32_t(offset + i));
      m.pair_j.push_back(j < n_r ? std::uint32_t(offset + j) : slot[j - n_r]);
      m.pair_history.push_back(s.pair_history[k]);
    }
    for (const auto q : s.wall_particles)
      m.wall_particles.push_back(std::uint32_t(offset + q));
    m.slot_normal.insert(m.slot_normal.end(), s.slot_normal.begin(), s.slot_normal.end());
    m.slot_delta.insert(m.slot_delta.end(), s.slot_delta.begin(), s.slot_delta.end());
    m.slot_wall.insert(m.slot_wall.end(), s.slot_wall.begin(), s.slot_wall.end());
    offset += n_r;
  }
  const SystemState& first = parts[0];
  m.time = first.time;
  m.n_steps = first.n_steps;
  m.n_rebuilds = first.n_rebuilds;
  m.wall_reference_time = first.wall_reference_time;
  m.n_threads = 1;
  const std::size_t length = first.wear_window.size() / std::size_t(std::max(1, first.n_threads));
  m.wear_window.assign(length, 0.0);
  for (const SystemState& s : parts)
    for (std::size_t at = 0; at < s.wear_window.size(); ++at)
      m.wear_window[at % length] += s.wear_window[at];
  return m;
}

SystemState whole_state_on_every_rank(const SystemState& mine, RankLink& link) {
  const std::vector<SystemState> parts = gather_rank_states(mine, link);
  std::vector<double> packed, all;
  if (link.rank() == 0)
    packed = pack_state(merge_rank_states(parts));
  link.gather_in_rank_order(packed, all);
  return unpack_state(all.data(), all.size());
}

void add_state_particles(Particles& p, const SystemState& s, bool own_part, double density) {
  const auto& at = own_part && s.reference_position.size() == s.position.size()
                       ? s.reference_position
                       : s.position;
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    p.add(at[i], s.velocity[i], s.radius[i], density, s.material[i]);
    p.mass.back() = s.mass[i];
    p.inertia.back() = s.inertia[i];
    p.id.back() = s.id[i];
  }
}

Particles gather_particles(const Particles& p, RankLink* link, GatherTo to,
                           const std::function<bool(std::size_t)>& keep, double density) {
  constexpr std::size_t values = 13; // position, velocity, spin, radius, mass, id, material
  std::vector<double> mine, all;
  for (std::size_t i = 0; i < p.n_real; ++i)
    if (!keep || keep(i))
      mine.insert(mine.end(), {p.position[i].x, p.position[i].y, p.position[i].z, p.velocity[i].x,
                               p.velocity[i].y, p.velocity[i].z, p.angular_velocity[i].x,
                               p.angular_velocity[i].y, p.angular_velocity[i].z, p.radius[i],
                               p.mass[i], double(p.id[i]), double(p.material[i])});
  if (!link)
    all = std::move(mine);
  else if (to == GatherTo::every_rank)
    link->gather_in_rank_order(mine, all);
  else {
    std::vector<std::size_t> counts;
    link->gather_to_first(mine, all, counts);
  }
  Particles out;
  for (std::size_t k = 0; k + values <= all.size(); k += values) {
    const double* v = all.data() + k;
    out.add({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[9], density, int(v[12]));
    out.angular_velocity.back() = {v[6], v[7], v[8]};
    out.mass.back() = v[10];
    out.id.back() = std::int64_t(v[11]);
  }
  return out;
}

} // namespace wear::dem

namespace wear::dem {

Clumps gather_clumps(const Clumps& mine, const Particles& gathered, RankLink* link) {
  Clumps all;
  if (!link) {
    all.restore(mine);
  } else {
    std::vector<double> packed, message;
    std::vector<std::size_t> counts;
    Packer packer{packed};
    visit_bodies(const_cast<Clumps&>(mine), packer); // the packer only reads
    link->gather_to_first(packed, message, counts);
    std::size_t at = 0;
    for (const std::size_t n : counts) {
      ClumpsState part;
      Unpacker unpacker{message.data() + at, message.data() + at + n};
      visit_bodies(part, unpacker);
      append_bodies(all, part);
      at += n;
    }
    all.member_slot.assign(all.member_id.size(), 0);
  }
  if (!all.empty()) {
    std::vector<std::int64_t> slot_of_id;
    std::vector<std::int32_t> body_of_slot;
    all.index_members(gathered, slot_of_id, body_of_slot);
  }
  return all;
}

} // namespace wear::dem

// Export and import of the DEM state that decides how a run continues (checkpoints).
//
// What is kept: the real particles in the engine's current order (state, forces of the last
// step, properties, stable ids), the listed pairs with their tangential histories and the
// ghost owners they refer to, the wall-contact slots, the clock and the rebuild counter (it
// decides when the arrays are next sorted). What is not kept is rebuilt: ghosts, pair
// constants, wall candidates, reference positions.
//
// import_state() goes through rebuild(), which carries the histories over by stable id exactly
// as a rebuild inside the step loop does. A coupled run therefore passes every stage boundary
// through export + import, resumed or not, and a resumed run repeats the uninterrupted one
// bit for bit (same thread count). Forces are restored, not recomputed: computing them again
// would advance the tangential histories a second time.
//
// resume_state() continues at any step, where an extra rebuild would change the run (the
// wrap rotates histories there and back, the pair order and the threads' split follow the
// positions, the next rebuild's trigger moves). So the state also carries what the last
// rebuild decided (reference positions, wall candidates, the cost estimate behind the
// threads' split) and the open wear window as the threads hold it; nothing is rebuilt, and
// only pure functions of those (ghost slots from their owners, the split) are recomputed.
//
// Over ranks each rank exports and takes back its own part: its particles, lists and slots,
// and besides them the ghosts of the rank below as they sit in their slots (their ids name
// the pairs' histories) and the particles it sends up as ghosts, in order. A state continues
// only on the rank and rank count that wrote it (checked); the rebuild of import_state() is
// the ranks' common rebuild, with its migration and ghost exchange. On another rank count the
// parts are merged into one process's bed (rank_states.h), which import_state() takes over
// ranks as a whole bed (System::import_whole_state), its window added by add_wear_window().
#include "dem/engine/system.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace wear::dem {

SystemState System::export_state() const {
  if (!set_up_)
    throw std::logic_error("System::export_state() before setup()");
  const auto& p = particles;
  const std::size_t n = p.n_real;
  SystemState s;
  s.position.assign(p.position.begin(), p.position.begin() + n);
  s.velocity.assign(p.velocity.begin(), p.velocity.begin() + n);
  s.angular_velocity.assign(p.angular_velocity.begin(), p.angular_velocity.begin() + n);
  s.force.assign(p.force.begin(), p.force.begin() + n);
  s.torque.assign(p.torque.begin(), p.torque.begin() + n);
  s.radius.assign(p.radius.begin(), p.radius.begin() + n);
  s.mass.assign(p.mass.begin(), p.mass.begin() + n);
  s.inertia.assign(p.inertia.begin(), p.inertia.begin() + n);
  s.material.assign(p.material.begin(), p.material.begin() + n);
  s.id.assign(p.id.begin(), p.id.begin() + n);
  s.ghost_owner = ghost_owner_;
  s.pair_i = neighbors_.pair_i;
  s.pair_j = neighbors_.pair_j;
  s.pair_history = pair_history_;
  s.wall_particles = wall_particles_;
  s.slot_normal.reserve(slots_.size());
  s.slot_delta.reserve(slots_.size());
  s.slot_wall.reserve(slots_.size());
  for (const auto& sl : slots_) {
    s.slot_normal.push_back(sl.normal);
    s.slot_delta.push_back(sl.delta);
    s.slot_wall.push_back(sl.wall);
  }
  s.time = time_;
  s.n_steps = n_steps_;
  s.n_rebuilds = n_rebuilds_;
  s.reference_position = reference_position_;
  s.wall_candidate_offset = wall_candidate_offset_;
  s.wall_candidate = wall_candidate_;
  s.particle_cost = particle_cost_;
  s.wall_reference_time = wall_reference_time_;
  s.next_id = next_id_;
  for (const auto& thread : wear_acc_)
    for (const auto& wall : thread)
      s.wear_window.insert(s.wear_window.end(), wall.begin(), wall.end());
  s.n_threads = n_threads_;
  s.n_periodic_ghosts = n_periodic_ghosts_;
  s.n_image_ghosts = n_image_ghosts_;
  if (rank_link_) {
    s.rank = rank_link_->rank();
    s.n_ranks = rank_link_->n_ranks();
    for (std::size_t k = n + n_periodic_ghosts_; k < p.position.size(); ++k) {
      for (const Vec3& v : {p.position[k], p.velocity[k], p.angular_velocity[k]})
        s.rank_ghosts.insert(s.rank_ghosts.end(), {v.x, v.y, v.z});
      s.rank_ghosts.insert(s.rank_ghosts.end(), {p.radius[k], p.mass[k], p.inertia[k],
                                                 double(p.material[k]), double(p.id[k])});
    }
    s.rank_sent_up = rank_scratch_.sent_up;
  }
  s.clumps = clumps_;
  return s;
}

void System::check_importable(const SystemState& s, bool whole) const {
  const std::size_t n = s.position.size();
  const auto require = [](bool ok, const std::string& what) {
    if (!ok)
      throw std::invalid_argument("DEM state: " + what);
  };
  // Over ranks a rebuild since the export (a new wall mesh) may have passed particles between
  // the ranks: the part replaces whatever the rank holds.
  require(whole || rank_link_ || n == particles.n_real, "holds " + std::to_string(n) +
                                                            " particles, the system " +
                                                            std::to_string(particles.n_real));
  for (const auto size :
       {s.velocity.size(), s.angular_velocity.size(), s.force.size(), s.torque.size(),
        s.radius.size(), s.mass.size(), s.inertia.size(), s.material.size(), s.id.size()})
    require(size == n, "particle arrays of different lengths");
  require(s.pair_j.size() == s.pair_i.size() && s.pair_history.size() == s.pair_i.size(),
          "pair arrays of different lengths");
  require(s.slot_normal.size() == wall_slots * s.wall_particles.size() &&
              s.slot_delta.size() == s.slot_normal.size() &&
              s.slot_wall.size() == s.slot_normal.size(),
          "wall slots do not match the particles that own them");
  const std::size_t n_slots_total = n + s.ghost_owner.size();
  for (std::size_t k = 0; k < s.pair_i.size(); ++k)
    require(s.pair_i[k] < n && s.pair_j[k] < n_slots_total,
            "pair " + std::to_string(k) + " refers to a missing particle");
  const int rank = rank_link_ ? rank_link_->rank() : 0;
  const int n_ranks = rank_link_ ? rank_link_->n_ranks() : 1;
  require(whole ? s.n_ranks == 1 : s.rank == rank && s.n_ranks == n_ranks,
          "was written by rank " + std::to_string(s.rank) + " of " + std::to_string(s.n_ranks) +
              "; this is rank " + std::to_string(rank) + " of " + std::to_string(n_ranks) +
              " (a part continues on the rank count that wrote it; another rank count takes "
              "the parts merged, merge_rank_states)");
  const std::size_t n_periodic = s.n_ranks > 1 ? s.n_periodic_ghosts : s.ghost_owner.size();
  require(n_periodic <= s.ghost_owner.size() &&
              s.rank_ghosts.size() == 14 * (s.ghost_owner.size() - n_periodic),
          "the ghosts of the rank below do not match the ghost slots");
  for (std::size_t g = 0; g < s.ghost_owner.size(); ++g)
    require(g < n_periodic ? s.ghost_owner[g] < n : s.ghost_owner[g] == n + g,
            "a ghost refers to a missing particle");
  for (const auto q : s.rank_sent_up)
    require(q < n, "a ghost sent up refers to a missing particle");
  for (const auto q : s.wall_particles)
    require(q < n, "a wall slot refers to a missing particle");
  for (std::size_t i = 0; i < n; ++i)
    require(s.radius[i] > 0 && s.mass[i] > 0 && s.material[i] >= 0 &&
                s.material[i] < materials.n_materials(),
            "particle " + std::to_string(i) + " has an invalid radius, mass or material");
  try {
    first_free_id(s.id.data(), n);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("DEM state: ") + e.what());
  }
  for (const auto w : s.slot_wall)
    require(w >= -1 && w < n_walls(), "a wall slot refers to a missing wall");
  // Over ranks a part holds the bodies of its slab, however many: the bed has clumps or not.
  require(rank_link_ ? s.clumps.empty() || has_clumps_ : s.clumps.size() == clumps_.size(),
          "holds " + std::to_string(s.clumps.size()) + " clumps, the system " +
              std::to_string(clumps_.size()) + " (add_state_clumps before setup)");
  if (!s.clumps.empty()) { // a bed of spheres sorts no ids
    s.clumps.check();
    std::vector<std::int64_t> ids = s.id;
    std::sort(ids.begin(), ids.end());
    for (const auto id : s.clumps.member_id)
      require(std::binary_search(ids.begin(), ids.end(), id),
              "a clump's member " + std::to_string(id) + " is not among its particles");
  }
}

void System::check_resumable(const SystemState& s) const {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok)
      throw std::invalid_argument("DEM state: " + what);
  };
  const std::size_t n = s.position.size();
  require(s.n_threads == n_threads_, "was written with " + std::to_string(s.n_threads) +
                                         " threads; this run has " + std::to_string(n_threads_) +
                                         " (a stage continues bit for bit only with the same "
                                         "thread count: set DEM/Threads)");
  require(s.reference_position.size() == n && s.particle_cost.size() == n &&
              s.wall_candidate_offset.size() == n + 1,
          "continuation arrays do not match the particles");
  require(s.wall_candidate_offset[0] == 0 &&
              std::is_sorted(s.wall_candidate_offset.begin(), s.wall_candidate_offset.end()) &&
              s.wall_candidate_offset[n] == s.wall_candidate.size(),
          "wall-candidate offsets do not fit the candidates");
  // A revolution wall lists face 0 only.
  for (const auto c : s.wall_candidate)
    require(int(c >> 24) < n_walls() &&
                (c & 0xffffffu) < (wall_kind_[c >> 24] == WallKind::revolution
                                       ? 1
                                       : walls_[std::size_t(wall_local_[c >> 24])].n_faces()),
            "a wall candidate refers to a missing face");
  std::size_t window = 0;
  for (const auto& thread : wear_acc_)
    for (const auto& wall : thread)
      window += wall.size();
  require(s.wear_window.size() == window, "the wear window does not match the walls");
}

void System::take_particles(const SystemState& s) {
  auto& p = particles;
  p.resize_ghosts(0);
  p.position = s.position;
  p.velocity = s.velocity;
  p.angular_velocity = s.angular_velocity;
  p.force = s.force;
  p.torque = s.torque;
  p.radius = s.radius;
  p.mass = s.mass;
  p.inertia = s.inertia;
  p.material = s.material;
  p.id = s.id;
  p.n_real = s.position.size();
  next_id_ = std::max(s.next_id, first_free_id(s.id.data(), s.id.size()));
  ghost_owner_ = s.ghost_owner;
  n_periodic_ghosts_ = n_image_ghosts_ = ghost_owner_.size();
  if (rank_link_ && s.n_ranks > 1) {
    n_periodic_ghosts_ = std::size_t(s.n_periodic_ghosts);
    n_image_ghosts_ = std::size_t(s.n_image_ghosts);
    rank_scratch_.sent_up = s.rank_sent_up;
  }
  neighbors_.pair_i = s.pair_i;
  neighbors_.pair_j = s.pair_j;
  pair_history_ = s.pair_history;
  wall_particles_ = s.wall_particles;
  slots_.resize(s.slot_normal.size());
  for (std::size_t k = 0; k < slots_.size(); ++k)
    slots_[k] = {s.slot_normal[k], s.slot_delta[k], s.slot_wall[k]};
  time_ = s.time;
  n_steps_ = s.n_steps;
  n_rebuilds_ = s.n_rebuilds;
  if (has_clumps_) { // the bodies in the state's order, their members in the particles'
    clumps_.restore(s.clumps);
    clumps_.index_members(particles, rebuild_scratch_.clump_slot_of_id, body_of_slot_);
  }
}

void System::import_state(const SystemState& s) {
  if (!set_up_)
    throw std::logic_error("System::import_state() before setup()");
  if (rank_link_ && s.n_ranks == 1) {
    import_whole_state(s);
    return;
  }
  check_importable(s);
  take_particles(s);
  particles.resize_ghosts(s.ghost_owner.size());
  if (rank_link_) // the histories with them are keyed by their ids
    place_rank_ghosts(s.rank_ghosts);
  reset_wear_integrals();
  move_walls(time_);
  rebuild();
}

void System::add_wear_window(const SystemState& s) {
  std::size_t length = 0; // one thread's accumulators
  for (const auto& wall : wear_acc_.front())
    length += wall.size();
  if (s.n_threads <= 0 || s.wear_window.size() != length * std::size_t(s.n_threads))
    throw std::invalid_argument("DEM state: its wear window holds " +
                                std::to_string(s.wear_window.size()) + " values for " +
                                std::to_string(s.n_threads) + " thread(s); the walls need " +
                                std::to_string(length) + " per thread");
  const bool whole = rank_link_ && s.n_ranks == 1;
  if (whole && rank_link_->rank() != 0)
    return;
  for (std::size_t at = 0; at < s.wear_window.size();) // thread after thread
    for (auto& wall : wear_acc_.front())
      for (auto& x : wall)
        x += s.wear_window[at++];
}

void System::resume_state(const SystemState& s) {
  if (!set_up_)
    throw std::logic_error("System::resume_state() before setup()");
  check_importable(s);
  check_resumable(s);
  take_particles(s);
  fill_ghost_slots();
  if (rank_link_)
    place_rank_ghosts(s.rank_ghosts);
  wall_candidate_offset_ = s.wall_candidate_offset;
  wall_candidate_ = s.wall_candidate;
  particle_cost_ = s.particle_cost;
  split_ownership();
  pack_particles();
  reference_position_ = s.reference_position;
  move_walls(s.wall_reference_time);
  for (auto& w : walls_)
    w.mark_reference();
  wall_reference_time_ = s.wall_reference_time;
  move_walls(time_);
  std::size_t at = 0;
  for (auto& thread : wear_acc_)
    for (auto& wall : thread) {
      std::copy_n(s.wear_window.begin() + std::ptrdiff_t(at), wall.size(), wall.begin());
      at += wall.size();
    }
}

} // namespace wear::dem

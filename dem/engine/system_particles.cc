// Particles that enter and leave a running System (inlets and outlets of a scene).
//
// Changes happen between steps, inside a list rebuild: the old lists' pair histories and
// wall slots are first keyed by the particles' stable ids, then particles are removed (the
// real arrays compacted in order) and appended (new ids from next_id_, never reused), then
// the new lists are built and take the histories of the pairs and wall contacts that stay.
// An inserted particle starts with gravity as its force (its first half-kick), a removed
// one leaves its last contact forces on its partners for their closing half-kick: the same
// as a contact that opens or closes within a step.
#include "dem/engine/reused_buffer.h"
#include "dem/engine/system.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wear::dem {

std::int64_t first_free_id(const std::int64_t* id, std::size_t n) {
  std::int64_t bound = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Pair keys hold two ids in 32 bits each.
    if (id[i] < 0 || id[i] >= (std::int64_t(1) << 32) - 1)
      throw std::invalid_argument("DEM: particle id " + std::to_string(id[i]) +
                                  " lies outside 0 .. 2^32 - 2");
    bound = std::max(bound, id[i] + 1);
  }
  std::vector<char> seen(std::size_t(bound), 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (seen[std::size_t(id[i])])
      throw std::invalid_argument("DEM: particle id " + std::to_string(id[i]) + " is given twice");
    seen[std::size_t(id[i])] = 1;
  }
  return bound;
}

void System::insert_particles(const std::vector<NewParticle>& batch) {
  if (!set_up_)
    throw std::logic_error("System::insert_particles() before setup(): add them to particles");
  for (std::size_t k = 0; k < batch.size(); ++k) {
    const NewParticle& q = batch[k];
    const std::string what = "DEM: inserted particle " + std::to_string(k) + " of the batch";
    if (q.shape) {
      const ClumpShape& c = *q.shape;
      if (c.members.empty() || !(c.volume > 0))
        throw std::invalid_argument(what + ": clump shape '" + c.name + "' has no members");
      const double scale = 2 * q.radius / c.equivalent_diameter();
      double r = 0, overhang = 0;
      for (const ClumpMember& m : c.members) {
        r = std::max(r, m.radius * scale);
        overhang = std::max(overhang, meshes::norm(m.centre) * scale);
      }
      if (r > r_max_ || overhang > member_overhang_)
        throw std::invalid_argument(what + " is a clump whose members (largest radius " +
                                    std::to_string(r) + " m, reaching " + std::to_string(overhang) +
                                    " m from its centre) exceed the reach "
                                    "fixed at setup (radius " +
                                    std::to_string(r_max_) + " m, overhang " +
                                    std::to_string(member_overhang_) +
                                    " m: DemSettings::max_radius and max_overhang)");
    }
    if (!(q.radius > 0) || !std::isfinite(q.radius))
      throw std::invalid_argument(what + " has a non-positive radius");
    if (!(q.density > 0) || !std::isfinite(q.density))
      throw std::invalid_argument(what + " has a non-positive density");
    if (q.material < 0 || q.material >= materials.n_materials())
      throw std::invalid_argument(what + " refers to an unknown material");
    if (!q.shape && q.radius > r_max_)
      throw std::invalid_argument(what + " is larger (r = " + std::to_string(q.radius) +
                                  " m) than the largest particle at setup, which fixed the "
                                  "list reach (r = " +
                                  std::to_string(r_max_) + " m)");
  }
  if (batch.empty())
    return;
  const ParticleChanges changes{&batch, nullptr, nullptr};
  rebuild(false, &changes);
}

std::vector<RemovedParticle>
System::remove_particles(const std::function<bool(const Vec3&, double)>& remove) {
  if (!set_up_)
    throw std::logic_error("System::remove_particles() before setup()");
  std::vector<RemovedParticle> removed;
  double any = 0;
  for (std::size_t i = 0; i < particles.n_real && any == 0; ++i)
    if (clumps_.empty() || body_of_slot_[i] < 0)
      any = remove(particles.position[i], particles.radius[i]) ? 1 : 0;
  for (std::size_t b = 0; b < clumps_.size() && any == 0; ++b)
    any = remove(clumps_.position[b], body_reach(b)) ? 1 : 0;
  if (rank_link_) // a rebuild is every rank's together
    rank_link_->max_over_ranks(&any, 1);
  if (any == 0)
    return removed;
  const ParticleChanges changes{nullptr, &remove, &removed};
  rebuild(false, &changes);
  return removed;
}

void System::move_particle(std::size_t to, std::size_t from) {
  if (to == from)
    return;
  auto& p = particles;
  p.position[to] = p.position[from];
  p.velocity[to] = p.velocity[from];
  p.angular_velocity[to] = p.angular_velocity[from];
  p.force[to] = p.force[from];
  p.torque[to] = p.torque[from];
  p.radius[to] = p.radius[from];
  p.mass[to] = p.mass[from];
  p.inertia[to] = p.inertia[from];
  p.material[to] = p.material[from];
  p.id[to] = p.id[from];
}

void System::apply_particle_changes(const ParticleChanges& changes) {
  auto& p = particles;
  std::size_t n = p.n_real;
  if (changes.remove) {
    // A body leaves whole, by its centre and reach, booked once (its first member's id, its
    // centre, velocity and mass); its members leave with it.
    const bool clumps = !clumps_.empty();
    std::vector<std::uint8_t>& body_kept = rebuild_scratch_.body_kept;
    if (clumps) {
      clumps_.index_members(p, rebuild_scratch_.clump_slot_of_id, body_of_slot_);
      resize_reusing(body_kept, clumps_.size());
      for (std::size_t b = 0; b < clumps_.size(); ++b) {
        body_kept[b] = !(*changes.remove)(clumps_.position[b], body_reach(b));
        if (!body_kept[b] && changes.removed)
          changes.removed->push_back({clumps_.member_id[clumps_.member_begin[b]],
                                      clumps_.position[b], clumps_.velocity[b], clumps_.mass[b]});
      }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::int32_t body = clumps ? body_of_slot_[i] : -1;
      if (body >= 0 ? !body_kept[std::size_t(body)]
                    : (*changes.remove)(p.position[i], p.radius[i])) {
        if (body < 0 && changes.removed)
          changes.removed->push_back({p.id[i], p.position[i], p.velocity[i], p.mass[i]});
        continue;
      }
      move_particle(kept++, i);
    }
    n = kept;
    if (clumps)
      clumps_.keep_bodies(body_kept);
    if (n == 0 && !rank_link_) // over ranks, another may still hold particles
      throw std::runtime_error(
          "DEM: the outlets removed every particle at t = " + std::to_string(time_) + " s");
  }
  p.n_real = n;
  p.resize_ghosts(0); // make_ghosts() sizes the ghost region anew
  if (changes.insert)
    for (const NewParticle& q : *changes.insert) {
      // Over ranks every rank is given the whole batch and keeps those in its slab (a clump by
      // its centre); the ids are counted on all of them alike.
      const std::size_t n_ids = q.shape ? q.shape->members.size() : 1;
      has_clumps_ = has_clumps_ || q.shape; // on every rank alike
      if (rank_link_ && slab_cuts_.owner(q.position) != rank_link_->rank()) {
        next_id_ += std::int64_t(n_ids);
        continue;
      }
      // The last id it takes must stay below 2^32 - 1 (pair keys hold two ids in 32 bits).
      if (next_id_ + std::int64_t(n_ids) - 1 >= (std::int64_t(1) << 32) - 1)
        throw std::runtime_error("DEM: particle ids are exhausted (2^32 - 1 inserted)");
      if (q.shape) {
        place_clump(q.shape->scaled(2 * q.radius / q.shape->equivalent_diameter()), q.density,
                    q.material, q.position, normalized(q.orientation), q.velocity,
                    q.angular_velocity, true);
        continue;
      }
      p.add(q.position, q.velocity, q.radius, q.density, q.material);
      p.angular_velocity.back() = q.angular_velocity;
      p.force.back() = settings.gravity * p.mass.back();
      p.id.back() = next_id_++;
    }
  if (!clumps_.empty()) // the rebuild's steps find the members by slot
    clumps_.index_members(p, rebuild_scratch_.clump_slot_of_id, body_of_slot_);
}

} // namespace wear::dem

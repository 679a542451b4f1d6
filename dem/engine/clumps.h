#pragma once
// Rigid clumps in the engine: bodies whose members are particles of the System. The members
// take part in every contact as spheres do (pairs, walls, wear integrals); the bodies carry the
// motion: velocity Verlet for the centre of mass, kicks of the angular momentum and the free
// rotation of rigid_body.h for the orientation. Structure of arrays, one entry per body; the
// members are found by their particles' stable ids, so the engine may reorder particles.
#include "dem/engine/particles.h"
#include "dem/engine/rigid_body.h"

#include <cstdint>
#include <vector>

namespace wear::dem {

/// The bodies as a run continues from them (SystemState): every array of Clumps but the
/// members' slots, which follow from the particles' ids.
struct ClumpsState {
  // Per body.
  std::vector<Vec3> position;          ///< [m] centre of mass
  std::vector<Vec3> velocity;          ///< [m/s]
  std::vector<Quaternion> orientation; ///< body frame -> space frame
  std::vector<Vec3> angular_momentum;  ///< [kg m^2/s] space frame
  std::vector<Vec3> force;             ///< [N] of the last evaluation, gravity included
  std::vector<Vec3> torque;            ///< [N m] about the centre of mass
  std::vector<double> mass;            ///< [kg]
  std::vector<Vec3> moments;           ///< [kg m^2] principal moments (body axes)
  /// Members of body b: [member_begin[b], member_begin[b + 1]) of the member arrays.
  std::vector<std::uint32_t> member_begin{0};
  // Per member.
  std::vector<std::int64_t> member_id; ///< the member particle's stable id
  std::vector<Vec3> member_offset;     ///< [m] its centre in the body frame

  std::size_t size() const { return mass.size(); }
  bool empty() const { return mass.empty(); }
  /// Throws std::invalid_argument ("DEM state: clumps ...") when the arrays do not fit
  /// together: lengths, member ranges, a non-positive mass or moment, a zero orientation.
  void check() const;
};

struct Clumps : ClumpsState {
  /// The member's particle slot now (index_members after every reordering).
  std::vector<std::uint32_t> member_slot;

private:
  /// order_by_members' buffers: the new order and one array of each type, swapped in.
  struct Scratch {
    std::vector<std::uint32_t> order, begin, slot;
    std::vector<std::int64_t> id;
    std::vector<Vec3> vec3, offset;
    std::vector<Quaternion> quaternion;
    std::vector<double> real;
  };
  Scratch scratch_;

public:
  /// Takes the bodies of `s` (checked) in its order; the members' slots are to be indexed.
  void restore(const ClumpsState& s);

  /// Appends a body; its members' ids and body-frame offsets follow in member order.
  void add_body(const Vec3& x, const Vec3& v, const Quaternion& q, const Vec3& L, double m,
                const Vec3& principal_moments, const std::vector<std::int64_t>& ids,
                const std::vector<Vec3>& offsets);

  /// Keeps the bodies b with keep[b] != 0 in their order, their members with them (the
  /// members' slots are to be indexed again); in place, allocating nothing.
  void keep_bodies(const std::vector<std::uint8_t>& keep);

  /// member_slot from the particles' ids, and per slot (real particles) the body it belongs
  /// to, -1 for a free sphere; `slot_of_id` is a buffer (kept by the caller, so that a rebuild
  /// in the step loop allocates nothing). Throws std::logic_error when a member's particle is
  /// missing.
  void index_members(const Particles& p, std::vector<std::int64_t>& slot_of_id,
                     std::vector<std::int32_t>& body_of_slot);

  /// Reorders the bodies by the slot of their first member (after index_members), so that the
  /// bodies' pass walks the particle arrays in their order instead of at random, and renumbers
  /// `body_of_slot` (index_members' per-slot bodies) to match. Its buffers are kept (a rebuild
  /// in the step loop allocates nothing once they have grown).
  void order_by_members(std::vector<std::int32_t>& body_of_slot);

  /// [rad/s] The angular velocity of body b in the space frame.
  Vec3 angular_velocity(std::size_t b) const {
    return dem::angular_velocity(orientation[b], moments[b], angular_momentum[b]);
  }

  /// Places the members of body b where its pose puts them, with the velocity and spin of the
  /// rigid motion, and returns nothing; used after the drift and at setup.
  void place_members(std::size_t b, Particles& p) const;

  /// Adds the forces and torques on the members of body b (contacts only: a member's own
  /// force starts at zero) to the body's: F_b += sum F_i, T_b += sum (x_i - x_b) x F_i + T_i.
  void gather_forces(std::size_t b, const Particles& p);
};

} // namespace wear::dem

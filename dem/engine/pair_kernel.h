#pragma once
// The particle-pair contact kernel: forces and torques of one block of listed pairs.
#include "dem/engine/material.h"
#include "meshes/vec3.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wear::dem {

using meshes::Vec3;

constexpr int pair_block_size = 256;

/// Scratch of the kernel (one per thread): the touching pairs of a block, field by field, so
/// that the contact law runs over them in SIMD lanes.
struct alignas(64) PairBlock {
  static constexpr int n = pair_block_size;
  std::uint32_t pair[n];                                 ///< listed pair, from the block start
  double dx[n], dy[n], dz[n];                            ///< [m] x_i - x_j
  double dist2[n];                                       ///< [m^2] |x_i - x_j|^2
  double hx[n], hy[n], hz[n];                            ///< [m] updated tangential history
  double fx[n], fy[n], fz[n];                            ///< [N] on i
  double tix[n], tiy[n], tiz[n], tjx[n], tjy[n], tjz[n]; ///< [N m] on i and on j
  double redo[n]; ///< the history's rotation needs its exact scale (contact_law.h)
};

/// Position and radius of one particle slot in one 32-byte record: the distance test of a
/// listed pair reads one cache line per partner.
struct alignas(32) PackedPosition {
  double x, y, z; ///< [m]
  double r;       ///< [m]
};

/// Velocity, spin and mass of one particle slot in one 64-byte record, written where the
/// half-step velocities are: the law's gathers of a partner read one cache line instead of
/// three arrays.
struct alignas(64) PackedMotion {
  double vx, vy, vz; ///< [m/s]
  double mass;       ///< [kg]
  double wx, wy, wz; ///< [rad/s]
  double unused;
};

/// Forces of one thread's contacts on particles that another thread owns, kept aside and
/// added after the evaluation in thread order (the threads never write the same particle).
/// Sized at each rebuild to the thread's listed pairs with such a partner.
struct ForeignForces {
  std::vector<std::uint32_t> target; ///< real particle each entry goes to
  std::vector<Vec3> force, torque;   ///< [N], [N m] on it
  std::size_t n = 0;                 ///< entries of the current evaluation
};

/// What the kernel reads and writes, shared by all blocks of one thread's evaluation.
struct PairKernelData {
  const PackedPosition* position; ///< [m] real and ghost slots
  const PackedMotion* motion;     ///< real and ghost slots
  const int* material;            ///< material id
  const std::uint32_t *pair_i, *pair_j;
  const ContactParameters* contact; ///< table indexed by material_i x n_materials + material_j
  int n_materials;
  /// The one pair type when every slot has the same material (the common bed of one
  /// gravel): the law then takes its constants from registers instead of a gather per lane.
  const ContactParameters* uniform;
  Vec3* history;                    ///< [m] per listed pair, updated
  std::uint8_t* touching;           ///< per listed pair: in contact at the last evaluation
  const std::uint32_t* ghost_owner; ///< real particle behind ghost slot j - n_real
  std::size_t n_real;
  /// Ghost slots below this are periodic images (their forces go back rotated by +angle), the
  /// others ghosts of the rank below on the same side of the seam.
  std::size_t rotated_end;
  std::uint32_t own_begin, own_end; ///< the particles this thread owns
  ForeignForces* foreign;           ///< where forces on the other particles go
  double cos_angle, sin_angle;      ///< [-] of the periodic sector angle (ghost forces go back)
  double dt;                        ///< [s]
};

/// Pairs [k0, k0 + n_listed): updates their histories and adds their forces and torques into
/// `force` and `torque` (indexed by particle; a ghost's go to its owner, rotated by +angle), or
/// into d.foreign for a particle outside [own_begin, own_end). Returns the number of pairs in
/// contact. Built for several instruction sets, chosen at load time for the CPU; the same CPU
/// and thread count give bitwise identical results.
int pair_block_forces(const PairKernelData& d, std::size_t k0, int n_listed, PairBlock& bl,
                      Vec3* force, Vec3* torque);

} // namespace wear::dem

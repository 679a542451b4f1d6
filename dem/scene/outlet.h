#pragma once
// Particle sinks of a scene: boxes that take out the particles reaching them and book their
// mass (inlet.h: the source).
#include "dem/engine/system.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wear::dem {

/// An axis-aligned box that removes the particles whose centres enter it.
struct Outlet {
  std::string name;
  Vec3 min, max;               ///< [m]
  double removed_mass = 0;     ///< [kg] so far
  std::uint64_t n_removed = 0; ///< [-] so far
  bool contains(const Vec3& x) const {
    return x.x >= min.x && x.y >= min.y && x.z >= min.z && x.x <= max.x && x.y <= max.y &&
           x.z <= max.z;
  }
};

/// Removes from `system` the particles in any of the outlets and books each to the first
/// outlet that holds it. Returns the count removed. Over ranks (the system's rank link; every
/// rank calls it together) each rank removes its own and the outlets' counts and masses are
/// the sums over the ranks, the same on every rank.
std::size_t apply_outlets(System& system, std::vector<Outlet>& outlets);

} // namespace wear::dem

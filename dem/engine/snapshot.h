#pragma once
// Particle snapshots for ParaView.
#include "dem/engine/particles.h"

#include <string>

namespace wear::dem {

/// Writes the real particles as a .vtu point cloud with radius, velocity, angular velocity
/// and id (atomically).
void write_particles_vtu(const Particles& p, const std::string& path);

} // namespace wear::dem

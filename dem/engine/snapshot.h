#pragma once
// Particle snapshots for ParaView.
#include "dem/engine/clumps.h"
#include "dem/engine/particles.h"

#include <string>

namespace wear::dem {

/// Writes the real particles as a .vtu point cloud with radius, velocity, angular velocity
/// and id (atomically). With `clumps` (their members among p, indexed), each point also
/// carries its body ("body": its index, -1 for a free sphere), the body's orientation (a
/// quaternion w, x, y, z) and its centre of mass, so that ParaView can colour or glyph by body.
void write_particles_vtu(const Particles& p, const std::string& path,
                         const Clumps* clumps = nullptr);

} // namespace wear::dem

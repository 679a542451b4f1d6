#pragma once
// The particle shapes a case may name: a sphere, a clump template of the library (elongated,
// flat and angular crushed-stone shapes of 2 to 8 spheres) or a template file, each a
// ClumpTemplate whose size the PSD sets (by the equivalent-volume diameter).
#include "dem/engine/clump_shape.h"

#include <optional>
#include <string>
#include <vector>

namespace wear::dem {

/// A named shape of the library: its members at unit scale and what it stands for.
struct ParticleShapeEntry {
  std::string name;
  /// What it stands for and its aspect ratios (Zingg: I/L elongation, S/I flatness, of the
  /// extents along the body axes L >= I >= S).
  std::string description;
  std::vector<ClumpMember> members;
};

/// The library, sphere first.
const std::vector<ParticleShapeEntry>& particle_shapes();

/// The template of a library shape; throws std::invalid_argument naming `parameter`, the
/// name and the shapes there are.
ClumpTemplate named_clump_template(const std::string& name, const std::string& parameter);

/// Reads a template file: one member per line, "x y z r" (any length unit; the PSD scales
/// it), '#' starts a comment. Throws std::runtime_error naming the file and the line.
ClumpTemplate read_clump_template(const std::string& path);

/// The shape a case's `parameter` (DEM/Particle shape) names: none for "sphere" (the engine's
/// spheres), the library's shape of that name, or the template file at a path ending in .txt,
/// its mass properties integrated (clump_shape). Throws std::invalid_argument naming
/// `parameter` for an unknown name or a file that does not read.
std::optional<ClumpShape> particle_shape(const std::string& value, const std::string& parameter);

/// [m] The extents of a shape along its body axes, largest first (L, I, S).
Vec3 body_extents(const ClumpShape& s);

} // namespace wear::dem

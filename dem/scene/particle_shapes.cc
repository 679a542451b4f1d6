// The library of particle shapes and the template file.
//
// Crushed stone and gravel are described by their extents along three axes, L >= I >= S
// (longest, intermediate, shortest), and the Zingg ratios I/L (elongation) and S/I (flatness):
// a sphere is 1 : 1, a typical crushed aggregate about 0.7 : 0.7, an "elongated" particle
// has I/L below 2/3 and a "flat" one S/I below 2/3. The library's clumps span that range with
// 2 to 8 members; each entry's description states its ratios, and the shape test measures them
// on the body (body_extents of the integrated union), so the description and the members
// cannot part.
#include "dem/scene/particle_shapes.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

const std::vector<ParticleShapeEntry>& particle_shapes() {
  static const std::vector<ParticleShapeEntry> entries{
      {"sphere", "one sphere, I/L = 1, S/I = 1", {{{0, 0, 0}, 1}}},
      {"elongated 2",
       "two equal spheres overlapping by 40 % of their diameter: a rounded elongated grain, "
       "I/L = 0.63, S/I = 1",
       {{{-0.6, 0, 0}, 1}, {{0.6, 0, 0}, 1}}},
      {"elongated 3",
       "three spheres in a row, the middle one largest: an elongated rod-like grain, "
       "I/L = 0.51, S/I = 1",
       {{{-1.1, 0, 0}, 0.85}, {{0, 0, 0}, 1}, {{1.1, 0, 0}, 0.85}}},
      {"flat 4",
       "four equal spheres in a plane: a flat, blade-like grain, I/L = 0.91, S/I = 0.69",
       {{{-0.6, -0.45, 0}, 1}, {{0.6, -0.45, 0}, 1}, {{-0.6, 0.45, 0}, 1}, {{0.6, 0.45, 0}, 1}}},
      {"crushed stone 4",
       "four unequal spheres in an irregular tetrahedron: a compact angular grain, "
       "I/L = 0.80, S/I = 0.85",
       {{{0.7, 0, 0}, 1}, {{-0.6, 0.4, 0.1}, 0.9}, {{-0.3, -0.5, 0}, 0.85}, {{0, 0.1, 0.45}, 0.8}}},
      {"crushed stone 8",
       "eight spheres at the corners of a box, radii 0.6 to 0.75 of the unit: a rounded "
       "angular block of crushed stone, I/L = 0.82, S/I = 0.79",
       {{{-0.9, -0.6, -0.35}, 0.7},
        {{0.9, -0.6, -0.35}, 0.75},
        {{-0.9, 0.6, -0.35}, 0.65},
        {{0.9, 0.6, -0.35}, 0.7},
        {{-0.9, -0.6, 0.35}, 0.6},
        {{0.9, -0.6, 0.35}, 0.7},
        {{-0.9, 0.6, 0.35}, 0.75},
        {{0.9, 0.6, 0.35}, 0.65}}}};
  return entries;
}

ClumpTemplate named_clump_template(const std::string& name, const std::string& parameter) {
  std::string names;
  for (const auto& e : particle_shapes()) {
    if (e.name == name)
      return {e.name, e.members};
    names += (names.empty() ? "" : ", ") + e.name;
  }
  throw std::invalid_argument(parameter + " = '" + name + "' is not a shape of the library (" +
                              names + ") nor a template file (a path ending in .txt)");
}

ClumpTemplate read_clump_template(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("clump template file '" + path + "' cannot be opened");
  ClumpTemplate t;
  t.name = path;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    line = line.substr(0, line.find('#'));
    std::istringstream s(line);
    ClumpMember m;
    if (!(s >> std::ws) || s.eof())
      continue;
    std::string extra;
    if (!(s >> m.centre.x >> m.centre.y >> m.centre.z >> m.radius) || (s >> extra))
      throw std::runtime_error("clump template file '" + path + "', line " + std::to_string(n) +
                               ": expected four numbers, x y z r, not '" + line + "'");
    if (!(m.radius > 0))
      throw std::runtime_error("clump template file '" + path + "', line " + std::to_string(n) +
                               ": the radius must be positive, not " + std::to_string(m.radius));
    t.members.push_back(m);
  }
  if (t.members.empty())
    throw std::runtime_error("clump template file '" + path + "' holds no member sphere");
  return t;
}

std::optional<ClumpShape> particle_shape(const std::string& value, const std::string& parameter) {
  if (value == "sphere")
    return std::nullopt;
  const bool file = value.size() > 4 && value.compare(value.size() - 4, 4, ".txt") == 0;
  if (!file)
    return clump_shape(named_clump_template(value, parameter));
  try {
    return clump_shape(read_clump_template(value));
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(parameter + ": " + e.what());
  }
}

Vec3 body_extents(const ClumpShape& s) {
  double e[3];
  for (int k = 0; k < 3; ++k) {
    double lo = 1e300, hi = -1e300;
    for (const auto& m : s.members) {
      lo = std::min(lo, m.centre[k] - m.radius);
      hi = std::max(hi, m.centre[k] + m.radius);
    }
    e[k] = hi - lo;
  }
  std::sort(e, e + 3, [](double a, double b) { return a > b; });
  return {e[0], e[1], e[2]};
}

} // namespace wear::dem

// The angle of repose of a bed of clumps against a bed of spheres of the same volumes and
// friction, without rolling friction: the interlocking of non-spherical grains holds a
// steeper slope (spheres without rolling resistance roll down slopes of about 20 deg; angular
// gravel stands at 30 to 40 deg).
//
// A quasi-two-dimensional dam break: a column of particles settles in a channel of 5
// diameters' width against its back wall, held by a gate 10 diameters in front of it; the
// gate is taken away (the bed continues, at rest, in a system without it), the column
// slumps along the channel and comes to rest. The heap's free surface (the highest member
// top per diameter-wide bin along the channel) is fitted by a line where it stands between
// 20 % and 80 % of the heap's height: the angle of repose is that line's slope.
#include "dem/engine/clump_shape.h"
#include "dem/engine/filling.h"
#include "dem/engine/rank_states.h"
#include "dem/engine/system.h"
#include "dem/scene/particle_shapes.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace wear::dem;
using wear::meshes::SurfaceMesh;
using wear::meshes::Vec3;

namespace {

constexpr double d = 4e-3;      // [m] equivalent-volume diameter
constexpr double width = 5 * d; // [m] of the channel
constexpr double gate = 10 * d; // [m] the gate's distance from the back wall
constexpr double length = 0.24; // [m] of the channel's floor
constexpr double height = 0.12; // [m] of its walls
constexpr std::size_t n = 700;  // bodies

// The rectangle a b c d (counter-clockwise seen from the side it faces) as two triangles.
void add_rectangle(SurfaceMesh& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& e) {
  const auto first = std::uint32_t(m.vertices.size());
  m.vertices.insert(m.vertices.end(), {a, b, c, e});
  m.triangles.push_back({first, first + 1, first + 2});
  m.triangles.push_back({first, first + 2, first + 3});
  m.face_labels.resize(m.triangles.size(), wear::meshes::label::wall);
}

// The channel: floor, back wall x = 0, end wall x = length, side walls y = 0 and y = width,
// all facing inwards; with `with_gate`, the gate x = gate facing the back wall.
SurfaceMesh channel(bool with_gate) {
  SurfaceMesh m;
  add_rectangle(m, {0, 0, 0}, {length, 0, 0}, {length, width, 0}, {0, width, 0});
  add_rectangle(m, {0, 0, 0}, {0, width, 0}, {0, width, height}, {0, 0, height});
  add_rectangle(m, {length, 0, 0}, {length, 0, height}, {length, width, height},
                {length, width, 0});
  add_rectangle(m, {0, 0, 0}, {0, 0, height}, {length, 0, height}, {length, 0, 0});
  add_rectangle(m, {0, width, 0}, {length, width, 0}, {length, width, height}, {0, width, height});
  if (with_gate)
    add_rectangle(m, {gate, 0, 0}, {gate, 0, height}, {gate, width, height}, {gate, width, 0});
  return m;
}

// Runs until the mean speed is below 5 mm/s (at least 0.15 s, at most `max_time`).
void settle(System& s, double max_time) {
  const double t0 = s.time();
  for (;;) {
    s.run(std::uint64_t(0.02 / s.time_step()));
    double mean = 0;
    for (std::size_t i = 0; i < s.particles.n_real; ++i)
      mean += wear::meshes::norm(s.particles.velocity[i]);
    mean /= double(s.particles.n_real);
    if ((mean < 5e-3 && s.time() - t0 > 0.15) || s.time() - t0 > max_time)
      return;
  }
}

struct Heap {
  double angle_deg = 0; ///< [deg] of the fitted free surface
  double height = 0;    ///< [m] of the heap
  double runout = 0;    ///< [m] the farthest member from the back wall
};

// The dam break of `n` spheres (no shape) or clumps of `shape`, diameter d.
Heap dam_break(const std::optional<ClumpShape>& shape) {
  SizeDistribution psd;
  psd.diameters = {0.9 * d, 1.1 * d};
  psd.mass_fractions = {0.5, 0.5};
  System column;
  int g = testing::add_gravel(column, 0.5, 0.5, 0);
  column.add_wall(MeshWall(channel(true), g, {}, false, "channel"));
  double margin = 0.55 * d;
  if (shape) {
    double r_member = 0;
    for (const auto& m : shape->members)
      r_member = std::max(r_member, m.radius);
    margin = r_member * 1.1 * d / shape->equivalent_diameter();
  }
  const FillRegion region = box_region({0, 0, 0}, {gate, width, height}, margin);
  const std::size_t placed = shape
                                 ? insert_random_clumps(column, region, psd, *shape, n, 2650, g, 11)
                                 : insert_random(column.particles, region, psd, n, 2650, g, 11);
  REQUIRE(placed == n);
  column.set_n_threads(2);
  column.setup();
  settle(column, 1.0);
  const SystemState rest = column.export_state();

  System heap; // the same bed without the gate
  g = testing::add_gravel(heap, 0.5, 0.5, 0);
  heap.add_wall(MeshWall(channel(false), g, {}, false, "channel"));
  add_state_particles(heap.particles, rest, false, 2650);
  if (shape)
    heap.add_state_clumps(rest.clumps);
  heap.set_n_threads(2);
  heap.setup();
  settle(heap, 2.0);

  const auto& p = heap.particles;
  const int n_bins = int(length / d);
  std::vector<double> top(std::size_t(n_bins), 0.0);
  Heap h;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const int bin = std::clamp(int(p.position[i].x / d), 0, n_bins - 1);
    top[std::size_t(bin)] = std::max(top[std::size_t(bin)], p.position[i].z + p.radius[i]);
    h.runout = std::max(h.runout, p.position[i].x + p.radius[i]);
  }
  h.height = *std::max_element(top.begin(), top.end());
  // Least squares z = a + b x over the bins between 20 % and 80 % of the height.
  double sx = 0, sz = 0, sxx = 0, sxz = 0, m = 0;
  for (int b = 0; b < n_bins; ++b) {
    const double z = top[std::size_t(b)], x = (b + 0.5) * d;
    if (z < 0.2 * h.height || z > 0.8 * h.height)
      continue;
    sx += x;
    sz += z;
    sxx += x * x;
    sxz += x * z;
    ++m;
  }
  REQUIRE(m >= 4);
  const double slope = (m * sxz - sx * sz) / (m * sxx - sx * sx);
  h.angle_deg = std::atan(-slope) * 180 / wear::pi;
  return h;
}

} // namespace

TEST_CASE("a heap of clumps stands steeper than a heap of spheres (angle of repose)",
          "[dem][clump][repose]") {
  const Heap spheres = dam_break(std::nullopt);
  const Heap clumps = dam_break(clump_shape(named_clump_template("crushed stone 4", "test")));
  INFO("spheres: " << spheres.angle_deg << " deg, height " << spheres.height * 1e3 << " mm, runout "
                   << spheres.runout * 1e3 << " mm");
  INFO("clumps ('crushed stone 4'): " << clumps.angle_deg << " deg, height " << clumps.height * 1e3
                                      << " mm, runout " << clumps.runout * 1e3 << " mm");
  WARN("angle of repose: spheres " << spheres.angle_deg << " deg, clumps " << clumps.angle_deg
                                   << " deg");
  CHECK(spheres.angle_deg > 5);
  CHECK(clumps.angle_deg > spheres.angle_deg + 5);
  CHECK(clumps.runout < spheres.runout);
}

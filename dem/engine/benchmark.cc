// Benchmark workloads. The full-annulus lattice reproduces gen_meshes.py of the anchor
// exactly: sites ((i + 1/2) a, (j + 1/2) a, (k + 1/2) a) with r_in + 0.6 a < r < r_out - 0.6 a,
// and nz = round(45000 / sites per layer) layers, giving the anchor's 44,448 particles.
#include "dem/engine/benchmark.h"

#include "dem/engine/filling.h"
#include "meshes/constants.h"
#include "meshes/structured_grid.h"
#include "meshes/tester_walls.h"

#include <cmath>
#include <stdexcept>

namespace wear::dem {

namespace {
constexpr double d0 = 7.95e-3, ri = 0.29, ro = 0.50;

// Lattice sites of one layer inside the full annulus, as gen_meshes.py counts them.
int lattice_sites_per_layer(double a) {
  int layer = 0;
  const int m = int(ro / a) + 2;
  for (int i = -m; i < m; ++i)
    for (int j = -m; j < m; ++j) {
      const double r = std::hypot((i + 0.5) * a, (j + 0.5) * a);
      layer += (ri + 0.6 * a < r && r < ro - 0.6 * a);
    }
  return layer;
}

meshes::SurfaceMesh plate(double theta, double r0, double r1, double z0, double z1, int n) {
  // Vertical plate in the radial-vertical plane at angle theta (normal along the flow),
  // n x n quads split in two: 2 n^2 triangles.
  const double c = std::cos(theta), s = std::sin(theta);
  return meshes::structured_grid(
      n, n,
      [=](double u, double v) {
        const double r = r0 + (r1 - r0) * u;
        return Vec3{r * c, r * s, z0 + (z1 - z0) * v};
      },
      false, meshes::label::wall, meshes::Diagonals::uniform);
}

WallMotion rotating() {
  WallMotion m;
  m.angular_velocity = 0.5 * pi;
  return m;
}

meshes::TesterGeometry tester(double sector_angle_deg, double wall_height) {
  meshes::TesterGeometry t;
  t.inner_radius = ri;
  t.outer_radius = ro;
  t.consolidator = false;
  t.sector_angle_deg = sector_angle_deg;
  t.wall_height = wall_height;
  t.wall_mesh_size = 0.021; // the anchor's: 150 x 10 floor segments in the full annulus
  return t;
}

/// Floor (z = 0) and cylinders (0 <= z <= height) of the full annulus ri..ro as revolution
/// walls, the floor rotating and the cylinders too if `rotating_cylinders`.
void add_revolution_walls(System& s, int g, double height, bool rotating_cylinders) {
  const WallMotion cylinders = rotating_cylinders ? rotating() : WallMotion{};
  s.add_wall(RevolutionWall(RevolutionSurface::annulus(0, ri, ro), g, rotating(), false, "floor"));
  s.add_wall(
      RevolutionWall(RevolutionSurface::cylinder(ri, 0, height), g, cylinders, false, "inner"));
  s.add_wall(
      RevolutionWall(RevolutionSurface::cylinder(ro, 0, height), g, cylinders, false, "outer"));
}

/// The anchor's full annulus: about 45,000 particles on the lattice, layers to match.
void add_annulus(System& s, int g, bool mesh_walls) {
  const double a = 1.03 * d0;
  const int layer = lattice_sites_per_layer(a);
  const int nz = std::max(1, int(std::lround(45000.0 / layer)));
  if (mesh_walls) {
    const auto w = meshes::generate_tester_walls(tester(360, 0.12));
    s.add_wall(MeshWall(w.floor, g, rotating(), false, "floor"));
    s.add_wall(MeshWall(w.inner, g, {}, false, "inner"));
    s.add_wall(MeshWall(w.outer, g, {}, false, "outer"));
  } else {
    add_revolution_walls(s, g, 0.12, false);
  }
  FillRegion region{{-ro, -ro, 0}, {ro, ro, nz * a}, [=](const Vec3& x) {
                      const double r = std::hypot(x.x, x.y);
                      return ri + 0.6 * a < r && r < ro - 0.6 * a && x.z > 0 && x.z < nz * a;
                    }};
  insert_lattice(s.particles, region, a, d0, 2650, g, 1e-4, 15485863);
}

/// A periodic sector of about `target` particles in 14 layers, walls rotating with the bed;
/// `with_plate`: a fixed vertical plate (a mesh) across the flow in the middle of the sector.
void add_sector(System& s, int g, std::size_t target, bool with_plate, bool mesh_walls) {
  // 14 layers as the anchor's channels; angle from the lattice sites per layer and radian.
  const double a = 1.03 * d0;
  const int nz = 14;
  const double z_top = nz * a;
  const double per_rad = lattice_sites_per_layer(a) / (2 * pi);
  const double angle = std::min(2 * pi * 0.9, double(target) / (nz * per_rad));
  if (mesh_walls) {
    // Mesh walls reach a little past both cut planes: particles may sit up to half a skin
    // beyond a cut between list rebuilds. (The revolution walls are full circles.)
    const double margin = 0.02;
    const auto w = meshes::generate_tester_walls(tester(angle * 180 / pi, 0.2));
    const auto extend = [&](const meshes::SurfaceMesh& mesh) {
      return meshes::widen_sector(mesh, angle, margin);
    };
    s.add_wall(MeshWall(extend(w.floor), g, rotating(), false, "floor"));
    s.add_wall(MeshWall(extend(w.inner), g, rotating(), false, "inner"));
    s.add_wall(MeshWall(extend(w.outer), g, rotating(), false, "outer"));
  } else {
    add_revolution_walls(s, g, 0.2, true);
  }
  if (with_plate)
    s.add_wall(MeshWall(plate(angle / 2, 0.345, 0.445, 0.015, 0.115, 40), g, {}, false, "plate"));
  s.settings.periodic = {true, angle};
  FillRegion region{{-ro, -ro, 0}, {ro, ro, z_top}, [=](const Vec3& x) {
                      const double r = std::hypot(x.x, x.y);
                      double th = std::atan2(x.y, x.x);
                      if (th < 0)
                        th += 2 * pi;
                      const bool in_plate = with_plate && std::abs(th - angle / 2) * r < 0.6 * a;
                      return ri + 0.6 * a < r && r < ro - 0.6 * a && x.z > 0 && x.z < z_top &&
                             th * r > 0.5 * a && (angle - th) * r > 0.5 * a && !in_plate;
                    }};
  insert_lattice(s.particles, region, a, d0, 2650, g, 1e-4, 15485863);
}
/// The annulus of add_annulus with rigid clumps of four spheres instead of spheres: as many
/// member spheres (44,448 in 11,112 clumps), members of 7.95 mm mean diameter (the
/// irregular tetrahedron of the shape library's "crushed stone 4", scaled), inserted at random
/// orientations into the annulus up to 0.25 m and settled by the benchmark's settle steps.
void add_annulus_clumps(System& s, int g) {
  add_revolution_walls(s, g, 0.3, false);
  const ClumpTemplate t{
      "crushed stone 4",
      {{{0.7, 0, 0}, 1}, {{-0.6, 0.4, 0.1}, 0.9}, {{-0.3, -0.5, 0}, 0.85}, {{0, 0.1, 0.45}, 0.8}}};
  const double mean_radius = (1 + 0.9 + 0.85 + 0.8) / 4;
  const ClumpShape shape = clump_shape(t);
  SizeDistribution psd;
  psd.diameters = {d0 / (2 * mean_radius) * shape.equivalent_diameter()};
  psd.mass_fractions = {1};
  const double margin = 0.5 * d0 / mean_radius; // the largest member's radius
  FillRegion region{{-ro, -ro, 0}, {ro, ro, 0.25}, [=](const Vec3& x) {
                      const double r = std::hypot(x.x, x.y);
                      return ri + margin < r && r < ro - margin && x.z > margin && x.z < 0.25;
                    }};
  const std::size_t n = insert_random_clumps(s, region, psd, shape, 11112, 2650, g, 15485863);
  if (n != 11112)
    throw std::runtime_error("benchmark annulus-clumps: only " + std::to_string(n) +
                             " of 11112 clumps found room");
}
} // namespace

void build_benchmark(System& s, const BenchmarkOptions& o) {
  build_benchmark(s, o.workload, o.mesh_walls);
}

void build_benchmark(System& s, const std::string& workload, bool mesh_walls) {
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {0.5, 0.5, 0.1});
  s.settings.skin = 0.002;
  s.settings.time_step_fraction = 0.2;
  s.settings.domain = {{-0.52, -0.52, -0.01}, {0.52, 0.52, 1.0}};
  if (workload == "annulus") {
    add_annulus(s, g, mesh_walls);
    return;
  }
  if (workload == "annulus-clumps") {
    if (mesh_walls)
      throw std::invalid_argument("benchmark annulus-clumps: revolution walls only");
    add_annulus_clumps(s, g);
    return;
  }
  std::size_t target = 0;
  if (workload == "sector5k")
    target = 5000;
  else if (workload == "sector20k")
    target = 20000;
  else if (workload == "sector45k" || workload == "sample45k")
    target = 45000;
  else
    throw std::invalid_argument("unknown benchmark workload '" + workload +
                                "' (annulus, annulus-clumps, sector5k, sector20k, sector45k, "
                                "sample45k)");
  add_sector(s, g, target, workload == "sample45k", mesh_walls);
}

SlabDecomposition benchmark_slabs(const System& s, int n_ranks) {
  const double angle = s.settings.periodic.enabled ? s.settings.periodic.angle : 2 * pi;
  return SlabDecomposition::uniform_angular(angle, n_ranks, ri);
}

} // namespace wear::dem

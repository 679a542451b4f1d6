// Revolution walls in the System: the same contacts, forces and per-face wear as the walls
// triangulated where the triangulation is exact, the same settled bed, and bitwise
// continuation of an exported or resumed state.
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <random>
#include <vector>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::norm;
using wear::meshes::Vec3;

namespace {
/// The tester's walls over a 60-degree sector at 5 mm, a consolidator plate at 5 cm over
/// 25..35 degrees.
wear::meshes::TesterGeometry fine_tester() {
  wear::meshes::TesterGeometry t;
  t.sector_angle_deg = 60;
  t.wall_height = 0.1;
  t.wall_mesh_size = 5e-3;
  t.consolidator = true;
  t.consolidator_height = 0.05;
  t.consolidator_angle_deg = 30;
  t.consolidator_extent_deg = 10;
  return t;
}

/// Walls 0..3: floor (rotating, wearing), consolidator (fixed, wearing), inner and outer
/// cylinders (rotating); revolution walls with the triangulations as accounting meshes, or
/// the triangulations as mesh walls.
void add_walls(System& s, int g, const wear::meshes::TesterGeometry& t,
               const wear::meshes::TesterWalls& m, bool analytic) {
  WallMotion rot;
  rot.angular_velocity = 0.5 * pi;
  const double ri = t.inner_radius, ro = t.outer_radius, h = t.wall_height;
  const double e = t.consolidator_extent_deg * pi / 180;
  const double th0 = t.consolidator_angle_deg * pi / 180 - e / 2;
  if (analytic) {
    s.add_wall(
        RevolutionWall(RevolutionSurface::annulus(0, ri, ro), g, rot, true, "floor", &m.floor));
    s.add_wall(
        RevolutionWall(RevolutionSurface::annulus(t.consolidator_height, ri, ro, th0, th0 + e), g,
                       {}, true, "consolidator", &*m.consolidator));
    s.add_wall(RevolutionWall(RevolutionSurface::cylinder(ri, 0, h), g, rot, false, "inner"));
    s.add_wall(RevolutionWall(RevolutionSurface::cylinder(ro, 0, h), g, rot, false, "outer"));
  } else {
    s.add_wall(MeshWall(m.floor, g, rot, true, "floor"));
    s.add_wall(MeshWall(*m.consolidator, g, {}, true, "consolidator"));
    s.add_wall(MeshWall(m.inner, g, rot, false, "inner"));
    s.add_wall(MeshWall(m.outer, g, rot, false, "outer"));
  }
}

struct Placed {
  Vec3 x, v, w; ///< [m], [m/s], [rad/s]
};

/// Particles of radius r, each overlapping one wall by 0.2 to 1 % of r, at least 3 r apart,
/// with random velocities and spins: on the floor anywhere away from its curved rims; on the
/// plate from above and below and beyond its straight radial edges (normals within 70 degrees
/// of the plate); if `cylinders`, on the cylinders radially over mesh vertices (the inner
/// from the bed, the outer from outside), where the triangulated distance and normal are
/// exact.
std::vector<Placed> contact_configuration(const wear::meshes::TesterGeometry& t,
                                          const wear::meshes::TesterWalls& m, double r,
                                          bool cylinders) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> u(0, 1);
  const double ri = t.inner_radius, ro = t.outer_radius, hc = t.consolidator_height;
  const double e = t.consolidator_extent_deg * pi / 180;
  const double th0 = t.consolidator_angle_deg * pi / 180 - e / 2;
  std::vector<Placed> out;
  // At a contact point p with normal n (wall to centre): the centre p + n gap, a random
  // tangential velocity and an approach of up to 0.1 m/s (a separating contact can lose its
  // force to the damping's clamp).
  const auto place = [&](const Vec3& p, const Vec3& n) {
    const Vec3 x = p + n * (r * (1 - 0.002 - 0.008 * u(rng)));
    for (const auto& o : out)
      if (norm(o.x - x) < 3 * r)
        return;
    const Vec3 v{0.6 * u(rng) - 0.3, 0.6 * u(rng) - 0.3, 0.6 * u(rng) - 0.3};
    const Vec3 v_t = v - n * wear::meshes::dot(v, n);
    out.push_back(
        {x, v_t - n * (0.1 * u(rng)), Vec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5} * 40.0});
  };
  const auto radial = [](double th) { return Vec3{std::cos(th), std::sin(th), 0}; };
  for (int k = 0; k < 40; ++k) // floor
    place(radial(0.05 + 0.9 * u(rng)) * (ri + 0.03 + (ro - ri - 0.06) * u(rng)), {0, 0, 1});
  for (int k = 0; k < 12; ++k) // plate, above or below
    place(radial(th0 + e * (0.2 + 0.6 * u(rng))) * (ri + 0.03 + (ro - ri - 0.06) * u(rng)) +
              Vec3{0, 0, hc},
          {0, 0, k % 2 ? 1.0 : -1.0});
  for (int k = 0; k < 16; ++k) { // beyond a radial edge of the plate
    const double th = k % 2 ? th0 + e : th0, beta = 2.4 * u(rng) - 1.2;
    const Vec3 out_of_plane =
        k % 2 ? Vec3{-std::sin(th), std::cos(th), 0} : Vec3{std::sin(th), -std::cos(th), 0};
    const Vec3 n = out_of_plane * std::cos(beta) + Vec3{0, 0, std::sin(beta)};
    place(radial(th) * (ri + 0.03 + (ro - ri - 0.06) * u(rng)) + Vec3{0, 0, hc}, n);
  }
  if (!cylinders)
    return out;
  for (const auto* mesh : {&m.inner, &m.outer})
    for (const Vec3& v : mesh->vertices) {
      const double th = std::atan2(v.y, v.x), rv = std::hypot(v.x, v.y);
      const bool clear_of_plate = th < 0.3 || th > 0.75;
      if (v.z > 0.03 && v.z < 0.07 && th > 0.1 && th < 0.95 && clear_of_plate && u(rng) < 0.05)
        place(v, radial(th));
    }
  return out;
}

void build(System& s, bool analytic, const std::vector<Placed>& placed, double r) {
  const auto t = fine_tester();
  const auto m = wear::meshes::generate_tester_walls(t);
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  add_walls(s, g, t, m, analytic);
  for (const auto& p : placed) {
    s.particles.add(p.x, p.v, r, 2650, g);
    s.particles.angular_velocity.back() = p.w;
  }
  s.settings.domain = {{-0.6, -0.6, -0.1}, {0.6, 0.6, 0.3}};
  omp_set_num_threads(1);
  s.setup();
  omp_set_num_threads(omp_get_num_procs());
}

/// |a - b| <= tol |a|, with the values in the message.
bool close(const Vec3& a, const Vec3& b, double tol) {
  return norm(a - b) <= tol * norm(a);
}
} // namespace

TEST_CASE("revolution walls give the forces of the exactly triangulated walls", "[dem][walls]") {
  // At setup: one force evaluation, every particle in contact with one wall. The plane walls
  // (floor, plate) are exact when triangulated, also at the plate's straight radial edges;
  // the cylinders are exact radially over a mesh vertex on the convex side. Tolerance 1e-6
  // relative (the closest points differ by round-off only).
  const double r = 4e-3;
  const auto t = fine_tester();
  const auto placed = contact_configuration(t, wear::meshes::generate_tester_walls(t), r, true);
  System a, b;
  build(a, true, placed, r);
  build(b, false, placed, r);
  REQUIRE(placed.size() > 50);
  int n_in_contact = 0, n_force = 0, n_torque = 0;
  for (std::size_t i = 0; i < a.particles.n_real; ++i) {
    const Vec3 weight = a.settings.gravity * a.particles.mass[i];
    const Vec3 fa = a.particles.force[i] - weight, fb = b.particles.force[i] - weight;
    n_in_contact += norm(fa) > 0;
    n_force += !close(fa, fb, 1e-6);
    n_torque += !close(a.particles.torque[i], b.particles.torque[i], 1e-6);
  }
  CHECK(n_in_contact == int(placed.size()));
  CHECK(n_force == 0);
  CHECK(n_torque == 0);
  CHECK(a.energy().elastic == Approx(b.energy().elastic).epsilon(1e-6));
  CHECK(a.energy().elastic > 0);
}

TEST_CASE("wear of revolution walls goes to the accounting faces as on the triangulated walls",
          "[dem][walls][wear]") {
  // Floor and plate particles only (planes: the triangulation is exact everywhere they go),
  // 400 steps through their impacts, sliding on the turning floor and along the plate. The
  // per-face Archard integral, normal impulse and contact-steps agree within 1e-6 of the
  // largest face value; forces and positions stay within round-off of each other.
  const double r = 4e-3;
  const auto t = fine_tester();
  const auto placed = contact_configuration(t, wear::meshes::generate_tester_walls(t), r, false);
  System a, b;
  build(a, true, placed, r);
  build(b, false, placed, r);
  a.run(400);
  b.run(400);
  double max_dx = 0;
  for (std::size_t i = 0; i < a.particles.n_real; ++i)
    max_dx = std::max(max_dx, norm(a.particles.position[i] - b.particles.position[i]));
  CHECK(max_dx < 1e-12);
  for (const int w : {0, 1}) {
    const auto wa = a.wear_integrals(w), wb = b.wear_integrals(w);
    REQUIRE(wa.archard.size() == wb.archard.size());
    const double top = *std::max_element(wa.archard.begin(), wa.archard.end());
    const double top_fn = *std::max_element(wa.normal_impulse.begin(), wa.normal_impulse.end());
    int n_hit = 0, n_differ = 0;
    for (std::size_t f = 0; f < wa.archard.size(); ++f) {
      n_hit += wa.archard[f] > 0;
      n_differ += std::abs(wa.archard[f] - wb.archard[f]) > 1e-6 * top ||
                  std::abs(wa.normal_impulse[f] - wb.normal_impulse[f]) > 1e-6 * top_fn ||
                  std::abs(wa.contact_steps[f] - wb.contact_steps[f]) > 1e-6;
    }
    INFO("wall " << w << ": " << n_hit << " faces worn");
    CHECK(n_hit >= 10);
    CHECK(n_differ == 0);
    CHECK(wa.total_archard == Approx(wb.total_archard).epsilon(1e-6));
    CHECK(close(wa.total_impulse, wb.total_impulse, 1e-6));
  }
}

namespace {
/// A bed of 400 gravel particles of 8 mm (about 3.6 cm deep) settled for 0.5 s in a full
/// annulus 0.03 .. 0.05 m (a narrow channel between strongly curved cylinders), floor and
/// cylinders at rest: revolution walls (with accounting triangulations, for their impulses) or
/// their triangulations at 2.5 mm. Returns the mean force of the bed on the three walls over
/// the next 0.05 s [N], the bed's weight [N] and the largest speed at the end [m/s].
Vec3 settled_wall_load(bool analytic, double& weight, double& max_speed) {
  const double ri = 0.03, ro = 0.05;
  wear::meshes::TesterGeometry t;
  t.inner_radius = ri;
  t.outer_radius = ro;
  t.sector_angle_deg = 360;
  t.wall_height = 0.1;
  t.wall_mesh_size = 2.5e-3;
  t.consolidator = false;
  const auto m = wear::meshes::generate_tester_walls(t);
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  if (analytic) {
    s.add_wall(
        RevolutionWall(RevolutionSurface::annulus(0, ri, ro), g, {}, true, "floor", &m.floor));
    s.add_wall(
        RevolutionWall(RevolutionSurface::cylinder(ri, 0, 0.1), g, {}, true, "inner", &m.inner));
    s.add_wall(
        RevolutionWall(RevolutionSurface::cylinder(ro, 0, 0.1), g, {}, true, "outer", &m.outer));
  } else {
    s.add_wall(MeshWall(m.floor, g, {}, true, "floor"));
    s.add_wall(MeshWall(m.inner, g, {}, true, "inner"));
    s.add_wall(MeshWall(m.outer, g, {}, true, "outer"));
  }
  s.settings.domain = {{-0.1, -0.1, -0.01}, {0.1, 0.1, 0.2}};
  const SizeDistribution psd{{8e-3}, {1.0}, 1.0};
  const auto n = insert_random(s.particles, annular_sector_region(ri, ro, 2 * pi, 0, 0.1, 4.1e-3),
                               psd, 400, 2650, g, 17);
  REQUIRE(n == 400);
  omp_set_num_threads(2);
  s.setup();
  omp_set_num_threads(omp_get_num_procs());
  s.run(std::uint64_t(0.5 / s.time_step()));
  s.reset_wear_integrals();
  const std::uint64_t window = std::uint64_t(0.05 / s.time_step());
  s.run(window);
  Vec3 impulse;
  for (int w = 0; w < 3; ++w)
    impulse += s.wear_integrals(w).total_impulse;
  weight = 0;
  max_speed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    weight += s.particles.mass[i] * 9.81;
    max_speed = std::max(max_speed, norm(s.particles.velocity[i]));
  }
  return impulse / (double(window) * s.time_step());
}
} // namespace

TEST_CASE("a bed settles on revolution walls as on their fine triangulation", "[dem][walls]") {
  // The total force on floor and cylinders agrees within 1 % between the two, and carries the
  // bed's weight within 1 % (a settled bed: the rest is the residual motion). A full annulus:
  // in a periodic sector the walls also balance the net force across the cuts, which depends
  // on the packing each run happens to reach (1.3 % apart for another seed).
  double weight_a = 0, weight_b = 0, speed_a = 0, speed_b = 0;
  const Vec3 load_a = settled_wall_load(true, weight_a, speed_a);
  const Vec3 load_b = settled_wall_load(false, weight_b, speed_b);
  INFO("revolution walls: load (" << load_a.x << ", " << load_a.y << ", " << load_a.z
                                  << ") N, largest speed " << speed_a << " m/s");
  INFO("triangulated: load (" << load_b.x << ", " << load_b.y << ", " << load_b.z
                              << ") N, largest speed " << speed_b << " m/s; weight " << weight_a
                              << " N");
  CHECK(weight_a == weight_b);
  CHECK(norm(load_a - load_b) < 0.01 * norm(load_a));
  CHECK(load_a.z == Approx(-weight_a).epsilon(0.01));
  CHECK(load_b.z == Approx(-weight_b).epsilon(0.01));
  CHECK(speed_a < 0.05);
  CHECK(speed_b < 0.05);
}

namespace {
// 600 particles in a 30-degree periodic tester sector with revolution walls (floor turning and
// wearing, with the tester triangulation for its accounting), on two threads; with `from`, the
// particles where that state has them.
void make_revolution_sector(System& s, const SystemState* from) {
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  wear::meshes::TesterGeometry t;
  t.sector_angle_deg = 30;
  t.wall_height = 0.1;
  t.wall_mesh_size = 0.02;
  t.consolidator = false;
  const auto m = wear::meshes::generate_tester_walls(t);
  WallMotion rot;
  rot.angular_velocity = 0.5 * pi;
  s.add_wall(
      RevolutionWall(RevolutionSurface::annulus(0, 0.29, 0.5), g, rot, true, "floor", &m.floor));
  s.add_wall(RevolutionWall(RevolutionSurface::cylinder(0.29, 0, 0.1), g, rot, false, "inner"));
  s.add_wall(RevolutionWall(RevolutionSurface::cylinder(0.5, 0, 0.1), g, rot, false, "outer"));
  s.settings.periodic = {true, pi / 6};
  s.settings.domain = {{-0.6, -0.6, -0.01}, {0.6, 0.6, 0.5}};
  const SizeDistribution psd{{8e-3, 10e-3}, {0.5, 0.5}, 1.0};
  if (from)
    add_particles_of(s.particles, *from);
  else
    insert_random(s.particles, annular_sector_region(0.29, 0.5, pi / 6, 0, 0.04, 5.1e-3), psd, 600,
                  2650, g, 11);
  omp_set_num_threads(2);
  s.setup();
  omp_set_num_threads(omp_get_num_procs());
}

} // namespace

TEST_CASE("with revolution walls an exported or resumed state continues bit for bit",
          "[dem][determinism][walls]") {
  System a;
  make_revolution_sector(a, nullptr);
  a.run(2500);
  const SystemState start = a.export_state();
  CHECK(a.n_wall_particles() > 100);
  CHECK(a.n_ghosts() > 0);
  SECTION("resumed between two steps") {
    System b;
    make_revolution_sector(b, &start);
    b.resume_state(start);
    a.run(300);
    b.run(137);
    const SystemState middle = b.export_state();
    System c;
    make_revolution_sector(c, &middle);
    c.resume_state(middle);
    c.run(163);
    CHECK(a.export_state().n_rebuilds > start.n_rebuilds);
    check_same_state(a, c);
  }
  SECTION("exported and imported at a boundary") {
    a.import_state(start);
    a.run(300);
    System b;
    make_revolution_sector(b, &start);
    b.import_state(start);
    b.run(300);
    check_same_state(a, b);
  }
}

// Engine-level checks: energy conservation, the cylindrical periodic sector, Coulomb
// sliding on a rotating floor, determinism, and clear failures on bad input.
#include "dem/engine/snapshot.h"
#include "meshes/structured_grid.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <random>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::Vec3;

namespace {
// 400 particles of 8 mm settled in a 10 cm box (friction, damping), returned as a state.
Particles settled_box(int n_steps) {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.0);
  s.add_wall(MeshWall(box_walls(0.1), g, {}, false, "box"));
  SizeDistribution psd{{8e-3}, {1.0}, 1.0};
  const auto n = insert_random(s.particles, box_region({0, 0, 0}, {0.1, 0.1, 0.1}, 4.1e-3), psd,
                               400, 2650, g, 42);
  REQUIRE(n == 400);
  s.setup();
  s.run(n_steps);
  return s.particles;
}

// 1200 gravel particles (8 and 10 mm) in a 30-degree periodic tester sector with rotating
// walls, on two threads; with `from`, the particles where that state has them, as
// WearTester::restore does, so the set-up system already has contacts (and forces) of its own.
void make_periodic_sector(System& s, const SystemState* from, bool wearing_floor = false) {
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  add_periodic_tester_sector(s, g, 30, false, wearing_floor);
  SizeDistribution psd{{8e-3, 10e-3}, {0.5, 0.5}, 1.0};
  if (from)
    add_particles_of(s.particles, *from);
  else
    insert_random(s.particles, annular_sector_region(0.29, 0.5, 30 * pi / 180, 0, 0.05, 5.1e-3),
                  psd, 1200, 2650, g, 11);
  omp_set_num_threads(2); // setup() takes OpenMP's thread count
  s.setup();
  omp_set_num_threads(omp_get_num_procs());
}
} // namespace

TEST_CASE("energy is conserved without damping and friction", "[dem][energy]") {
  const Particles settled = settled_box(4000);
  System s;
  const int g = add_gravel(s, 1.0, 0.0, 0.0);
  s.add_wall(MeshWall(box_walls(0.1), g, {}, false, "box"));
  s.particles = settled;
  // Release: every particle gets a velocity kick so the assembly moves and collides.
  for (std::size_t i = 0; i < s.particles.n_real; ++i)
    s.particles.velocity[i] = {0.3 * std::sin(1.0 * i), 0.3 * std::cos(1.7 * i),
                               0.2 * std::sin(2.3 * i)};
  s.setup();
  const Energy e0 = s.energy();
  double worst = 0;
  for (int k = 0; k < 100; ++k) {
    s.run(100);
    worst = std::max(worst, std::abs(s.energy().total() - e0.total()));
  }
  INFO("E0 = " << e0.total() << " J (kinetic " << e0.kinetic << "), worst drift " << worst);
  CHECK(worst / e0.total() < 1e-3);
  // The stricter reading: the drift is also small against the kinetic energy alone.
  CHECK(worst / e0.kinetic < 1e-2);
  CHECK(s.n_steps() == 10000);
}

TEST_CASE("periodic sector: a particle crossing the cut keeps speed and radius",
          "[dem][periodic]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.0);
  s.settings.gravity = {};
  s.settings.periodic = {true, 150 * pi / 180};
  const double R = 0.4, v = 2.0, angle = 150 * pi / 180;
  // Just before the theta = angle cut, moving in +theta.
  const double th0 = angle - 0.01;
  const Vec3 x0{R * std::cos(th0), R * std::sin(th0), 0.05};
  const Vec3 v0{-v * std::sin(th0), v * std::cos(th0), 0};
  s.particles.add(x0, v0, 4e-3, 2650, g);
  s.setup();
  for (int k = 0; k < 400; ++k) {
    s.step();
    // Unwrapped straight line, then rotated back into the sector if past the cut.
    const Vec3 line = x0 + v0 * s.time();
    const Vec3& x = s.particles.position[0];
    CHECK(std::hypot(x.x, x.y) == Approx(std::hypot(line.x, line.y)).epsilon(1e-12));
    CHECK(wear::meshes::norm(s.particles.velocity[0]) == Approx(v).epsilon(1e-12));
  }
  const Vec3& x = s.particles.position[0];
  const Vec3 line = x0 + v0 * s.time();
  CHECK(std::atan2(line.y, line.x) > angle); // the straight line left the sector ...
  // ... and the particle re-entered through the theta = 0 cut, rotated by the sector angle.
  CHECK(std::atan2(x.y, x.x) == Approx(std::atan2(line.y, line.x) - angle).epsilon(1e-9));
}

TEST_CASE("periodic sector: a pair across the cut feels the interior force", "[dem][periodic]") {
  const double angle = 150 * pi / 180, R = 0.4, r = 4e-3, gap = -0.5e-3; // overlap 0.5 mm
  const auto run = [&](double th_a, double th_b, bool periodic) {
    System s;
    const int g = add_gravel(s, 0.5, 0.5, 0.1);
    s.settings.gravity = {};
    s.settings.periodic = {periodic, angle};
    // Velocities and spins in polar components, so both set-ups differ only by a rotation.
    const auto polar = [](double th, double a_r, double a_t, double a_z) {
      return Vec3{a_r * std::cos(th) - a_t * std::sin(th), a_r * std::sin(th) + a_t * std::cos(th),
                  a_z};
    };
    s.particles.add({R * std::cos(th_a), R * std::sin(th_a), 0.05}, polar(th_a, 0.1, 0.05, 0), r,
                    2650, g);
    s.particles.add({R * std::cos(th_b), R * std::sin(th_b), 0.05}, polar(th_b, -0.05, -0.1, 0.02),
                    r, 2650, g);
    s.particles.angular_velocity[0] = polar(th_a, 3, 1, -2);
    s.particles.angular_velocity[1] = polar(th_b, -1, 2, 5);
    s.setup();
    s.run(3); // history and damping take part
    return std::pair{s.particles.force[0], s.particles.force[1]};
  };
  // Chord half-angle so that the centre distance is 2 r + gap.
  const double half = std::asin((2 * r + gap) / (2 * R));
  const auto straddle = run(angle - half, half, true); // particle 1 sits across the cut
  const auto inside = run(1.0 - half, 1.0 + half, false);
  // The same relative geometry, rotated: compare magnitudes.
  CHECK(norm(straddle.first) == Approx(norm(inside.first)).epsilon(1e-9));
  CHECK(norm(straddle.second) == Approx(norm(inside.second)).epsilon(1e-9));
  CHECK(norm(straddle.first) > 1.0); // really in contact
}

TEST_CASE("periodic sector: a pair colliding across the cut follows the interior pair",
          "[dem][periodic]") {
  // The slab test's check for the sector, where crossing the cut turns a particle and its
  // pair histories by the sector angle: an oblique, spinning impact of two 3 mm particles
  // drifting at 3 m/s along the circle, so that particle a wraps through the cut while the
  // pair is in contact (tangential spring and rolling history carried across the wrap). The
  // reference is the same pair, turned, in the middle of the sector. Free flight is straight,
  // so both set-ups are exact rotations of one another.
  // t0 lies a quarter step off the step grid: a contact starting exactly on a step would begin
  // one step earlier or later with the round-off of the turn, a jump of 1e-7 in the outcome.
  const double angle = 30 * pi / 180, R = 0.4, r = 3e-3, t0 = 1.00005e-3;
  const auto turn = [](double b, const Vec3& v) {
    return Vec3{v.x * std::cos(b) - v.y * std::sin(b), v.x * std::sin(b) + v.y * std::cos(b), v.z};
  };
  // The pair about (R, 0, 0.05) with +y along the circle: a's centre 0.2 mm short of y = 0
  // when they touch, both moved back along their velocities by t0.
  const Vec3 va{0.02, 3.1, 0.01}, vb{-0.01, 2.9, -0.02};
  const Vec3 wa{10, -40, 25}, wb{-15, 20, 30};
  const Vec3 touch_a{R, -0.2e-3, 0.05};
  const Vec3 touch_b = touch_a + Vec3{1.0e-3, std::sqrt(4 * r * r - 1.0e-6 - 0.25e-6), 0.5e-3};
  const Vec3 xa = touch_a - t0 * va, xb = touch_b - t0 * vb;
  struct Run {
    System s;
    bool wrapped_in_contact = false;
  };
  const auto run = [&](double beta, bool periodic) {
    auto out = std::make_unique<Run>();
    System& s = out->s;
    const int g = add_gravel(s, 0.5, 0.5, 0.1);
    s.settings.gravity = {};
    s.settings.periodic = {periodic, angle};
    s.settings.time_step = 2e-7;
    s.settings.skin = 2e-4; // a rebuild every few tens of steps, several while in contact
    // b lies past theta = beta; in the periodic set-up it starts wrapped, turned back by angle.
    const double wrap_b = periodic ? -angle : 0.0;
    s.particles.add(turn(beta, xa), turn(beta, va), r, 2650, g);
    s.particles.add(turn(beta + wrap_b, xb), turn(beta + wrap_b, vb), r, 2650, g);
    s.particles.angular_velocity[0] = turn(beta, wa);
    s.particles.angular_velocity[1] = turn(beta + wrap_b, wb);
    s.setup();
    double theta_a = std::atan2(s.particles.position[0].y, s.particles.position[0].x);
    for (int k = 0; k < 15000; ++k) { // 3 ms: closing, contact (about 0.3 ms), apart again
      s.run(1);
      const Vec3& p = s.particles.position[0];
      const double th = std::atan2(p.y, p.x);
      if (th < theta_a - 0.5 * angle && norm(s.particles.force[0]) > 0)
        out->wrapped_in_contact = true;
      theta_a = th;
    }
    return out;
  };
  const auto across = run(angle, true);
  const auto inside = run(0.5 * angle, false);
  // Measured (engine ef5c169): velocities 6e-12, spins 1.5e-10 relative, positions 6e-14 m.
  REQUIRE(across->wrapped_in_contact);
  REQUIRE(across->s.n_rebuilds() > 20);
  const Particles& per = across->s.particles;
  const Particles& ref = inside->s.particles;
  for (int i = 0; i < 2; ++i) {
    INFO("particle " << i);
    // Each particle of the periodic run lies half a sector ahead of or behind its reference.
    const double d = std::atan2(per.position[i].y, per.position[i].x) -
                     std::atan2(ref.position[i].y, ref.position[i].x);
    CHECK(std::abs(std::abs(d) - 0.5 * angle) < 1e-9);
    const Vec3 dx = turn(-d, per.position[i]) - ref.position[i];
    const Vec3 dv = turn(-d, per.velocity[i]) - ref.velocity[i];
    const Vec3 dw = turn(-d, per.angular_velocity[i]) - ref.angular_velocity[i];
    CHECK(norm(dx) <= 1e-12);
    CHECK(norm(dv) <= 1e-9 * norm(ref.velocity[i]));
    CHECK(norm(dw) <= 1e-9 * norm(ref.angular_velocity[i]));
    // The collision happened: friction changed the spins.
    CHECK(norm(ref.angular_velocity[i] - turn(0.5 * angle, i == 0 ? wa : wb)) > 1.0);
  }
}

TEST_CASE("periodic sector: particle count constant over a long run", "[dem][periodic]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  const double angle = 60 * pi / 180;
  add_periodic_tester_sector(s, g, 60, true);
  SizeDistribution psd{{8e-3}, {1.0}, 1.0};
  const auto n = insert_random(
      s.particles, annular_sector_region(0.29, 0.5, angle, 0, 0.06, 4.1e-3), psd, 1500, 2650, g, 7);
  REQUIRE(n > 1000);
  s.setup();
  const double steps_per_second = 1 / s.time_step();
  s.run(std::uint64_t(0.4 * steps_per_second)); // the bed turns by 36 deg
  CHECK(s.particles.n_real == n);
  double mean_omega = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = s.particles.position[i];
    const double th = std::atan2(x.y, x.x);
    CHECK(th > -0.05);
    CHECK(th < angle + 0.05);
    mean_omega += (x.x * s.particles.velocity[i].y - x.y * s.particles.velocity[i].x) /
                  (x.x * x.x + x.y * x.y);
  }
  mean_omega /= double(n);
  INFO("mean bed angular velocity " << mean_omega << " rad/s");
  CHECK(mean_omega > 0.2); // the rotating floor drags the bed along
  CHECK(s.n_ghosts() > 0);
  write_particles_vtu(s.particles, "periodic_sector.vtu");
  std::ifstream in("periodic_sector.vtu");
  CHECK(in.good());
}

TEST_CASE("Coulomb sliding on a rotating floor", "[dem][walls]") {
  System s;
  const double mu = 0.5, r = 4e-3, R0 = 0.4, omega = 0.5 * pi;
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {0.5, mu, 0.0});
  wear::meshes::TesterGeometry t;
  t.consolidator = false;
  t.wall_mesh_size = 0.03;
  WallMotion rot;
  rot.angular_velocity = omega;
  s.add_wall(MeshWall(generate_tester_walls(t).floor, g, rot, false, "floor"));
  const double th0 = 1.0;
  // At rest in its gravity equilibrium overlap.
  const double m = 2650 * 4.0 / 3.0 * pi * r * r * r;
  const double e_star = 1 / (2 * (1 - 0.0625) / 5e7);
  const double delta = std::pow(m * 9.81 / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);
  s.particles.add({R0 * std::cos(th0), R0 * std::sin(th0), r - delta}, {}, r, 2650, g);
  s.setup();
  s.run(std::uint64_t(0.01 / s.time_step()));
  const double t_run = s.time();
  const Vec3 tangent{-std::sin(th0), std::cos(th0), 0};
  const Vec3 v = s.particles.velocity[0];
  // Sliding: a = mu g along the floor motion, spin-up 5/2 mu g / r.
  CHECK(dot(v, tangent) == Approx(mu * 9.81 * t_run).epsilon(0.01));
  const Vec3 f = s.particles.force[0] + Vec3{0, 0, m * 9.81}; // contact force alone
  CHECK(std::hypot(f.x, f.y) == Approx(mu * f.z).epsilon(1e-6));
  const double spin = norm(s.particles.angular_velocity[0]);
  CHECK(spin == Approx(2.5 * mu * 9.81 * t_run / r).epsilon(0.01));
  // Wall-relative slip of the contact point: floor speed minus (v + r w).
  const double slip_expected = omega * R0 - 3.5 * mu * 9.81 * t_run;
  const Vec3 cp = v + cross(s.particles.angular_velocity[0], Vec3{0, 0, -r});
  const Vec3 floor_v = cross(Vec3{0, 0, omega}, s.particles.position[0]);
  CHECK(norm(floor_v - Vec3{cp.x, cp.y, 0}) == Approx(slip_expected).epsilon(0.01));
}

TEST_CASE("same input and thread count give bitwise identical states", "[dem][determinism]") {
  const auto run = [](int threads) {
    omp_set_num_threads(threads);
    auto p = settled_box(1500);
    omp_set_num_threads(omp_get_num_procs());
    return p;
  };
  const auto a = run(2), b = run(2), c = run(1);
  bool same_ab = true;
  double max_ac = 0;
  for (std::size_t i = 0; i < a.n_real; ++i) {
    same_ab = same_ab && a.position[i] == b.position[i] && a.velocity[i] == b.velocity[i] &&
              a.angular_velocity[i] == b.angular_velocity[i];
    max_ac = std::max(max_ac, norm(a.position[i] - c.position[i]));
  }
  CHECK(same_ab);
  // Another thread count adds the forces on a particle near the threads' boundary in another
  // order (a thread's own contacts first, then the other's), so the last bits may differ; in
  // this settling box they stay at round-off (1.5e-17 m measured): 1e-9 m leaves room for
  // growth but catches a force lost or counted twice at the boundary.
  INFO("largest position difference, 1 against 2 threads: " << max_ac << " m");
  CHECK(max_ac < 1e-9);
}

TEST_CASE("an exported state continues bit for bit in a freshly set-up system",
          "[dem][determinism]") {
  // As the coupler does at a stage boundary (export, import into the same system) and after a
  // restart (import into a new one): a periodic sector with rotating walls, on two threads,
  // so ghosts, wraps, wall slots and the per-thread force sums all cross the boundary.
  System a;
  make_periodic_sector(a, nullptr);
  a.run(4000); // settled: the bed rests on the floor, and its contacts cross the boundary
  const SystemState boundary = a.export_state();
  a.import_state(boundary);
  a.run(300);
  System b;
  make_periodic_sector(b, &boundary);
  b.import_state(boundary);
  b.run(300);
  CHECK(a.n_pair_contacts() > 300);
  CHECK(a.n_ghosts() > 0);
  check_same_particles(a, b);
}

TEST_CASE("a state resumed between any two steps continues as if never stopped",
          "[dem][determinism]") {
  // As an in-stage checkpoint does: stopped at a step that is no rebuild, the lists, the
  // threads' split and the open wear window (on a wearing floor) must come back as they were;
  // an extra rebuild would wrap, reorder and re-split, and the bits would differ.
  System a;
  make_periodic_sector(a, nullptr, true);
  a.run(4000);
  const SystemState start = a.export_state();
  const std::uint64_t rebuilds_before = start.n_rebuilds;
  System b;
  make_periodic_sector(b, &start, true);
  b.resume_state(start);
  a.run(300);
  b.run(137);
  const SystemState middle = b.export_state();
  System c;
  make_periodic_sector(c, &middle, true);
  c.resume_state(middle);
  c.run(163);
  CHECK(a.n_rebuilds() > rebuilds_before); // lists were rebuilt after the stop
  CHECK(a.n_rebuilds() == c.n_rebuilds());
  CHECK(a.n_ghosts() > 0);
  check_same_state(a, c);
  // Another thread count is refused by name.
  System d;
  make_periodic_sector(d, &middle, true);
  d.set_n_threads(1);
  CHECK_THROWS_WITH(d.resume_state(middle), Catch::Contains("DEM/Threads"));
}

TEST_CASE("a tangential history belongs to the pair and not to its listed order",
          "[dem][determinism]") {
  // The history of pair (i, j) is the tangential displacement of i relative to j: listed as
  // (j, i) it is the negative. The spatial sort renumbers particles every tenth rebuild and a
  // wrap across the periodic cut turns a real pair into a ghost pair, so a rebuild must carry
  // each history over with the orientation of the new list. Here the same settled state is
  // imported once as listed and once with every real pair listed the other way round (and
  // its history negated): the same physical state, so the same forces, bit for bit.
  System s;
  make_periodic_sector(s, nullptr);
  s.run(4000);
  const SystemState as_listed = s.export_state();
  SystemState reversed = as_listed;
  const std::size_t n = as_listed.position.size();
  std::size_t n_reversed_with_history = 0;
  for (std::size_t k = 0; k < reversed.pair_i.size(); ++k)
    if (reversed.pair_j[k] < n) {
      std::swap(reversed.pair_i[k], reversed.pair_j[k]);
      reversed.pair_history[k] = -reversed.pair_history[k];
      n_reversed_with_history += wear::meshes::norm(reversed.pair_history[k]) > 0;
    }
  REQUIRE(n_reversed_with_history > 300);
  s.import_state(as_listed);
  s.run(1);
  const SystemState a = s.export_state();
  s.import_state(reversed);
  s.run(1);
  const SystemState b = s.export_state();
  REQUIRE(a.pair_i == b.pair_i);
  std::size_t n_force_differ = 0, n_history_differ = 0;
  for (std::size_t i = 0; i < n; ++i)
    n_force_differ += !(a.force[i] == b.force[i] && a.torque[i] == b.torque[i]);
  for (std::size_t k = 0; k < a.pair_history.size(); ++k)
    n_history_differ += !(a.pair_history[k] == b.pair_history[k]);
  CHECK(n_force_differ == 0);
  CHECK(n_history_differ == 0);
}

TEST_CASE("bad input stops with a message naming the problem", "[dem][errors]") {
  {
    System s;
    const int g = add_gravel(s, 0.5, 0.5, 0.0);
    s.particles.add({0, 0, 0}, {}, 4e-3, 2650, g);
    s.settings.time_step = 1e-3; // far above 40 % of the Rayleigh time (~1.6e-4 s)
    CHECK_THROWS_WITH(s.setup(), Catch::Contains("Time step") && Catch::Contains("Rayleigh"));
  }
  {
    System s;
    const int g = add_gravel(s, 0.5, 0.5, 0.0);
    s.particles.add({0, 0, 0}, {}, -4e-3, 2650, g);
    CHECK_THROWS_WITH(s.setup(), Catch::Contains("radius"));
  }
  {
    System s; // two particles inserted almost on top of each other explode
    const int g = add_gravel(s, 0.5, 0.5, 0.0);
    s.settings.gravity = {};
    s.settings.max_speed = 10;
    s.particles.add({0, 0, 0}, {}, 4e-3, 2650, g);
    s.particles.add({1e-4, 0, 0}, {}, 4e-3, 2650, g);
    s.setup();
    CHECK_THROWS_WITH(s.run(100), Catch::Contains("particle") && Catch::Contains("speed limit") &&
                                      Catch::Contains("overlaps") &&
                                      Catch::Contains("1 particle(s) overlapping it, the deepest"));
  }
  {
    System s; // a particle placed 1.2 mm into a wall is thrown out of it; the message says where
    const int g = add_gravel(s, 0.5, 0.5, 0.0);
    s.settings.gravity = {};
    s.settings.max_speed = 5;
    s.add_wall(MeshWall(box_walls(0.1), g, {}, false, "box"));
    s.particles.add({0.03, 0.06, 4e-3 - 1.2e-3}, {}, 4e-3, 2650, g);
    s.setup();
    CHECK_THROWS_WITH(s.run(100), Catch::Contains("speed limit") &&
                                      Catch::Contains("Around it now: wall 'box' ") &&
                                      Catch::Contains("um deep at face") &&
                                      Catch::Contains("0 particle(s) overlapping it."));
  }
  {
    System s; // no floor: the particle falls out of the domain
    add_gravel(s, 0.5, 0.5, 0.0);
    s.settings.domain = {{-1, -1, -0.1}, {1, 1, 1}};
    s.particles.add({0, 0, 0}, {}, 4e-3, 2650, 0);
    s.setup();
    CHECK_THROWS_WITH(s.run(20000), Catch::Contains("left the domain"));
  }
  CHECK_THROWS_WITH(SizeDistribution({{2e-3, 3e-3}, {0.5, 0.4}, 1}).validate(),
                    Catch::Contains("sum to"));
}

TEST_CASE("filling to a bed height from a PSD, then settling", "[dem][filling]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  const double L = 0.06;
  auto box = box_walls(L); // twice as tall as wide: room for the loose insertion
  for (auto& v : box.vertices)
    v.z *= 2;
  s.add_wall(MeshWall(box, g, {}, false, "box"));
  // The reference three-bin PSD at s = 3: 6, 7.95, 10.05 mm.
  SizeDistribution psd{{2.0e-3, 2.65e-3, 3.35e-3}, {0.25, 0.5, 0.25}, 3.0};
  const auto report = fill_to_height(
      s,
      [&](double z_top) {
        return box_region({0, 0, 0}, {L, L, std::min(z_top, 2 * L)}, 5.1e-3);
      },
      L * L, 0.0, 0.025, psd, 2650, g, 3, 3.0, 0.01, 2.0, {}, 0.52);
  INFO("n " << report.n_particles << ", bed height " << report.bed_height << " m, packing "
            << report.packing_fraction << ", settled after " << report.settle_time << " s");
  CHECK(report.n_particles > 100);
  CHECK(report.bed_height == Approx(0.025).epsilon(0.2));
  CHECK(report.packing_fraction > 0.45); // random packings of spheres: about 0.55 to 0.64
  CHECK(report.packing_fraction < 0.68);
  // No particle overlaps another by more than 2 % of its radius after settling.
  const auto& p = s.particles;
  double worst = 0;
  for (std::size_t i = 0; i < p.n_real; ++i)
    for (std::size_t j = i + 1; j < p.n_real; ++j)
      worst = std::max(worst, (p.radius[i] + p.radius[j] - norm(p.position[i] - p.position[j])) /
                                  std::min(p.radius[i], p.radius[j]));
  CHECK(worst < 0.02);
}

TEST_CASE("a finely tessellated concave wall gives one Hertz contact", "[dem][walls]") {
  // A sphere (r = 4 mm) pressed into a trough (R = 20 mm) of 0.5-degree chords: about a dozen
  // chords' planes overlap it, each a distance minimum of its own. They are one contact with
  // the smooth surface; the engine keeps the deepest (the chord under the centre), so the
  // force is F = 4/3 E* sqrt(r) delta^1.5 of that chord, along its normal.
  System s;
  s.settings.gravity = {0, 0, 0};
  const int g = add_gravel(s, 0.5, 0.5, 0.0);
  const double R = 0.02, r = 4e-3, delta = 5e-5, d_theta = pi / 360;
  const int n_u = 240; // -60 ... +60 degrees
  const auto trough = [&](bool flip) {
    return wear::meshes::structured_grid(
        n_u, 20,
        [&](double u, double v) {
          const double th = (u - 0.5) * n_u * d_theta;
          return Vec3{0.02 * v, R * std::sin(th), R - R * std::cos(th)};
        },
        flip, wear::meshes::label::wall);
  };
  auto mesh = trough(false);
  if (dot(wear::meshes::face_normal_unnormalized(mesh, 0), Vec3{0, 0, 1}) < 0)
    mesh = trough(true); // normals towards the axis, the side the particle is on
  s.add_wall(MeshWall(mesh, g, {}, false, "trough"));
  const double th_mid = 0.5 * d_theta; // middle of the chord just past the bottom
  const Vec3 axis{0.0105, 0, R}, out{0, std::sin(th_mid), -std::cos(th_mid)};
  const double chord_distance = R * std::cos(0.5 * d_theta); // axis to the chord's plane
  s.particles.add(axis + out * (chord_distance - r + delta), {}, r, 2650, g);
  int n_overlapping = 0; // chords whose plane cuts the sphere
  for (int k = -n_u / 2; k < n_u / 2; ++k)
    if (chord_distance - (chord_distance - r + delta) * std::cos((k + 0.5) * d_theta - th_mid) < r)
      ++n_overlapping;
  REQUIRE(n_overlapping > 6); // more than the engine's contact slots: merging is exercised
  s.setup();
  const double e_star = 5e7 / (2 * (1 - 0.25 * 0.25));
  const double f_hertz = 4.0 / 3.0 * e_star * std::sqrt(r) * std::pow(delta, 1.5);
  const Vec3 f = s.particles.force[0];
  CHECK(norm(f) == Approx(f_hertz).epsilon(1e-9));
  CHECK(dot(f, out) == Approx(-f_hertz).epsilon(1e-9));
}

TEST_CASE("the wall's cheap rejections never drop a face within reach", "[dem][walls]") {
  // The step rejects a candidate face by the distance to its plane, then by the distance to
  // its bounding sphere and by the disc the ball cuts from its plane, before the closest-point
  // search. All three are lower bounds of the true distance, so a rejected face must lie at
  // least r from the centre. Points around a finely
  // tessellated cylinder (convex, 1-degree chords, 1 mm along the axis), where many faces'
  // planes pass near a sphere that touches the cylinder elsewhere.
  const double R = 0.02;
  const auto mesh = wear::meshes::structured_grid(
      360, 20,
      [&](double u, double v) {
        const double th = 2 * pi * u;
        return Vec3{0.02 * v, R * std::cos(th), R * std::sin(th)};
      },
      false, wear::meshes::label::wall);
  const MeshWall wall(mesh, 0, {}, false, "cylinder");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  int n_wrong = 0, n_sphere_only = 0, n_disc_only = 0, n_touching = 0, n_combined_differs = 0;
  for (int k = 0; k < 200; ++k) {
    const double th = 2 * pi * unit(rng), rho = R + 0.01 * unit(rng);
    const Vec3 x{0.02 * unit(rng), rho * std::cos(th), rho * std::sin(th)};
    const double r = 1e-3 + 6e-3 * unit(rng);
    for (std::uint32_t f = 0; f < mesh.n_faces(); ++f) {
      const auto& b = wall.bound(f);
      const double h = b.plane_distance(x);
      const bool by_plane = h >= r;
      const bool by_sphere = b.beyond_sphere(x, r);
      const bool by_disc = !by_plane && b.beyond_disc(x, r, h);
      const bool touching = norm(wall.closest(f, x).point - x) < r;
      n_wrong += (by_plane || by_sphere || by_disc) && touching;
      n_combined_differs += b.rejects(x, r) != (by_plane || by_sphere || by_disc);
      n_sphere_only += by_sphere && !by_plane;
      n_disc_only += by_disc && !by_sphere;
      n_touching += touching;
    }
  }
  CHECK(n_wrong == 0);
  CHECK(n_combined_differs == 0);
  CHECK(n_touching > 0);
  CHECK(n_sphere_only > n_touching); // the sphere test does reject what the plane test passes
  CHECK(n_disc_only > 0);            // and the disc test some of what the sphere test passes
}

TEST_CASE("every wall face a particle touches is among its listed candidates", "[dem][walls]") {
  // A rebuild lists, per particle, the faces within r + skin/2: until the next rebuild no
  // particle moves more than skin/2 (the trigger) and walls move only through
  // set_wall_vertices, which rebuilds. Checked at every step of a falling and flowing bed in
  // the periodic tester sector with rotating walls, against each wall's own search grid.
  System s;
  make_periodic_sector(s, nullptr);
  const auto& p = s.particles;
  std::size_t n_touching = 0, n_missing = 0;
  const std::uint64_t rebuilds_before = s.n_rebuilds();
  for (int step = 0; step < 4000; ++step) {
    s.step();
    for (std::size_t i = 0; i < p.n_real; ++i) {
      const auto [b, e] = s.wall_candidates(i);
      for (int w = 0; w < s.n_walls(); ++w) {
        auto [fb, fe] = s.wall(w).candidates(p.position[i]);
        for (; fb != fe; ++fb) {
          if (norm(s.wall(w).closest(*fb, p.position[i]).point - p.position[i]) >= p.radius[i])
            continue;
          ++n_touching;
          n_missing += std::find(b, e, (std::uint32_t(w) << 24) | *fb) == e;
        }
      }
    }
  }
  CHECK(n_missing == 0);
  CHECK(n_touching > 100000);                   // the bed lies on the walls
  CHECK(s.n_rebuilds() - rebuilds_before > 20); // and moves: the lists were rebuilt often
}

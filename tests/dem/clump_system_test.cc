// Rigid clumps stepped by the System (dem/engine/system_clumps.cc, clumps.cc):
// - in zero gravity an asymmetric clump keeps its energy to 1e-8 over 1e5 steps, its angular
//   momentum exactly (no torque), its centre moves at its velocity, and its members, which
//   overlap, never touch each other; a spin about the intermediate axis flips, one about the
//   largest axis stays;
// - a clump at rest on a plane stays at rest (drift below 1e-9 m over 1e5 steps), once placed at
//   the analytic Hertz overlap and once settled from a drop;
// - a brick-like clump on an incline stays 1 degree below the friction angle atan(mu) and slides
//   1 degree above it with the acceleration g (sin t - mu cos t), without rolling.
#include "dem/engine/clump_shape.h"
#include "dem/engine/system.h"
#include "dem/scene/particle_shapes.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace wear::dem;
using wear::pi;
using wear::dem::testing::add_gravel;
using wear::meshes::Vec3;

namespace {

/// A library shape scaled to the equivalent diameter d [m].
ClumpShape library_shape(const std::string& name, double d) {
  const ClumpShape s = clump_shape(named_clump_template(name, "test"));
  return s.scaled(d / s.equivalent_diameter());
}

/// A horizontal square plane z = 0 of half-width a, facing +z.
wear::meshes::SurfaceMesh plane(double a) {
  wear::meshes::SurfaceMesh m;
  m.vertices = {{-a, -a, 0}, {a, -a, 0}, {a, a, 0}, {-a, a, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.face_labels.assign(2, wear::meshes::label::wall);
  return m;
}

struct FreeSpin {
  double max_energy_error = 0; ///< [-] relative
  double momentum_change = 0;  ///< [-] relative, angular
  double centre_error = 0;     ///< [m] from x0 + v t
  int n_flips = 0;             ///< sign changes of the body-frame momentum along `axis`
  std::size_t max_pairs = 0;   ///< listed pairs (members of one body are never listed)
  double omega_dt = 0;         ///< [rad] |omega| dt
};

FreeSpin spin_freely(const Vec3& omega_body, int axis) {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0);
  s.settings.gravity = {0, 0, 0};
  s.set_n_threads(1);
  const ClumpShape shape = library_shape("crushed stone 8", 5e-3);
  const Quaternion q0 = rotation_about(wear::meshes::normalized(Vec3{1, 2, 3}), 0.7);
  const Vec3 v{0.1, -0.05, 0.02};
  s.add_clump(shape, 2650, g, {0, 0, 0}, q0, v, rotate(q0, omega_body));
  s.setup();
  const auto& c = s.clumps();
  const double e0 = s.energy().total();
  const Vec3 L0 = c.angular_momentum[0];
  FreeSpin r;
  double last = rotate_back(c.orientation[0], L0)[axis];
  for (int n = 0; n < 1000; ++n) {
    s.run(100);
    r.max_energy_error = std::max(r.max_energy_error, std::abs(s.energy().total() - e0) / e0);
    const double l = rotate_back(c.orientation[0], c.angular_momentum[0])[axis];
    r.n_flips += (l > 0) != (last > 0);
    last = l;
    r.max_pairs = std::max(r.max_pairs, s.n_neighbor_pairs());
  }
  r.omega_dt = wear::meshes::norm(omega_body) * s.time_step();
  r.momentum_change = wear::meshes::norm(c.angular_momentum[0] - L0) / wear::meshes::norm(L0);
  r.centre_error = wear::meshes::norm(c.position[0] - v * (s.time()));
  return r;
}

} // namespace

TEST_CASE("a clump in zero gravity keeps its energy and momentum; about its intermediate axis "
          "it flips",
          "[dem][clump][rotation]") {
  // 50 rad/s, a grain's spin in the tester's bed, at the bed's time step: |omega| dt = 5e-4
  // (the energy error grows as its square).
  const FreeSpin intermediate = spin_freely({10, 50, 10}, 1);
  const FreeSpin largest = spin_freely({1, 1, 50}, 2);
  CAPTURE(intermediate.max_energy_error, largest.max_energy_error, intermediate.n_flips,
          intermediate.omega_dt);
  CHECK(intermediate.max_energy_error < 1e-8);
  CHECK(largest.max_energy_error < 1e-8);
  CHECK(intermediate.momentum_change < 1e-14);
  CHECK(largest.momentum_change < 1e-14);
  CHECK(intermediate.centre_error < 1e-12);
  CHECK(intermediate.n_flips >= 2);
  CHECK(largest.n_flips == 0);
  CHECK(intermediate.max_pairs == 0);
}

TEST_CASE("a clump at rest on a plane stays at rest", "[dem][clump]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0);
  s.set_n_threads(1);
  s.add_wall(MeshWall(plane(0.05), g, {}, false, "floor"));
  SECTION("four members on the plane at the Hertz overlap of a quarter of the weight each") {
    const ClumpShape shape = library_shape("flat 4", 5e-3);
    const double r = shape.members[0].radius, m = 2650 * shape.volume;
    const double e_star = 5e7 / (2 * (1 - 0.25 * 0.25)); // particle and wall of gravel
    const double f = m * 9.81 / 4;
    const double delta = std::pow(3 * f / (4 * e_star * std::sqrt(r)), 2.0 / 3.0);
    // The flat shape's largest moment is about the normal of its plane: body z.
    REQUIRE(std::abs(shape.members[0].centre.z) < 1e-6 * r);
    s.add_clump(shape, 2650, g, {0, 0, r - delta}, Quaternion{});
    s.setup();
    const Vec3 x0 = s.clumps().position[0];
    double drift = 0;
    for (int n = 0; n < 100; ++n) {
      s.run(1000);
      drift = std::max(drift, wear::meshes::norm(s.clumps().position[0] - x0));
    }
    CAPTURE(drift, delta);
    CHECK(drift < 1e-9);
  }
  SECTION("an irregular clump dropped and settled") {
    const ClumpShape shape = library_shape("crushed stone 4", 5e-3);
    s.add_clump(shape, 2650, g, {0, 0, shape.reach() + 1e-4},
                rotation_about(wear::meshes::normalized(Vec3{1, -1, 0.5}), 0.4));
    s.setup();
    s.run(std::uint64_t(0.5 / s.time_step()));
    const Vec3 x0 = s.clumps().position[0];
    double drift = 0;
    for (int n = 0; n < 100; ++n) {
      s.run(1000);
      drift = std::max(drift, wear::meshes::norm(s.clumps().position[0] - x0));
    }
    CAPTURE(drift, x0.z);
    CHECK(drift < 1e-9);
    CHECK(x0.z > 0);
  }
}

TEST_CASE("a brick-like clump on an incline slides above the friction angle, at the analytic "
          "acceleration, and does not roll",
          "[dem][clump]") {
  const double mu = 0.5, friction_angle = std::atan(mu);
  // Eight equal spheres at the corners of a 2 : 1.5 : 1 box: it rests on four.
  const double a = 1.5e-3;
  ClumpTemplate brick{"brick", {}};
  for (int k = 0; k < 8; ++k)
    brick.members.push_back(
        {{(k & 1 ? 1.0 : -1.0) * 2 * a, (k & 2 ? 1.0 : -1.0) * 1.5 * a, (k & 4 ? 1.0 : -1.0) * a},
         1.2 * a});
  const ClumpShape shape = clump_shape(brick);
  // Its body axes follow the box's (moments ascending: longest edge first); the incline is a
  // plane z = 0 under gravity tilted by t about y.
  const auto slide = [&](double t, double& acceleration, double& max_spin) {
    System s;
    const int g = add_gravel(s, 0.5, mu, 0);
    s.set_n_threads(1);
    s.settings.gravity = {9.81 * std::sin(t), 0, -9.81 * std::cos(t)};
    s.add_wall(MeshWall(plane(0.1), g, {}, false, "incline"));
    double z_min = 1e9;
    for (const auto& m : shape.members)
      z_min = std::min(z_min, m.centre.z - m.radius);
    s.add_clump(shape, 2650, g, {-0.05, 0, -z_min - 2e-6}, Quaternion{});
    s.setup();
    s.run(std::uint64_t(0.05 / s.time_step())); // lands and settles on its four spheres
    const double t0 = s.time(), x0 = s.clumps().position[0].x, v0 = s.clumps().velocity[0].x;
    max_spin = 0;
    for (int n = 0; n < 20; ++n) {
      s.run(std::uint64_t(0.01 / s.time_step()));
      max_spin = std::max(max_spin, wear::meshes::norm(s.clumps().angular_velocity(0)));
    }
    const double dt = s.time() - t0, dx = s.clumps().position[0].x - x0;
    acceleration = 2 * (dx - v0 * dt) / (dt * dt);
  };
  double below = 0, above = 0, spin_below = 0, spin_above = 0;
  slide(friction_angle - pi / 180, below, spin_below);
  slide(friction_angle + pi / 180, above, spin_above);
  const double t = friction_angle + pi / 180;
  const double analytic = 9.81 * (std::sin(t) - mu * std::cos(t));
  CAPTURE(below, above, analytic, spin_below, spin_above);
  CHECK(std::abs(below) < 1e-3 * analytic);
  CHECK(std::abs(above - analytic) < 0.02 * analytic);
  CHECK(spin_above < 0.1); // [rad/s]: sliding, not rolling (rolling would turn at v / r)
}

TEST_CASE("a clump colliding across a periodic sector's cut follows the interior pair",
          "[dem][clump][periodic]") {
  // The sphere test's set-up (system_test.cc) with two clumps of two spheres ('elongated 2',
  // 6 mm) lying along the circle and drifting along it at about 3 m/s: a's front member has
  // crossed the cut when the pair touches, and a's centre crosses it (the body wraps as one,
  // its members and their contact histories with it) while the pair is in contact. The
  // reference is the same pair, turned, in the middle of the sector; both set-ups are exact
  // rotations of one another up to round-off. No rolling friction (see below).
  const double angle = 30 * pi / 180, R = 0.4, t0 = 1.00005e-3;
  const auto turn = [](double b, const Vec3& v) {
    return Vec3{v.x * std::cos(b) - v.y * std::sin(b), v.x * std::sin(b) + v.y * std::cos(b), v.z};
  };
  const ClumpShape shape = library_shape("elongated 2", 6e-3);
  const double c = std::abs(shape.members[0].centre.x), rm = shape.members[0].radius;
  REQUIRE(std::abs(shape.members[1].centre.x) == Approx(c));
  // Body x along the circle (+y here); a's centre 0.2 mm short of the cut y = 0 at the touch.
  const Quaternion along = rotation_about({0, 0, 1}, 0.5 * pi);
  const Vec3 va{0.02, 3.1, 0.01}, vb{-0.01, 2.9, -0.02}, wa{1, -4, 2.5}, wb{-1.5, 2, 3};
  const Vec3 touch_a{R, -0.2e-3, 0.05};
  const Vec3 front_a = touch_a + Vec3{0, c, 0};
  const Vec3 touch_b =
      front_a + Vec3{1.0e-3, std::sqrt(4 * rm * rm - 1.25e-6), 0.5e-3} + Vec3{0, c, 0};
  const Vec3 xa = touch_a - t0 * va, xb = touch_b - t0 * vb;
  struct Run {
    System s;
    bool wrapped_in_contact = false;
  };
  const auto run = [&](double beta, bool periodic) {
    auto out = std::make_unique<Run>();
    System& s = out->s;
    const int g = add_gravel(s, 0.5, 0.5, 0);
    s.settings.gravity = {};
    s.settings.periodic = {periodic, angle};
    s.settings.time_step = 2e-7;
    s.settings.skin = 2e-4;
    const double wrap_b = periodic ? -angle : 0.0;
    const Quaternion qa = rotation_about({0, 0, 1}, beta) * along;
    const Quaternion qb = rotation_about({0, 0, 1}, beta + wrap_b) * along;
    s.add_clump(shape, 2650, g, turn(beta, xa), qa, turn(beta, va), turn(beta, wa));
    s.add_clump(shape, 2650, g, turn(beta + wrap_b, xb), qb, turn(beta + wrap_b, vb),
                turn(beta + wrap_b, wb));
    s.setup();
    double theta_a = std::atan2(s.clumps().position[0].y, s.clumps().position[0].x);
    for (int k = 0; k < 15000; ++k) {
      s.run(1);
      const Vec3& p = s.clumps().position[0];
      const double th = std::atan2(p.y, p.x);
      if (th < theta_a - 0.5 * angle && norm(s.clumps().force[0]) > 0)
        out->wrapped_in_contact = true;
      theta_a = th;
    }
    return out;
  };
  const auto across = run(angle, true);
  const auto inside = run(0.5 * angle, false);
  // Measured: positions 4e-13 m, velocities 4e-12, angular momenta 1.1e-9 relative,
  // orientations 3e-12 (a turned reference without the cut: 3.5e-13, 3.2e-12, 8.7e-10 and
  // 2.7e-12, so the wrap adds nothing beyond turning the frame). With rolling friction the
  // momenta of both set-ups part by 1e-6: its torque follows the direction of the members'
  // relative spin, which this glancing contact leaves ill-conditioned, with or without the cut.
  REQUIRE(across->wrapped_in_contact);
  REQUIRE(across->s.n_rebuilds() > 20);
  const Clumps& per = across->s.clumps();
  const Clumps& ref = inside->s.clumps();
  for (int b = 0; b < 2; ++b) {
    INFO("body " << b);
    const double d = std::atan2(per.position[b].y, per.position[b].x) -
                     std::atan2(ref.position[b].y, ref.position[b].x);
    CHECK(std::abs(std::abs(d) - 0.5 * angle) < 1e-9);
    const Vec3 dx = turn(-d, per.position[b]) - ref.position[b];
    const Vec3 dv = turn(-d, per.velocity[b]) - ref.velocity[b];
    const Vec3 dl = turn(-d, per.angular_momentum[b]) - ref.angular_momentum[b];
    const Quaternion q = rotation_about({0, 0, 1}, -d) * per.orientation[b];
    const Quaternion& r = ref.orientation[b];
    // q and -q are one rotation.
    const double sign = q.w * r.w + q.x * r.x + q.y * r.y + q.z * r.z < 0 ? -1 : 1;
    const double dq = std::sqrt(std::pow(sign * q.w - r.w, 2) + std::pow(sign * q.x - r.x, 2) +
                                std::pow(sign * q.y - r.y, 2) + std::pow(sign * q.z - r.z, 2));
    CAPTURE(norm(dx), norm(dv) / norm(ref.velocity[b]), norm(dl) / norm(ref.angular_momentum[b]),
            dq);
    CHECK(norm(dx) <= 1e-12 * R);
    CHECK(norm(dv) <= 1e-9 * norm(ref.velocity[b]));
    CHECK(norm(dl) <= 1e-8 * norm(ref.angular_momentum[b]));
    CHECK(dq <= 1e-10);
    // The collision happened: it changed the velocities.
    CHECK(norm(ref.velocity[b] - turn(0.5 * angle, b == 0 ? va : vb)) > 0.01);
  }
}

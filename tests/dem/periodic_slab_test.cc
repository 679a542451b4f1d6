// The planar periodic boundary (DemSettings::periodic_slab): a particle crossing a plane
// re-enters through the other one on its free-flight line; a pair colliding across the
// planes, one of them crossing while in contact, follows the same pair in the interior (its
// tangential history carried through the wrap); a dense gas colliding across the planes keeps
// its momentum to round-off; a slab shorter than the ghosts' reach is refused.
#include "dem_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::Vec3;

namespace {

/// The coordinate x brought into [lo, lo + L).
double into_slab(double x, double lo, double L) {
  return x - L * std::floor((x - lo) / L);
}

} // namespace

TEST_CASE("periodic slab: a particle leaves through one plane and enters through the other",
          "[dem][periodic]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  s.settings.gravity = {};
  s.settings.periodic_slab = {true, 0, -0.05, 0.05};
  const Vec3 x0{0.04, 0.01, 0.02}, v{2.0, -0.3, 0.1};
  s.particles.add(x0, v, 2e-3, 2650, g);
  s.settings.time_step = 1e-5;
  s.setup();
  s.run(6000); // 0.06 s: 0.12 m along x, through the upper plane twice (0.1 m period)
  const double t = s.time();
  const Vec3& x = s.particles.position[0];
  CHECK(x.x == Approx(into_slab(x0.x + v.x * t, -0.05, 0.1)).margin(1e-12));
  CHECK(x.y == Approx(x0.y + v.y * t).margin(1e-12));
  CHECK(x.z == Approx(x0.z + v.z * t).margin(1e-12));
  CHECK(s.particles.velocity[0] == v); // a shift does not turn the velocity
  CHECK(s.particles.n_real == 1);
}

TEST_CASE("periodic slab: a pair colliding across the planes follows the interior pair",
          "[dem][periodic]") {
  // Oblique, spinning impact of two 3 mm particles; in the periodic set-up particle a starts
  // 4 mm below the upper plane and b's image 4 mm above it, so they meet across the plane and
  // a crosses it in contact. The reference pair meets in the middle of a plain domain.
  const double r = 3e-3, L = 0.1;
  const auto run = [&](double xa, double xb, bool periodic) {
    System s;
    const int g = add_gravel(s, 0.5, 0.5, 0.1);
    s.settings.gravity = {};
    s.settings.periodic_slab = {periodic, 0, 0.0, L};
    s.settings.time_step = 2e-7;
    s.settings.skin = 2e-4; // rebuilds while in contact carry the history
    s.particles.add({xa, 0.0, 0.0}, {0.6, 0.1, -0.05}, r, 2650, g);
    s.particles.add({xb, 1.5e-3, 0.5e-3}, {-0.6, -0.2, 0.05}, r, 2650, g);
    s.particles.angular_velocity[0] = {10, -40, 25};
    s.particles.angular_velocity[1] = {-15, 20, 30};
    s.setup();
    s.run(40000); // 8 ms: closing, contact (about 0.1 ms) and apart again
    return s;
  };
  const System across = run(L - 4e-3, 4e-3, true);
  const System inside = run(0.05 - 4e-3, 0.05 + 4e-3, false);
  REQUIRE(across.n_rebuilds() > 5);
  for (int i = 0; i < 2; ++i) {
    INFO("particle " << i);
    const Vec3 dv = across.particles.velocity[i] - inside.particles.velocity[i];
    const Vec3 dw = across.particles.angular_velocity[i] - inside.particles.angular_velocity[i];
    CHECK(norm(dv) <= 1e-9 * norm(inside.particles.velocity[i]));
    CHECK(norm(dw) <= 1e-9 * norm(inside.particles.angular_velocity[i]));
    // The collision happened: each has turned from its initial velocity.
    CHECK(std::abs(inside.particles.velocity[i].x) < 0.55);
    // Positions agree modulo the period (the periodic pair starts 0.05 m further along x).
    const Vec3& a = across.particles.position[i];
    const Vec3& b = inside.particles.position[i];
    double dx = a.x - (b.x + 0.05);
    dx -= L * std::round(dx / L);
    CHECK(std::abs(dx) <= 1e-12);
    CHECK(a.y == Approx(b.y).margin(1e-12));
    CHECK(a.z == Approx(b.z).margin(1e-12));
  }
}

TEST_CASE("periodic slab: a dense gas colliding across the planes keeps its momentum",
          "[dem][periodic]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  s.settings.gravity = {};
  const double r = 2e-3, pitch = 4.2e-3;
  const int nx = 12, ny = 6, nz = 6;
  s.settings.periodic_slab = {true, 0, 0.0, nx * pitch};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        s.particles.add({(i + 0.5) * pitch, j * pitch, k * pitch}, {u(rng), u(rng), u(rng)},
                        r * (1 + 0.05 * u(rng)), 2650, g);
  s.settings.time_step = 1e-6;
  s.setup();
  const auto momentum = [&] {
    Vec3 m;
    double scale = 0;
    for (std::size_t i = 0; i < s.particles.n_real; ++i) {
      m += s.particles.mass[i] * s.particles.velocity[i];
      scale += s.particles.mass[i] * norm(s.particles.velocity[i]);
    }
    return std::pair{m, scale};
  };
  const auto [m0, scale] = momentum();
  std::size_t max_ghosts = 0, max_contacts = 0;
  for (int block = 0; block < 20; ++block) {
    s.run(500);
    max_ghosts = std::max(max_ghosts, s.n_ghosts());
    max_contacts = std::max(max_contacts, s.n_pair_contacts());
  }
  const auto [m1, unused] = momentum();
  INFO("momentum change " << norm(m1 - m0) << " of " << scale);
  CHECK(norm(m1 - m0) <= 1e-12 * scale);
  CHECK(max_ghosts > 0);
  CHECK(max_contacts > 20);
  for (std::size_t i = 0; i < s.particles.n_real; ++i) { // wrapped, drifting at most skin/2
    REQUIRE(s.particles.position[i].x >= -1e-3);
    REQUIRE(s.particles.position[i].x < nx * pitch + 1e-3);
  }
}

TEST_CASE("periodic slab: refused when shorter than the ghosts' reach or with a sector",
          "[dem][periodic]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  s.particles.add({0.001, 0, 0}, {}, 3e-3, 2650, g);
  s.settings.periodic_slab = {true, 0, 0.0, 0.012}; // reach 2 r + skin = 7.5 mm
  CHECK_THROWS_WITH(s.setup(), Catch::Contains("periodic slab's period 0.012"));
  System t;
  const int h = add_gravel(t, 0.5, 0.5, 0.1);
  t.particles.add({0.1, 0.1, 0}, {}, 3e-3, 2650, h);
  t.settings.periodic_slab = {true, 0, 0.0, 0.5};
  t.settings.periodic = {true, 1.0};
  CHECK_THROWS_WITH(t.setup(), Catch::Contains("exclude each other"));
}

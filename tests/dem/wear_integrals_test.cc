// Wearing walls: per-face integrals sum to the per-contact totals, and the Archard
// load-distance of a particle held on a moving face equals F_n |v_t| t.
#include "meshes/structured_grid.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::Vec3;

namespace {
// Flat square [-L, L]^2 at z = 0 with n x n quads.
wear::meshes::SurfaceMesh flat(double L, int n) {
  return wear::meshes::structured_grid(
      n, n,
      [L](double u, double v) {
        return Vec3{-L + 2 * L * u, -L + 2 * L * v, 0};
      },
      false, wear::meshes::label::base, wear::meshes::Diagonals::uniform);
}
} // namespace

TEST_CASE("wear integrals: per-face sums equal per-contact totals", "[dem][wear]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  const int w = s.add_wall(MeshWall(flat(0.05, 8), g, {}, true, "sample"));
  // A particle sliding diagonally over many faces, edges and vertices of the mesh.
  const double r = 4e-3;
  s.particles.add({-0.04, -0.04, r - 1e-5}, {0.5, 0.5, 0}, r, 2650, g);
  s.setup();
  s.run(4000);
  const auto wi = s.wear_integrals(w);
  double archard = 0, fn = 0, work = 0, steps = 0;
  Vec3 impulse{};
  std::size_t n_faces_hit = 0;
  for (std::size_t f = 0; f < wi.archard.size(); ++f) {
    archard += wi.archard[f];
    fn += wi.normal_impulse[f];
    work += wi.sliding_work[f];
    impulse += wi.impulse[f];
    steps += wi.contact_steps[f];
    n_faces_hit += wi.contact_steps[f] > 0;
  }
  CHECK(n_faces_hit >= 6);
  CHECK(wi.total_archard > 0);
  CHECK(archard == Approx(wi.total_archard).epsilon(1e-12));
  CHECK(fn == Approx(wi.total_normal_impulse).epsilon(1e-12));
  CHECK(work == Approx(wi.total_sliding_work).epsilon(1e-12));
  CHECK(norm(impulse - wi.total_impulse) < 1e-12 * norm(wi.total_impulse));
  // One contact per step, however it is shared: the fractional counts add up to whole steps.
  CHECK(std::abs(steps - std::round(steps)) < 1e-9);
  CHECK(steps > 3000);
  CHECK(steps <= 4000);
  s.reset_wear_integrals();
  CHECK(s.wear_integrals(w).total_archard == 0);
}

TEST_CASE("wear integrals: Archard load-distance of a particle on a moving face", "[dem][wear]") {
  // The face moves under a particle held in place by its own weight on a conveyor-like
  // surface velocity; once sliding is steady, F_n = m g and |v_t| is the slip speed.
  System s;
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {0.5, 0.0, 0.0}); // frictionless: the particle stays put
  WallMotion conveyor;
  conveyor.surface_velocity = {0.3, 0, 0};
  const int w = s.add_wall(MeshWall(flat(0.05, 4), g, conveyor, true, "sample"));
  const double r = 4e-3, m = 2650 * 4.0 / 3.0 * pi * r * r * r;
  const double e_star = 1 / (2 * (1 - 0.0625) / 5e7);
  const double delta = std::pow(m * 9.81 / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);
  s.particles.add({0.013, 0.007, r - delta}, {}, r, 2650, g); // over an interior edge region
  s.setup();
  s.run(1000);
  const double t = s.time();
  const auto wi = s.wear_integrals(w);
  CHECK(wi.total_archard == Approx(m * 9.81 * 0.3 * t).epsilon(0.005));
  CHECK(wi.total_normal_impulse == Approx(m * 9.81 * t).epsilon(0.005));
}

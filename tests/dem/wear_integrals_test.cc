// Wearing walls: per-face integrals sum to the per-contact totals (the Archard volume of a
// particle held on a moving face is tested in wear_law_test.cc).
#include "meshes/structured_grid.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::Vec3;

TEST_CASE("wear integrals: per-face sums (moments included) equal per-contact totals",
          "[dem][wear]") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  const int w = s.add_wall(MeshWall(flat_square(0.05, 8), g, {}, true, "sample"));
  // A particle sliding diagonally over many faces, edges and vertices of the mesh.
  const double r = 4e-3;
  s.particles.add({-0.04, -0.04, r - 1e-5}, {0.5, 0.5, 0}, r, 2650, g);
  s.setup();
  s.run(4000);
  const auto wi = s.wear_integrals(w);
  double archard = 0, fn = 0, work = 0, steps = 0;
  Vec3 impulse{}, normal_moment{}, moment{};
  std::size_t n_faces_hit = 0;
  for (std::size_t f = 0; f < wi.archard.size(); ++f) {
    archard += wi.archard[f];
    fn += wi.normal_impulse[f];
    work += wi.sliding_work[f];
    impulse += wi.impulse[f];
    normal_moment += wi.normal_moment[f];
    moment += wi.impulse_moment[f];
    steps += wi.contact_steps[f];
    n_faces_hit += wi.contact_steps[f] > 0;
  }
  CHECK(n_faces_hit >= 6);
  CHECK(wi.total_archard > 0);
  CHECK(archard == Approx(wi.total_archard).epsilon(1e-12));
  CHECK(fn == Approx(wi.total_normal_impulse).epsilon(1e-12));
  CHECK(work == Approx(wi.total_sliding_work).epsilon(1e-12));
  CHECK(norm(impulse - wi.total_impulse) < 1e-12 * norm(wi.total_impulse));
  CHECK(norm(normal_moment - wi.total_normal_moment) < 1e-12 * norm(wi.total_normal_moment));
  CHECK(norm(moment - wi.total_impulse_moment) < 1e-12 * norm(wi.total_impulse_moment));
  // The contacts lie on the plate z = 0, so the normal-load centroid does too.
  CHECK(std::abs(wi.total_normal_moment.z) <= 1e-15 * norm(wi.total_normal_moment));
  // One contact per step, however it is shared: the fractional counts add up to whole steps.
  CHECK(std::abs(steps - std::round(steps)) < 1e-9);
  CHECK(steps > 3000);
  CHECK(steps <= 4000);
  s.reset_wear_integrals();
  CHECK(s.wear_integrals(w).total_archard == 0);
}

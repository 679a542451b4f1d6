// A clump fitted to a closed surface (dem/scene/clump_fit.cc): a sphere's surface gives one
// member of its radius and centre (to the grid's spacing and the facets' sag); a 2 : 1 : 1 block
// is packed with inscribed spheres whose union stays inside it and whose volume error falls with
// each member to below the error asked for; an error that the member count cannot reach, and a
// surface that encloses nothing, are refused by name.
#include "dem/scene/clump_fit.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear::dem;
namespace shapes = wear::meshes::testing;

TEST_CASE("a sphere's surface is fitted by one sphere of its size", "[dem][clump]") {
  const double r = 5e-3;
  ClumpFitParameters p;
  p.volume_error = 0.01;
  const ClumpFit fit = fit_clump(shapes::icosphere(r, 4), p, "sphere.stl");
  REQUIRE(fit.clump.members.size() == 1);
  const double h = 2 * r / p.cells_per_extent;
  CHECK(wear::meshes::norm(fit.clump.members[0].centre) < h);
  CHECK(std::abs(fit.clump.members[0].radius - r) < 2 * h);
  CHECK(fit.volume_error < 0.01);
}

TEST_CASE("a block is packed with inscribed spheres to the volume error asked for",
          "[dem][clump]") {
  const double a = 0.02, b = 0.01, c = 0.01; // [m]
  const auto block = shapes::box(a, b, c);
  ClumpFitParameters p;
  p.volume_error = 0.42; // a block's corners are what inscribed spheres leave out
  const ClumpFit fit = fit_clump(block, p, "block.stl");
  CAPTURE(fit.clump.members.size(), fit.volume_error);
  CHECK(std::abs(fit.solid_volume - a * b * c) < 1e-12 * a * b * c);
  CHECK(fit.volume_error < 0.42);
  CHECK(fit.clump.members.size() >= 2);
  const double h = a / p.cells_per_extent;
  for (const auto& m : fit.clump.members) {
    CHECK(m.centre.x - m.radius > -h);
    CHECK(m.centre.x + m.radius < a + h);
    CHECK(m.centre.y - m.radius > -h);
    CHECK(m.centre.y + m.radius < b + h);
    CHECK(m.centre.z - m.radius > -h);
    CHECK(m.centre.z + m.radius < c + h);
  }
  // Each member covers what the others left: the error falls with the member count.
  double last = 1;
  for (int n = 1; n <= int(fit.clump.members.size()); ++n) {
    ClumpTemplate first_n{"first", {fit.clump.members.begin(), fit.clump.members.begin() + n}};
    const double error =
        std::abs(clump_shape(first_n).volume - fit.solid_volume) / fit.solid_volume;
    CHECK(error < last);
    last = error;
  }
}

TEST_CASE("a fit that cannot reach its error, or a surface that encloses nothing, is refused",
          "[dem][clump]") {
  ClumpFitParameters p;
  p.max_spheres = 2;
  p.volume_error = 0.01;
  CHECK_THROWS_WITH(fit_clump(shapes::box(0.02, 0.01, 0.01), p, "block.stl"),
                    Catch::Contains("block.stl: 2 inscribed spheres leave a volume error of"));
  auto inverted = shapes::box(0.02, 0.01, 0.01);
  for (auto& t : inverted.triangles)
    std::swap(t[1], t[2]);
  CHECK_THROWS_WITH(fit_clump(inverted, {}, "inside-out.stl"),
                    Catch::Contains("inside-out.stl encloses no volume"));
}

// Exact triangle-region tests (meshes/triangle_geometry.h, meshes/solid_region.h) that decide
// whether a scene's fill region cuts a wall: set cases on either side of the boundary, and random
// triangles against dense point sampling (a sampled point inside the region must make the test
// true; a test that says false must have every sample outside).
#include "meshes/constants.h"
#include "meshes/solid_region.h"
#include "meshes/triangle_geometry.h"
#include "test_shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

using namespace wear::meshes;

namespace {

bool in_cylinder(const Vec3& x, const Vec3& base, const Vec3& u, double length, double r) {
  const Vec3 d = x - base;
  const double s = dot(d, u);
  return s >= 0 && s <= length && norm(d - u * s) <= r;
}

bool in_box(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  return x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z;
}

// Whether any of the triangle's 861 barycentric grid points lies in the region.
template <typename Inside>
bool sampled(const Vec3& a, const Vec3& b, const Vec3& c, const Inside& inside) {
  const int n = 40;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      if (inside(a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n)))
        return true;
  return false;
}

} // namespace

TEST_CASE("triangle and cylinder: either side of the mantle, the caps, parallel faces",
          "[meshes]") {
  const Vec3 base{0, 0, 0}, u{0, 0, 1};
  const double L = 1, r = 0.5, e = 1e-9;
  const auto cuts = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    return triangle_intersects_cylinder(a, b, c, base, u, L, r);
  };
  // A large horizontal triangle through the axis, within and beyond the slab.
  CHECK(cuts({-5, -5, 0.5}, {5, -5, 0.5}, {0, 5, 0.5}));
  CHECK_FALSE(cuts({-5, -5, 1 + e}, {5, -5, 1 + e}, {0, 5, 1 + e}));
  CHECK_FALSE(cuts({-5, -5, -e}, {5, -5, -e}, {0, 5, -e}));
  // A vertical triangle parallel to the axis (its projection is a segment), just outside and
  // just inside the mantle.
  CHECK_FALSE(cuts({r + e, -1, 0}, {r + e, 1, 0}, {r + e, 0, 1}));
  CHECK(cuts({r - e, -1, 0}, {r - e, 1, 0}, {r - e, 0, 1}));
  // A triangle beside the cylinder reaching in with one corner, or not quite.
  CHECK(cuts({r - e, 0, 0.5}, {2, 1, 0.5}, {2, -1, 0.2}));
  CHECK_FALSE(cuts({r + e, 0, 0.5}, {2, 1, 0.5}, {2, -1, 0.2}));
  // With a hole of radius 0.4: a triangle wholly inside the hole does not cut the annulus,
  // one reaching from the hole past the mantle does.
  CHECK_FALSE(triangle_intersects_cylinder({-0.1, -0.1, 0.5}, {0.1, -0.1, 0.5}, {0, 0.1, 0.5}, base,
                                           u, L, r, 0.4));
  CHECK(
      triangle_intersects_cylinder({0, 0, 0.5}, {2, 0.1, 0.5}, {2, -0.1, 0.5}, base, u, L, r, 0.4));
  // A floor a millimetre below the base does not cut it; the base's own plane touches it.
  CHECK_FALSE(cuts({-5, -5, -1e-3}, {5, -5, -1e-3}, {0, 5, -1e-3}));
  CHECK(cuts({-5, -5, 0}, {5, -5, 0}, {0, 5, 0}));
}

TEST_CASE("triangle and cylinder or box: random triangles agree with dense sampling", "[meshes]") {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> x(-1.5, 1.5), angle(0, wear::pi);
  int n_true = 0, n_false = 0, n_unsampled = 0;
  for (int k = 0; k < 2000; ++k) {
    const double t = angle(rng), p = 2 * angle(rng);
    const Vec3 u{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
    const Vec3 base{x(rng) * 0.2, x(rng) * 0.2, x(rng) * 0.2};
    const double L = 0.5 + 0.3 * x(rng) / 1.5, r = 0.3 + 0.1 * x(rng) / 1.5;
    const Vec3 a{x(rng), x(rng), x(rng)}, b{x(rng), x(rng), x(rng)}, c{x(rng), x(rng), x(rng)};
    const bool cut = triangle_intersects_cylinder(a, b, c, base, u, L, r);
    const bool hit = sampled(a, b, c, [&](const Vec3& q) { return in_cylinder(q, base, u, L, r); });
    if (hit)
      REQUIRE(cut); // a point inside: the test cannot miss it
    (cut ? n_true : n_false)++;
    n_unsampled += cut && !hit; // a graze between the samples, or a wrong "true"
    const Vec3 lo{-0.4, -0.3, -0.2}, hi{0.3, 0.4, 0.5};
    if (sampled(a, b, c, [&](const Vec3& q) { return in_box(q, lo, hi); }))
      REQUIRE(triangle_intersects_box(a, b, c, lo, hi));
  }
  // Both outcomes occur often, so the comparison means something.
  CHECK(n_true > 200);
  CHECK(n_false > 200);
  // "True" without a sampled point only where the triangle grazes the region.
  CHECK(n_unsampled < n_true / 20);
}

TEST_CASE("solid region of a closed mesh: inside, distance and cutting triangles are exact",
          "[meshes]") {
  const SurfaceMesh cube = testing::box(0.2, 0.1, 0.05); // [0, 0.2] x [0, 0.1] x [0, 0.05]
  const SolidRegion solid(cube, "test cube");
  CHECK(solid.volume() == Approx(0.2 * 0.1 * 0.05).epsilon(1e-12));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(-0.05, 0.25), y(-0.05, 0.15), z(-0.05, 0.1);
  int n_inside = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 p{x(rng), y(rng), z(rng)};
    const Vec3 lo{0, 0, 0}, hi{0.2, 0.1, 0.05};
    const bool inside = in_box(p, lo, hi);
    REQUIRE(solid.contains(p) == inside);
    n_inside += inside;
    if (inside) { // the distance to the nearest face
      const double d = std::min({p.x, 0.2 - p.x, p.y, 0.1 - p.y, p.z, 0.05 - p.z});
      REQUIRE(solid.distance(p) == Approx(d).margin(1e-12));
    }
    // A small triangle around p cuts the solid exactly when it reaches into the box.
    const Vec3 a = p + Vec3{0.01, 0, 0}, b = p + Vec3{0, 0.01, 0}, c = p + Vec3{0, 0, 0.01};
    const bool hit = sampled(a, b, c, [&](const Vec3& q) { return in_box(q, lo, hi); });
    if (hit)
      REQUIRE(solid.cuts(a, b, c));
  }
  CHECK(n_inside > 300);
  // A large triangle through the middle with every vertex outside still cuts it.
  CHECK(solid.cuts({-1, -1, 0.02}, {1, -1, 0.02}, {0, 1, 0.02}));
  CHECK_FALSE(solid.cuts({-1, -1, 0.06}, {1, -1, 0.06}, {0, 1, 0.06}));
  // An open surface is no solid.
  SurfaceMesh open = cube;
  open.triangles.pop_back();
  open.face_labels.pop_back();
  CHECK_THROWS_WITH(SolidRegion(open, "Scene/Fill (File = open.stl)"),
                    Catch::Contains("Scene/Fill (File = open.stl): a fill region from a mesh "
                                    "must be a closed solid"));
}
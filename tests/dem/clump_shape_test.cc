// The mass properties of a clump's union of spheres (dem/engine/clump_shape.cc) against the
// analytic values of unions whose members do not overlap (a sphere, two touching spheres, three
// touching spheres in a triangle: the parallel-axis sums), of two coincident spheres (the mass of
// one) and of two overlapping spheres (the sphere pair minus the lens). The relative tolerance is
// the one docs/theory.md states for 200 columns per radius: 1e-3 (the measured error is about
// 1e-5).
#include "dem/engine/clump_shape.h"
#include "meshes/constants.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using namespace wear::dem;
using wear::meshes::Vec3;

namespace {

constexpr double r = 2e-3; // [m] a gravel grain's member
constexpr double tolerance = 1e-3;
const double v_sphere = 4.0 / 3.0 * wear::pi * r * r * r;

double relative(double value, double exact) {
  return std::abs(value - exact) / std::abs(exact);
}

} // namespace

TEST_CASE("a clump's union of spheres has the analytic volume, centre and principal moments",
          "[dem][clump]") {
  SECTION("one sphere: V = 4/3 pi r^3, I = 2/5 V r^2 about every axis") {
    const ClumpShape s = clump_shape({"sphere", {{{0.01, -0.02, 0.003}, r}}});
    CHECK(relative(s.volume, v_sphere) < tolerance);
    for (int k = 0; k < 3; ++k)
      CHECK(relative(s.moments[k], 0.4 * v_sphere * r * r) < tolerance);
    CHECK(wear::meshes::norm(s.centre - Vec3{0.01, -0.02, 0.003}) < 1e-6 * r);
    CHECK(relative(s.equivalent_diameter(), 2 * r) < tolerance);
  }
  SECTION("two touching spheres along an oblique line: the smallest moment about that line") {
    const Vec3 e = wear::meshes::normalized(Vec3{1, 2, -2});
    const ClumpShape s = clump_shape({"pair", {{e * r, r}, {e * -r, r}}});
    const double i_axis = 2 * 0.4 * v_sphere * r * r;
    const double i_across = 2 * (0.4 * v_sphere * r * r + v_sphere * r * r);
    CHECK(relative(s.volume, 2 * v_sphere) < tolerance);
    CHECK(relative(s.moments[0], i_axis) < tolerance);
    CHECK(relative(s.moments[1], i_across) < tolerance);
    CHECK(relative(s.moments[2], i_across) < tolerance);
    CHECK(std::abs(std::abs(wear::meshes::dot(s.axis[0], e)) - 1) < 1e-9);
    CHECK(wear::meshes::norm(s.centre) < 1e-6 * r);
    // The members in the body frame lie on its first axis, r from the centre.
    for (const auto& m : s.members)
      CHECK(std::abs(std::abs(m.centre.x) - r) < 1e-6 * r);
    CHECK(relative(s.reach(), 2 * r) < 1e-6);
  }
  SECTION("three touching spheres in a triangle: the largest moment about its normal") {
    const double d = 2 * r / std::sqrt(3.0); // centre to centroid
    ClumpTemplate t{"triangle", {}};
    for (int k = 0; k < 3; ++k) {
      const double a = wear::pi / 2 + 2 * wear::pi * k / 3;
      t.members.push_back({{d * std::cos(a), d * std::sin(a), 0}, r});
    }
    const ClumpShape s = clump_shape(t);
    const double i_normal = 3 * (0.4 * v_sphere * r * r + v_sphere * d * d);
    const double i_in_plane = 3 * 0.4 * v_sphere * r * r + v_sphere * 1.5 * d * d;
    CHECK(relative(s.volume, 3 * v_sphere) < tolerance);
    CHECK(relative(s.moments[0], i_in_plane) < tolerance);
    CHECK(relative(s.moments[1], i_in_plane) < tolerance);
    CHECK(relative(s.moments[2], i_normal) < tolerance);
    CHECK(std::abs(std::abs(s.axis[2].z) - 1) < 1e-9);
  }
  SECTION("overlaps count once: two coincident spheres have the mass of one") {
    const ClumpShape s = clump_shape({"twice", {{{0, 0, 0}, r}, {{0, 0, 0}, r}}});
    CHECK(relative(s.volume, v_sphere) < tolerance);
    CHECK(relative(s.moments[2], 0.4 * v_sphere * r * r) < tolerance);
  }
  SECTION(
      "two spheres a radius apart: the pair's volume less the lens, pi (4r + d)(2r - d)^2 / 12") {
    const ClumpShape s = clump_shape({"overlapping", {{{0, 0, 0}, r}, {{0, 0, r}, r}}});
    const double lens = wear::pi * (4 * r + r) * r * r / 12;
    CHECK(relative(s.volume, 2 * v_sphere - lens) < tolerance);
    CHECK(std::abs(s.centre.z - 0.5 * r) < 1e-6 * r);
  }
}

TEST_CASE("a clump scales as its length: volume by s^3, moments by s^5", "[dem][clump]") {
  const ClumpShape s = clump_shape({"pair", {{{r, 0, 0}, r}, {{-r, 0, 0}, 0.5 * r}}});
  const ClumpShape big = s.scaled(2.5);
  CHECK(relative(big.volume, s.volume * std::pow(2.5, 3)) < 1e-12);
  CHECK(relative(big.moments.y, s.moments.y * std::pow(2.5, 5)) < 1e-12);
  CHECK(relative(big.equivalent_diameter(), 2.5 * s.equivalent_diameter()) < 1e-12);
  CHECK(relative(big.reach(), 2.5 * s.reach()) < 1e-12);
}

TEST_CASE("a clump template without members or with a bad radius is refused by name",
          "[dem][clump]") {
  CHECK_THROWS_WITH(clump_shape({"empty", {}}), Catch::Contains("'empty' has no member"));
  CHECK_THROWS_WITH(clump_shape({"flat", {{{0, 0, 0}, r}, {{r, 0, 0}, 0}}}),
                    Catch::Contains("'flat': member 2 has the radius"));
  CHECK_THROWS_WITH(clump_shape({"lost", {{{NAN, 0, 0}, r}}}),
                    Catch::Contains("member 1 has a centre that is not finite"));
}

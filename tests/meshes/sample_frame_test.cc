#include "meshes/constants.h"
#include "meshes/sample_frame.h"

#include <catch2/catch.hpp>

#include <cmath>

using wear::meshes::SampleFrame;
using wear::meshes::Vec3;

namespace {
SampleFrame inclined_frame() {
  wear::meshes::SampleGeometry s;
  wear::meshes::SamplePlacement pl;
  pl.incline_deg = 7;
  pl.angle_deg = 40;
  return SampleFrame(s, pl);
}
} // namespace

// A vector (force, impulse) is rotated, never translated: the map of a vector equals the
// difference of the maps of two points it joins, and its length is kept (to round-off).
TEST_CASE("sample frame: vectors rotate, points rotate and translate", "[sample_frame]") {
  const SampleFrame f = inclined_frame();
  const Vec3 a{0.013, -0.021, 0.004}, b{-0.030, 0.045, 0.017};
  const Vec3 v = b - a;
  const Vec3 mapped = f.vector_to_tester(v);
  const Vec3 through_points = f.point_to_tester(b) - f.point_to_tester(a);
  CHECK(norm(mapped - through_points) < 1e-15);
  CHECK(norm(mapped) == Approx(norm(v)).epsilon(1e-14));
  CHECK(norm(f.vector_to_tester({0, 0, 0})) == 0);
  CHECK(norm(f.point_to_tester({0, 0, 0})) > 0.1); // the origin moves
  CHECK(norm(f.vector_to_sample(mapped) - v) < 1e-16);
  CHECK(norm(f.point_to_sample(f.point_to_tester(a)) - a) < 1e-15);
}

// The inverse maps undo the forward ones, and the wear face's centre lands at the placement.
TEST_CASE("sample frame: wear-face centre at the placement", "[sample_frame]") {
  wear::meshes::SampleGeometry s;
  wear::meshes::SamplePlacement pl;
  pl.incline_deg = 3;
  const SampleFrame f(s, pl);
  const Vec3 c = f.point_to_tester({0, 0, s.thickness});
  CHECK(std::hypot(c.x, c.y) == Approx(pl.radius).epsilon(1e-14));
  CHECK(c.z == Approx(pl.wear_face_height).epsilon(1e-14));
  CHECK(std::atan2(c.y, c.x) * 180 / wear::pi == Approx(pl.angle_deg).epsilon(1e-14));
}

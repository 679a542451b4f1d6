// The tester's evaluation of the bed over the sample (dem/evaluation/tester_evaluation.h) with
// spheres and clumps: a clump counts as one grain, with its centre's speed, the body's angular
// speed and the least gap of its members, never as its member spheres (whose point speeds
// carry the body's rotation, omega x arm). On a plain sample: a sphere and a two-member clump
// in the bottom layer and a sphere above it; the revolution's bottom-layer speed, spin and
// count against the values set, to round-off, and the member-wise reading they replace.
#include "dem/evaluation/tester_evaluation.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear;
using namespace wear::dem;
using meshes::Vec3;

TEST_CASE("the tester's evaluation reads a clump as one grain: its centre's speed, the body's "
          "spin, its lowest member's gap",
          "[dem][clump][evaluation]") {
  meshes::SampleGeometry g;
  g.convex = false;
  const meshes::SamplePlacement placement;
  const meshes::SampleFrame frame(g, placement);
  auto sample = meshes::testing::height_field_block(
      10, 12, g.width, g.length, [&](double, double) { return g.thickness; },
      [](double, double) { return meshes::label::base; });
  for (auto& x : sample.vertices)
    x = x - Vec3{g.width / 2, g.length / 2, 0};
  meshes::SurfaceMesh placed = sample;
  for (auto& x : placed.vertices)
    x = frame.point_to_tester(x);
  const double layer = 4e-3, t = g.thickness;
  TesterEvaluation evaluation(sample, g, placement, layer, 0.05, 2);

  Particles p;
  const auto at = [&](double x, double y, double z) { return frame.point_to_tester({x, y, z}); };
  // A sphere in the bottom layer (gap 0.5 mm) and one above it (gap 10 mm).
  p.add(at(0.01, 0.02, t + 1.5e-3), {0.3, 0, 0}, 1e-3, 950, 0);
  p.angular_velocity.back() = {0, 5, 0};
  p.add(at(0.02, -0.03, t + 11e-3), {0, 0.5, 0}, 1e-3, 950, 0);
  // A clump of two 1 mm members 2.4 mm apart along the sample's x, its centre 2 mm above the
  // base top (its
  // members' lowest points 1 mm above it), moving at 0.2 m/s along its axis and turning at
  // 40 rad/s about the tester's z: its members' points move at |v + omega x arm| = 0.2057 m/s.
  for (int k = 0; k < 2; ++k)
    p.add({0, 0, 0}, {0, 0, 0}, 1e-3, 950, 0);
  for (std::size_t i = 0; i < p.n_real; ++i)
    p.id[i] = std::int64_t(i);
  Clumps clumps;
  const double moment = 1e-9;                           // [kg m^2] principal, about every axis
  const Vec3 along = frame.vector_to_tester({1, 0, 0}); // the members' axis, and the motion
  clumps.add_body(at(-0.01, -0.02, t + 2e-3), along * 0.2, {1, 0, 0, 0}, {0, 0, 40 * moment}, 2e-6,
                  {moment, moment, moment}, {2, 3}, {along * -1.2e-3, along * 1.2e-3});
  std::vector<std::int64_t> slot_of_id;
  std::vector<std::int32_t> body_of_slot;
  clumps.index_members(p, slot_of_id, body_of_slot);
  clumps.place_members(0, p);
  REQUIRE(meshes::norm(p.angular_velocity[2]) == Approx(40).epsilon(1e-12));

  const std::vector<double> zero(sample.n_faces(), 0.0);
  const auto revolution = [&](const Clumps* c) {
    TesterEvaluation e = evaluation;
    e.begin_revolution(0);
    const BedGrains grains = e.grains(p, c, placed);
    e.sample(grains, 0.1, zero, zero);
    return std::make_pair(grains, e.end_revolution(0.1, zero, 0));
  };
  const auto [grains, r] = revolution(&clumps);
  REQUIRE(grains.size() == 3);
  CHECK(grains.gap[2] == Approx(1e-3).epsilon(1e-9));
  CHECK(grains.top[2] == Approx(t + 3e-3).epsilon(1e-9));
  CHECK(r.bottom_count == 2);
  CHECK(r.bottom_speed.mean == Approx((0.3 + 0.2) / 2).epsilon(1e-12));
  CHECK(r.bottom_spin.mean == Approx((5 + 40) / 2.0).epsilon(1e-12));
  CHECK(r.speed_over_sample.mean == Approx((0.3 + 0.5 + 0.2) / 3).epsilon(1e-12));

  // Read member by member (no clumps given) the body counts twice, at its points' speed.
  const auto [members, m] = revolution(nullptr);
  CHECK(members.size() == 4);
  CHECK(m.bottom_count == 3);
  const double points = meshes::norm(p.velocity[2]) + meshes::norm(p.velocity[3]);
  CHECK(points > 2 * 0.2 + 1e-3); // |v + u| + |v - u| > 2 |v|: the rotation counted as flow
  CHECK(m.bottom_speed.mean == Approx((0.3 + points) / 3).epsilon(1e-12));
  CHECK(m.bottom_spin.mean == Approx((5 + 2 * 40) / 3.0).epsilon(1e-12));
}

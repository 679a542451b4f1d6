// The candidate search of a triangle wall against brute force, on the reference convex sample
// as the tester places it (60,180 triangles at 1 mm, curved element caps, the incline): the
// wall's grid must return every face within reach of a point, and a set-up System must list
// for each particle every face within radius + skin/2. Complements "every wall face a
// particle touches is among its listed candidates" (system_test.cc), which follows a moving
// bed on the coarse tester walls and compares with the grid, not with all faces.
#include "dem/engine/filling.h"
#include "dem/engine/system.h"
#include "meshes/sample_frame.h"
#include "meshes/sample_generator.h"
#include "meshes/surface_locator.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

using namespace wear::dem;
using wear::meshes::norm;
using wear::meshes::Vec3;

namespace {
// The reference convex sample's surface, in the tester frame (generated once: a few seconds).
const wear::meshes::SurfaceMesh& placed_reference_sample() {
  static const wear::meshes::SurfaceMesh placed = [] {
    wear::meshes::GeometryParameters g;
    g.sample.volume_mesh = false;
    const auto sample = wear::meshes::generate_sample(g.sample);
    return wear::meshes::SampleFrame(g.sample, g.placement).place_in_tester(sample.surface);
  }();
  return placed;
}

// Points in and around the sample's bounding box widened by 2 reach (some beyond the grid),
// and as many within 1.5 reach of a random face centroid (most of them near the surface).
std::vector<Vec3> query_points(const wear::meshes::SurfaceMesh& m, double reach, int n) {
  const auto box = wear::meshes::bounding_box(m);
  const Vec3 margin{2 * reach, 2 * reach, 2 * reach};
  const Vec3 lo = box.min - margin, ext = box.max + margin - lo;
  std::mt19937 rng(20301);
  std::uniform_real_distribution<double> u(0, 1), v(-1, 1);
  std::uniform_int_distribution<std::size_t> face(0, m.n_faces() - 1);
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k) {
    points.push_back({lo.x + ext.x * u(rng), lo.y + ext.y * u(rng), lo.z + ext.z * u(rng)});
    const auto& t = m.triangles[face(rng)];
    const Vec3 c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) * (1.0 / 3.0);
    points.push_back(c + Vec3{v(rng), v(rng), v(rng)} * (1.5 * reach));
  }
  return points;
}
} // namespace

TEST_CASE("the sample wall's candidate grid returns every face within reach, as brute force",
          "[dem][walls]") {
  const auto& mesh = placed_reference_sample();
  REQUIRE(mesh.n_faces() > 50000);
  // 6.5 mm: r_max + skin at s = 3; 1.2 mm: about one triangle, the finest grid.
  for (const double reach : {6.5e-3, 1.2e-3}) {
    INFO("reach " << reach << " m");
    MeshWall wall(mesh, 0, {}, true, "sample");
    wall.build_grid(reach);
    std::size_t n_within = 0, n_points_near = 0, n_differ = 0, n_duplicates = 0;
    for (const Vec3& c : query_points(mesh, reach, 1000)) {
      const auto within = [&](std::uint32_t f) {
        return norm(wall.closest(f, c).point - c) < reach;
      };
      const auto [b, e] = wall.candidates(c);
      const std::set<std::uint32_t> listed(b, e);
      n_duplicates += listed.size() != std::size_t(e - b);
      std::set<std::uint32_t> by_grid, by_brute;
      for (const std::uint32_t f : listed)
        if (within(f))
          by_grid.insert(f);
      for (std::uint32_t f = 0; f < mesh.n_faces(); ++f)
        if (within(f))
          by_brute.insert(f);
      n_differ += by_grid != by_brute;
      n_within += by_brute.size();
      n_points_near += !by_brute.empty();
    }
    CHECK(n_differ == 0);
    CHECK(n_duplicates == 0);
    INFO(n_points_near << " of 2000 points within reach of " << n_within << " faces in all");
    CHECK(n_points_near > 500); // the queries do reach the surface, with several faces each
    CHECK(n_within > 3 * n_points_near);
  }
}

TEST_CASE("after setup every sample face within radius + skin/2 is listed for its particle",
          "[dem][walls]") {
  // The rebuild's definition of a particle's candidate faces, checked against all faces: the
  // largest particles at s = 3 (10.05 mm) with their centres 0 to 1.5 mm beyond touching the
  // sample, a skin of 1.5 mm (the default at s = 3), the sample as the tester's wearing wall.
  // About half the particles lie within reach of some face. No listed face may lie beyond
  // that reach either.
  const auto& mesh = placed_reference_sample();
  System s;
  const int g = s.materials.add({"gravel", 2.5e8, 0.25, 2650});
  s.materials.set_pair(g, g, {0.5, 0.5, 0.1});
  s.add_wall(MeshWall(mesh, g, {}, true, "sample"));
  const wear::meshes::SurfaceLocator locator(mesh);
  const SizeDistribution psd{{3.35e-3}, {1.0}, 3};
  const auto box = wear::meshes::bounding_box(mesh);
  const double r = 0.5 * psd.max_diameter(), skin = 1.5e-3;
  const Vec3 margin{2 * r, 2 * r, 2 * r};
  const FillRegion region{box.min - margin, box.max + margin, [&](const Vec3& x) {
                            const double d = locator.nearest(x).distance;
                            return d > r && d < r + skin;
                          }};
  insert_random(s.particles, region, psd, 150, 2650, g, 7);
  REQUIRE(s.particles.n_real == 150);
  s.settings.gravity = {0, 0, 0};
  s.settings.skin = skin;
  s.settings.domain = {box.min - margin * 2, box.max + margin * 2};
  s.setup();
  const double half_skin = 0.5 * skin;
  const auto& p = s.particles;
  std::size_t n_within = 0, n_missing = 0, n_beyond = 0, n_near = 0;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const double reach = p.radius[i] + half_skin;
    const auto [b, e] = s.wall_candidates(i);
    const std::set<std::uint32_t> listed(b, e);
    bool near = false;
    for (std::uint32_t f = 0; f < mesh.n_faces(); ++f) {
      const double d = norm(s.wall(0).closest(f, p.position[i]).point - p.position[i]);
      const bool is_listed = listed.count(f) > 0; // wall 0: the key is the face itself
      n_missing += d < reach && !is_listed;
      n_beyond += is_listed && d >= reach * (1 + 1e-6);
      n_within += d < reach;
      near = near || d < reach;
    }
    n_near += near;
  }
  CHECK(n_missing == 0);
  CHECK(n_beyond == 0);
  INFO(n_near << " particles within reach of " << n_within << " faces in all");
  CHECK(n_near > 50); // some particles lie within reach, with several faces each,
  CHECK(n_within > 3 * n_near);
  CHECK(n_near < 140); // and some do not
}

// A scene's discs and open cylinders as exact surfaces of revolution (revolution_surface,
// dem/scene/scene_walls.h): the closest point the engine's wall gives for a tilted cylinder
// and a tilted annulus with its hole against the analytic one (1e-12 m over random points
// inside, outside and beyond the ends and rims), which walls are exact and which stay
// triangles, and a scene's run holding them as revolution walls.
#include "dem/scene/scene_run.h"
#include "dem/scene/scene_walls.h"
#include "meshes/constants.h"
#include "scene_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace wear::dem;
using wear::meshes::dot;
using wear::meshes::norm;
using wear::meshes::normalized;
using wear::meshes::Vec3;

namespace {

SceneWallParameters tilted(const std::string& source) {
  SceneWallParameters w;
  w.name = source;
  w.source = source;
  w.origin = {0.1, -0.2, 0.3};
  w.axis = {0.0, 0.3, 0.4}; // 0.5 m long, tilted 37 degrees from z
  w.radius = 0.08;
  w.radius_inner = 0.025;
  return w;
}

/// Random points within 0.2 m of the wall's origin, so beyond its ends and rims too.
std::vector<Vec3> points_around(const Vec3& o) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 0.6);
  std::vector<Vec3> x;
  for (int k = 0; k < 2000; ++k)
    x.push_back(o + Vec3{u(rng) - 0.2, u(rng) - 0.2, u(rng) - 0.2});
  return x;
}

} // namespace

TEST_CASE("scene walls: a tilted open cylinder is exact: its closest points are the analytic "
          "ones to 1e-12 m") {
  const SceneWallParameters w = tilted("cylinder");
  const auto surface = revolution_surface(w);
  REQUIRE(surface);
  const RevolutionWall wall(*surface, 0, {}, false, w.name);
  const Vec3 o{0.1, -0.2, 0.3}, a = normalized(Vec3{0, 0.3, 0.4});
  for (const Vec3& c : points_around(o)) {
    const Vec3 d = c - o;
    const double s = std::clamp(dot(d, a), 0.0, 0.5);
    const Vec3 q = d - a * dot(d, a);
    const Vec3 expected = o + a * s + q * (0.08 / norm(q));
    REQUIRE(norm(wall.closest(c) - expected) < 1e-12);
  }
}

TEST_CASE("scene walls: a tilted disc with a hole is an exact annulus: its closest points are "
          "the analytic ones to 1e-12 m") {
  const SceneWallParameters w = tilted("disc");
  const auto surface = revolution_surface(w);
  REQUIRE(surface);
  const RevolutionWall wall(*surface, 0, {}, false, w.name);
  const Vec3 o{0.1, -0.2, 0.3}, a = normalized(Vec3{0, 0.3, 0.4});
  for (const Vec3& c : points_around(o)) {
    const Vec3 q = (c - o) - a * dot(c - o, a); // in the disc's plane
    const double rho = norm(q);
    const Vec3 expected = o + q * (std::clamp(rho, 0.025, 0.08) / rho);
    REQUIRE(norm(wall.closest(c) - expected) < 1e-12);
  }
}

TEST_CASE("scene walls: only a disc, an open cylinder or an open cone that keeps its place and "
          "does not wear is exact") {
  SceneWallParameters w = tilted("cylinder");
  CHECK(revolution_surface(w));
  w.motion = "surface rotation"; // the geometry stays; only its surface moves
  CHECK(revolution_surface(w));
  w.motion = "surface translation";
  CHECK(revolution_surface(w));
  for (const char* rigid : {"rotation", "translation", "oscillation"}) {
    w.motion = rigid;
    CHECK_FALSE(revolution_surface(w));
  }
  w.motion = "fixed";
  w.caps = true; // a closed solid: its end discs are faces of the same wall
  CHECK_FALSE(revolution_surface(w));
  w.caps = false;
  w.wears = true; // a wearing part's surface changes stage by stage
  CHECK_FALSE(revolution_surface(w));
  w.wears = false;
  w.exact = false;
  CHECK_FALSE(revolution_surface(w));
  SceneWallParameters cone = tilted("cone");
  cone.radius_top = 0.03;
  const auto frustum = revolution_surface(cone);
  REQUIRE(frustum);
  CHECK(frustum->kind == RevolutionKind::cone);
  CHECK(frustum->radius == 0.08);
  CHECK(frustum->radius_top == 0.03);
  CHECK(frustum->axial_max == Approx(0.5).epsilon(1e-15));
  cone.caps = true;
  CHECK_FALSE(revolution_surface(cone));
  for (const char* other : {"plane", "box", "file", "sample", "holder"}) {
    SceneWallParameters t = tilted(other);
    CHECK_FALSE(revolution_surface(t));
  }
}

TEST_CASE("scene walls: a bin's cylinder and floor are revolution walls of the run, a moving "
          "plug stays triangles") {
  SceneParameters s = testing::flat_bottomed_bin("bin, floor, plug", 0.06, 0.3, 0.025, 0.05);
  auto& plug = s.walls[2];
  plug.source = "disc";
  plug.axis = {0, 0, 1};
  plug.radius = 0.025;
  plug.mesh_size = 0.005;
  plug.motion = "translation";
  plug.velocity = {0, 0, -2};
  plug.start_time = 1.0; // after the window below
  plug.end_time = 1.1;
  s.fill.region = "box";
  s.fill.minimum = {-0.04, -0.04, 0.005};
  s.fill.maximum = {0.04, 0.04, 0.2};
  s.fill.count = 100;
  SceneRun run(s, testing::gravel(), build_scene_walls(s));
  run.setup();
  CHECK(run.system().wall_kind(0) == WallKind::revolution);
  CHECK(run.system().wall_kind(1) == WallKind::revolution);
  CHECK(run.system().wall_kind(2) == WallKind::mesh);
  CHECK(run.system().revolution_wall(1).n_faces() == 1); // its loads as totals
  // The exact floor's loads are summed as totals: with the plug's and the side's they carry
  // the bed's weight once it rests (dropped from at most 0.2 m, it lies still after
  // 0.4 s), the window's mean force per wall.
  run.advance(0.4);
  const SceneWindow w = run.advance(0.5);
  const double weight = 100 * 2650 * wear::pi / 6 * std::pow(0.006, 3) * 9.81;
  const double carried = w.walls[0].force.z + w.walls[1].force.z + w.walls[2].force.z;
  CHECK(carried == Approx(-weight).epsilon(0.02));
  CHECK(w.walls[1].force.z < -0.5 * weight);
}

TEST_CASE("scene walls: a hopper's cone is a revolution wall of the run and carries the bed with "
          "its floor") {
  // A 45-degree cone from r = 20 mm at z = 0 to r = 80 mm at z = 60 mm, closed below by a
  // disc: 100 spheres of 6 mm dropped into it rest on the cone and the floor, whose window
  // forces then carry the bed's weight (2 %: the bed still settles a little). The cone's
  // closest points themselves: revolution_wall_test.cc.
  SceneParameters s = testing::flat_bottomed_bin("cone, floor", 0.06, 0.3, 0.02, 0.05);
  auto& cone = s.walls[0];
  cone.source = "cone";
  cone.axis = {0, 0, 0.06};
  cone.radius = 0.02;
  cone.radius_top = 0.08;
  cone.mesh_size = 0.005;
  auto& floor = s.walls[1];
  floor.radius = 0.02;
  floor.radius_inner = 0;
  floor.mesh_size = 0.004;
  s.fill.region = "box";
  s.fill.minimum = {-0.035, -0.035, 0.045};
  s.fill.maximum = {0.035, 0.035, 0.2};
  s.fill.count = 100;
  SceneRun run(s, testing::gravel(), build_scene_walls(s));
  run.setup();
  REQUIRE(run.system().wall_kind(0) == WallKind::revolution);
  CHECK(run.system().revolution_wall(0).kind() == RevolutionKind::cone);
  CHECK(run.system().revolution_wall(0).n_faces() == 1);
  run.advance(0.5);
  const SceneWindow w = run.advance(0.6);
  const double weight = 100 * 2650 * wear::pi / 6 * std::pow(0.006, 3) * 9.81;
  CHECK(w.walls[0].force.z + w.walls[1].force.z == Approx(-weight).epsilon(0.02));
  // The bed, about 10 mm deep, leans on the cone's lowest ring beside the floor: 28 % of its
  // weight on the cone at this seed.
  CHECK(w.walls[0].force.z < -0.1 * weight);
  CHECK(w.walls[1].force.z < -0.1 * weight);
}

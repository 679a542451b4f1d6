// A scene's DEM run (dem/scene/scene_run.h): a bin drains through its orifice with every
// particle counted, an empty scene fed by an inlet starts at its first particle, a fill
// box through a wall is refused before any particle exists, and a fill to a bed height
// follows the DEM subsection's Loose factor and Settle time.
#include "dem/scene/scene_run.h"
#include "dem/tester/tester_parameters.h"
#include "meshes/constants.h"
#include "meshes/gmsh_session.h"
#include "scene_fixtures.h"

#include <gmsh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace wear::dem;

using testing::endless_belt;
using testing::gravel;

namespace {

/// A bin of radius 60 mm on a flat floor with a central orifice; below it an outlet.
SceneParameters bin(double orifice_radius) {
  SceneParameters s = testing::flat_bottomed_bin("bin, floor", 0.06, 0.3, orifice_radius, 0.05);
  s.fill.region = "box";
  s.fill.minimum = {-0.04, -0.04, 0.005};
  s.fill.maximum = {0.04, 0.04, 0.2};
  s.fill.count = 400;
  s.end_time = 0.4;
  return s;
}

/// The bin with a pinhole for an orifice: nothing drains while a bed settles or stands.
SceneParameters pinhole_bin() {
  SceneParameters s = bin(0.025);
  testing::close_to_pinhole(s);
  return s;
}

} // namespace

TEST_CASE("scene run: a bin drains through its orifice and every particle is counted") {
  SceneParameters scene = bin(0.025);
  // A plane 20 mm under the floor, above the outlet: all that leaves crosses it first.
  scene.flux_plane_names = "orifice";
  scene.flux_planes.push_back({"orifice", {0, 0, -0.02}, {0, 0, -1}});
  SceneRun run(scene, gravel(), build_scene_walls(scene));
  run.setup();
  REQUIRE(run.system().particles.n_real == 400);
  SceneWindow w;
  while (run.time() < scene.end_time - 1e-9)
    w = run.advance(std::min(scene.end_time, run.time() + 0.1));
  INFO(w.n_removed << " removed by t = " << w.t_end << " s");
  CHECK(w.n_removed > 40);
  // Filled = in the bin + taken by the outlet, in count and (one size) in mass.
  CHECK(w.n_particles + w.n_removed == 400);
  const double m = 2650 * wear::pi / 6 * 0.006 * 0.006 * 0.006;
  CHECK(w.outlet_mass[0] == Approx(double(w.n_removed) * m).epsilon(1e-12));
  // Through the plane: what the outlet took, and those below the plane not yet taken.
  std::size_t n_below = 0;
  const auto& p = run.system().particles;
  for (std::size_t i = 0; i < p.n_real; ++i)
    n_below += p.position[i].z < -0.02 ? 1 : 0;
  CHECK(w.flux_mass[0] >= w.outlet_mass[0] - 1e-12);
  CHECK(w.flux_mass[0] <= w.outlet_mass[0] + double(n_below) * m + 1e-12);
  CHECK(run.flux_planes()[0].n_backward() == 0);
  // The floor carries what rests on it: a downward force on it, at most the bin's weight.
  CHECK(w.walls[1].force.z < 0);
  CHECK(-w.walls[1].force.z < 1.5 * 400 * m * 9.81);
}

TEST_CASE("scene run: an empty scene fed by an inlet starts at its first particle") {
  SceneParameters s = scene_with_names({"plate", "feed", ""});
  s.domain_min = {-0.3, -0.3, -0.1};
  s.domain_max = {0.3, 0.3, 0.4};
  auto& plate = s.walls[0];
  plate.source = "plane";
  plate.origin = {-0.2, -0.2, 0};
  plate.edge_u = {0.4, 0, 0};
  plate.edge_v = {0, 0.4, 0};
  plate.mesh_size = 0.05;
  auto& feed = s.inlets[0];
  feed.corner = {-0.05, -0.05, 0.2};
  feed.edge_u = {0.1, 0, 0};
  feed.edge_v = {0, 0.1, 0};
  feed.mass_flow = 0.2;
  feed.velocity = {0, 0, -1};
  feed.start_time = 0.05;
  s.end_time = 0.25;
  SceneRun run(s, gravel(), build_scene_walls(s));
  run.setup();
  CHECK(run.system().particles.n_real == 0);
  const SceneWindow before = run.advance(0.04); // nothing yet
  CHECK(before.n_particles == 0);
  const SceneWindow w = run.advance(0.25);
  const double m = 2650 * wear::pi / 6 * 0.006 * 0.006 * 0.006;
  CHECK(w.n_particles == w.n_inserted);
  CHECK(w.inserted_mass == Approx(double(w.n_inserted) * m).epsilon(1e-12));
  // The rate from the start time on, to one particle at the last batch (batches come at the
  // exchange interval, so up to one interval's mass is still owed at the window's end).
  const double expected = 0.2 * (w.t_end - 0.05);
  CHECK(std::abs(w.inserted_mass - expected) <= 0.2 * run.exchange_interval() + m);
  CHECK(run.system().time() == Approx(w.t_end));
}

TEST_CASE("scene run: an inlet feeds clumps into a bin and its outlet takes them whole") {
  // The bin of the first test, fed from above by an inlet of 'crushed stone 4' clumps (6 mm
  // equivalent) instead of a fill: the first batch starts the engine (bodies added before
  // setup), the later ones are inserted between steps; the outlet below takes bodies whole.
  SceneParameters scene = testing::flat_bottomed_bin("bin, floor", 0.06, 0.3, 0.025, 0.05);
  scene.inlet_names = "feed";
  scene.inlets.resize(1);
  auto& feed = scene.inlets[0];
  feed.name = "feed";
  feed.corner = {-0.03, -0.03, 0.25};
  feed.edge_u = {0.06, 0, 0};
  feed.edge_v = {0, 0.06, 0};
  feed.mass_flow = 0.1;
  feed.velocity = {0, 0, -1};
  scene.end_time = 0.6;
  TesterDemParameters dem = gravel();
  dem.particle_shape = "crushed stone 4";
  SceneRun run(scene, dem, build_scene_walls(scene));
  run.setup();
  SceneWindow w;
  while (run.time() < scene.end_time - 1e-9)
    w = run.advance(std::min(scene.end_time, run.time() + 0.1));
  INFO(w.n_inserted << " inserted, " << w.n_removed << " removed by t = " << w.t_end << " s");
  const Clumps& bodies = run.system().clumps();
  // Counted in clumps: inserted = in the bin + taken; every body whole, four members each.
  CHECK(w.n_removed > 10);
  CHECK(w.n_particles + w.n_removed == w.n_inserted);
  CHECK(bodies.size() == w.n_particles);
  CHECK(run.system().particles.n_real == 4 * bodies.size());
  const double m = 2650 * wear::pi / 6 * 0.006 * 0.006 * 0.006;
  CHECK(w.inserted_mass == Approx(double(w.n_inserted) * m).epsilon(1e-12));
  CHECK(w.outlet_mass[0] == Approx(double(w.n_removed) * m).epsilon(1e-12));
  for (std::size_t b = 0; b < bodies.size(); ++b)
    CHECK(bodies.mass[b] == Approx(m).epsilon(1e-12));
  // At random orientations: the bodies' first members point every way from their centres.
  wear::meshes::Vec3 mean{};
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto& x = run.system().particles.position[bodies.member_slot[bodies.member_begin[b]]];
    mean += wear::meshes::normalized(x - bodies.position[b]) * (1.0 / double(bodies.size()));
  }
  CHECK(wear::meshes::norm(mean) < 0.3);
}

TEST_CASE("scene run: a fill box through a wall is refused before any particle exists") {
  SceneParameters scene = bin(0.025);
  scene.fill.maximum = {0.07, 0.04, 0.2}; // through the bin's side at r = 0.06
  CHECK_THROWS_WITH(SceneRun(scene, gravel(), build_scene_walls(scene)),
                    Catch::Contains("Scene/Fill") && Catch::Contains("wall 'bin'") &&
                        Catch::Contains("cylinder"));
  scene = bin(0.025);
  scene.fill.minimum = {-0.04, -0.04, -0.01}; // through the floor
  CHECK_THROWS_WITH(SceneRun(scene, gravel(), build_scene_walls(scene)),
                    Catch::Contains("wall 'floor'"));
}

TEST_CASE("scene run: an inlet whose insertion box cuts a wall is refused") {
  SceneParameters s = bin(0.025);
  s.fill.region = "none";
  s.inlet_names = "feed";
  s.inlets.push_back({});
  auto& feed = s.inlets.back();
  feed.name = "feed";
  feed.edge_u = {0.06, 0, 0};
  feed.edge_v = {0, 0.06, 0};
  feed.mass_flow = 0.1;
  feed.velocity = {0, 0, -1};
  feed.corner = {-0.03, -0.03, 0.2}; // inside the bin: clear
  CHECK_NOTHROW(SceneRun(s, gravel(), build_scene_walls(s)));
  feed.corner = {0.03, -0.03, 0.2}; // reaching through the bin's side at r = 0.06
  CHECK_THROWS_WITH(SceneRun(s, gravel(), build_scene_walls(s)),
                    Catch::Contains("Scene/Inlet feed") && Catch::Contains("wall 'bin'"));
  // Feeding upwards from 8 mm over the floor: the box lies upstream, 12 mm deep, through it.
  feed.corner = {-0.03, -0.03, 0.008};
  feed.velocity = {0, 0, 1};
  CHECK_THROWS_WITH(SceneRun(s, gravel(), build_scene_walls(s)), Catch::Contains("wall 'floor'"));
  feed.corner = {-0.03, -0.03, 0.2};
  feed.velocity = {0, 0, -1};
  feed.edge_v = {0.01, 0.06, 0}; // not a rectangle
  CHECK_THROWS_WITH(SceneRun(s, gravel(), build_scene_walls(s)), Catch::Contains("perpendicular"));
}

TEST_CASE("scene run: a fill to a bed height settles before the run starts") {
  SceneParameters scene = pinhole_bin();
  scene.fill.count = 0;
  scene.fill.bed_height = 0.03;
  scene.fill.minimum = {-0.04, -0.04, 0.001}; // a millimetre clear of the floor
  scene.fill.maximum = {0.04, 0.04, 0.1};
  SceneRun run(scene, gravel(), build_scene_walls(scene));
  std::vector<std::string> said;
  run.setup([&](const std::string& text) { said.push_back(text); });
  const auto& p = run.system().particles;
  REQUIRE(p.n_real > 500);
  CHECK(run.time() > 0.1); // it settled: the run starts after the settling time
  double mean_speed = 0, top = 0;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    mean_speed += wear::meshes::norm(p.velocity[i]) / double(p.n_real);
    top = std::max(top, p.position[i].z);
  }
  CHECK(mean_speed < 0.01);
  // The bed spreads over the bin, wider than the box its count was estimated for (0.0064
  // against 0.0113 m^2 of floor): lower than asked, never higher.
  CHECK(top < 0.001 + 0.03 + 0.006);
  CHECK(top > 0.01);
  REQUIRE(!said.empty());
  CHECK_THAT(said.back(), Catch::Contains("filled"));

  // Binned over a window, the settled bed keeps its volume on the grid (nothing drains
  // through the pinhole) and barely moves.
  SceneParameters with_fields = scene;
  with_fields.fields = {{3, 3, 4}, {-0.07, -0.07, 0}, {0.07, 0.07, 0.08}};
  SceneRun binned(with_fields, gravel(), build_scene_walls(with_fields));
  binned.setup();
  const std::size_t n = binned.system().particles.n_real;
  const SceneWindow w = binned.advance(binned.time() + 0.02);
  REQUIRE(binned.system().particles.n_real == n);
  REQUIRE(w.fields.n_samples >= 2);
  const Vec3 h = binned.fields()->grid().spacing();
  double grid_volume = 0, speed = 0;
  for (std::size_t c = 0; c < w.fields.solid_fraction.size(); ++c) {
    grid_volume += w.fields.solid_fraction[c] * h.x * h.y * h.z;
    speed = std::max(speed, wear::meshes::norm(w.fields.velocity[c]));
  }
  CHECK(grid_volume ==
        Approx(double(n) * 4.0 / 3.0 * wear::pi * std::pow(0.003, 3)).epsilon(1e-12));
  CHECK(speed < 0.01);
}

TEST_CASE("scene run: a fill to a bed height follows DEM/Loose factor and Settle time") {
  // The bed of 30 mm placed loosely up to L x 30 mm over the floor and settled for at most
  // 0.02 s: the settling checks every 0.02 s whether the bed is still and stops at the first
  // check at or past Settle time, so it ends between 0.02 and 0.04 s, long before the bed is
  // still; in 0.04 s a particle falls at most g t^2 / 2 = 7.8 mm, so the highest particle's
  // top lies within 12 mm under the insertion region's top 1 mm + L x 30 mm. Before the
  // scenes read the DEM subsection's values, L was 2.5 and the settling 2 s whatever the case
  // said (the bed still after about 0.3 s).
  SceneParameters scene = pinhole_bin();
  scene.fill.count = 0;
  scene.fill.bed_height = 0.03;
  scene.fill.minimum = {-0.04, -0.04, 0.001};
  scene.fill.maximum = {0.04, 0.04, 0.1};
  for (const double loose : {2.0, 3.0}) {
    INFO("Loose factor " << loose);
    DemParameters d = gravel();
    d.loose_factor = loose;
    d.settle_time = 0.02;
    SceneRun run(scene, d, build_scene_walls(scene));
    run.setup();
    CHECK(run.time() >= 0.02);
    CHECK(run.time() <= 0.04 + 1e-9);
    const auto& p = run.system().particles;
    REQUIRE(p.n_real > 500);
    double top = 0, mean_speed = 0;
    for (std::size_t i = 0; i < p.n_real; ++i) {
      top = std::max(top, p.position[i].z + p.radius[i]);
      mean_speed += wear::meshes::norm(p.velocity[i]) / double(p.n_real);
    }
    const double region_top = 0.001 + loose * 0.03;
    CHECK(top <= region_top + 1e-9);
    CHECK(top > region_top - 0.012);
    CHECK(mean_speed > 0.05); // still falling: the settling was cut short
  }
  // A loose bed above the region is refused, naming the parameter to change.
  DemParameters tall = gravel();
  tall.loose_factor = 4;
  CHECK_THROWS_WITH(SceneRun(scene, tall, build_scene_walls(scene)),
                    Catch::Contains("DEM/Loose factor = 4") &&
                        Catch::Contains("raise Maximum z to at least 0.121"));
}

TEST_CASE("scene run: a cylinder fills the bin to a count or a bed height, clear of its wall") {
  // The cylinder 2 mm inside the bin's wall, which a box could not fill.
  SceneParameters scene = testing::pinhole_bin_cylinder_fill("bin, floor");
  SceneRun counted(scene, gravel(), build_scene_walls(scene));
  counted.setup();
  const auto& p = counted.system().particles;
  REQUIRE(p.n_real == 600);
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const auto& x = p.position[i];
    REQUIRE(std::hypot(x.x, x.y) <= 0.058 - p.radius[i] + 1e-12);
    REQUIRE(x.z >= 0.001 + p.radius[i] - 1e-12);
  }
  // To a bed height over the bin's whole floor: the bed settles to about the height asked.
  scene.fill.count = 0;
  scene.fill.bed_height = 0.03;
  SceneRun bed(scene, gravel(), build_scene_walls(scene));
  bed.setup();
  const auto& q = bed.system().particles;
  std::vector<double> z;
  for (std::size_t i = 0; i < q.n_real; ++i)
    z.push_back(q.position[i].z + q.radius[i]);
  std::sort(z.begin(), z.end());
  const double top = z[std::size_t(0.98 * double(z.size()))]; // the surface, not a stray grain
  CHECK(top == Approx(0.001 + 0.03).margin(0.006));           // within a particle diameter
  // A cylinder wider than the bin cuts its wall: refused, naming it.
  scene.fill.radius = 0.061;
  CHECK_THROWS_WITH(SceneRun(scene, gravel(), build_scene_walls(scene)),
                    Catch::Contains("Scene/Fill: the cylinder of radius 0.061 m") &&
                        Catch::Contains("intersects wall 'bin' (cylinder)"));
  scene.fill.radius = 0.05;
  scene.fill.axis = {0.01, 0, 0.2};
  CHECK_THROWS_WITH(validate(scene), Catch::Contains("Scene/Fill/Axis: a fill to a Bed height"));
}

TEST_CASE("scene run: a ball dropped on a conveyor belt rolls at 2/7 of the belt's speed") {
  // The belt ('surface translation') stays where it is and its surface moves at V: the ball
  // slips until its contact point moves with the belt, then rolls at v = 2/7 V with spin
  // 5/7 V x z / r (as on a plate that slides, tests/dem/moving_wall_test.cc).
  SceneParameters scene = scene_with_names({"belt", "", ""});
  auto& belt = scene.walls[0];
  belt.source = "plane";
  belt.origin = {-0.1, -0.1, 0};
  belt.edge_u = {0.2, 0, 0};
  belt.edge_v = {0, 0.2, 0};
  belt.mesh_size = 0.05;
  belt.motion = "surface translation";
  belt.velocity = {0.08, 0.06, 0};
  scene.domain_min = {-0.2, -0.2, -0.1};
  scene.domain_max = {0.2, 0.2, 0.2};
  scene.fill.region = "box";
  scene.fill.minimum = {-0.0035, -0.0035, 0.0005};
  scene.fill.maximum = {0.0035, 0.0035, 0.0075}; // one 6 mm ball, dropped from below 1.5 mm
  scene.fill.count = 1;
  TesterDemParameters d = gravel();
  d.particle_wall.rolling_friction = 0; // rolling resistance would change the steady state
  SceneRun run(scene, d, build_scene_walls(scene));
  run.setup();
  run.advance(0.3);
  const auto& p = run.system().particles;
  REQUIRE(p.n_real == 1);
  const Vec3 V = scene_vector(belt.velocity);
  const double r = p.radius[0];
  const Vec3 v = p.velocity[0], w = p.angular_velocity[0];
  INFO("velocity " << v.x << " " << v.y << " " << v.z << ", spin " << w.x << " " << w.y);
  CHECK(wear::meshes::norm(v - V * (2.0 / 7.0)) <= 1e-6 * wear::meshes::norm(V));
  CHECK(wear::meshes::norm(w - wear::meshes::cross(V, Vec3{0, 0, 1}) * (5.0 / 7.0 / r)) <=
        1e-6 * wear::meshes::norm(V) / r);
}

TEST_CASE("scene run: a bed in a periodic sector on a turntable stays in the sector and turns") {
  // A 60-degree sector of an annular trough (walls: the floor, a disc turning as a
  // 'surface rotation', and the inner and outer cylinders, fixed), a bed of 300 particles:
  // the floor drags it round, the particles leave through one periodic plane and come back
  // through the other, none is lost and all stay in the sector.
  SceneParameters scene = scene_with_names({"floor, inner, outer", "", ""});
  scene.periodic_angle_deg = 60;
  scene.domain_min = {-0.3, -0.3, -0.05};
  scene.domain_max = {0.3, 0.3, 0.3};
  auto& floor = scene.walls[0];
  floor.source = "disc";
  floor.axis = {0, 0, 1};
  floor.radius = 0.2;
  floor.radius_inner = 0.1;
  floor.mesh_size = 0.02;
  floor.motion = "surface rotation";
  floor.angular_velocity = 2;
  for (int k : {1, 2}) {
    auto& side = scene.walls[std::size_t(k)];
    side.source = "cylinder";
    side.axis = {0, 0, 0.2};
    side.radius = k == 1 ? 0.1 : 0.2;
    side.mesh_size = 0.02;
  }
  scene.fill.region = "box";
  scene.fill.minimum = {0.12, 0.01, 0.002};
  scene.fill.maximum = {0.17, 0.07, 0.15};
  scene.fill.count = 300;
  SceneRun run(scene, gravel(), build_scene_walls(scene));
  run.setup();
  run.advance(0.5);
  const auto& p = run.system().particles;
  REQUIRE(p.n_real == 300);
  double mean_tangential = 0;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const double theta = std::atan2(p.position[i].y, p.position[i].x);
    REQUIRE(theta >= -1e-12);
    REQUIRE(theta < wear::pi / 3 + 1e-12);
    const Vec3 t{-std::sin(theta), std::cos(theta), 0};
    mean_tangential += wear::meshes::dot(p.velocity[i], t) / double(p.n_real);
  }
  // Dragged along, slower than the floor under it (2 rad/s x 0.15 m = 0.3 m/s).
  CHECK(mean_tangential > 0.02);
  CHECK(mean_tangential < 0.3);

  // A wall that moves as a rigid body cannot be periodic; a fill outside the sector is refused.
  SceneParameters rigid = scene;
  rigid.walls[0].motion = "rotation";
  CHECK_THROWS_WITH(validate(rigid), Catch::Contains("Scene/Wall floor/Motion") &&
                                         Catch::Contains("periodic sector"));
  SceneParameters outside = scene;
  outside.fill.minimum = {0.12, -0.02, 0.002};
  CHECK_THROWS_WITH(SceneRun(outside, gravel(), build_scene_walls(outside)),
                    Catch::Contains("Scene/Fill: the box") &&
                        Catch::Contains("outside the periodic sector"));

  // The trough filled to a bed height as an annulus about z: only its 60-degree share, clear of
  // both walls (2 mm), settles to about the height asked.
  SceneParameters trough = scene;
  trough.walls[0].motion = "fixed";
  trough.fill.region = "cylinder";
  trough.fill.origin = {0, 0, 0.001};
  trough.fill.axis = {0, 0, 0.1};
  trough.fill.radius = 0.198;
  trough.fill.radius_inner = 0.102;
  trough.fill.count = 0;
  trough.fill.bed_height = 0.02;
  SceneRun bed(trough, gravel(), build_scene_walls(trough));
  bed.setup();
  const auto& q = bed.system().particles;
  REQUIRE(q.n_real > 100);
  std::vector<double> z;
  for (std::size_t i = 0; i < q.n_real; ++i) {
    const double theta = std::atan2(q.position[i].y, q.position[i].x);
    REQUIRE(theta >= -1e-12);
    REQUIRE(theta < wear::pi / 3 + 1e-12);
    z.push_back(q.position[i].z + q.radius[i]);
  }
  std::sort(z.begin(), z.end());
  CHECK(z[std::size_t(0.98 * double(z.size()))] == Approx(0.001 + 0.02).margin(0.006));
  // An annulus whose hole does not clear the inner wall cuts it.
  trough.fill.radius_inner = 0.099;
  CHECK_THROWS_WITH(SceneRun(trough, gravel(), build_scene_walls(trough)),
                    Catch::Contains("intersects wall 'inner'"));
}

TEST_CASE("scene run: a tilted solid from STEP is filled to a count, inside it and clear of it") {
  // A 60 x 40 x 40 mm box turned 30 degrees about x, centred in the bin, written by
  // OpenCASCADE in millimetres.
  {
    wear::meshes::GmshSession session("fill solid");
    const int box = gmsh::model::occ::addBox(-30, -20, 20, 60, 40, 40);
    gmsh::model::occ::rotate({{3, box}}, 0, 0, 40, 1, 0, 0, wear::pi / 6);
    gmsh::model::occ::synchronize();
    gmsh::write("fill_tilted_box.step");
  }
  SceneParameters scene = pinhole_bin();
  scene.fill.region = "mesh";
  scene.fill.file = "fill_tilted_box.step";
  scene.fill.unit = "mm";
  scene.fill.mesh_size = 0.01;
  scene.fill.count = 60;
  SceneRun run(scene, gravel(), build_scene_walls(scene));
  run.setup();
  const auto& p = run.system().particles;
  REQUIRE(p.n_real == 60);
  // Each sphere lies inside the box: in its frame (turned back by 30 degrees about x through
  // (0, 0, 40) mm) within the half sizes less the radius.
  const double c = std::cos(wear::pi / 6), s30 = std::sin(wear::pi / 6);
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const Vec3 x = p.position[i] - Vec3{0, 0, 0.04};
    const Vec3 local{x.x, c * x.y + s30 * x.z, -s30 * x.y + c * x.z};
    const double r = p.radius[i];
    REQUIRE(std::abs(local.x) <= 0.03 - r + 1e-9);
    REQUIRE(std::abs(local.y) <= 0.02 - r + 1e-9);
    REQUIRE(local.z >= -0.02 + r - 1e-9);
    REQUIRE(local.z <= 0.02 + r - 1e-9 + 0.0); // the top face z = 60 mm before turning
  }
  // A count above what the solid holds at the densest packing of its 6 mm spheres,
  // 0.7405 x 96 cm^3 / (pi/6 x (6 mm)^3) = 628, is refused once the file is read, before any
  // particle (its volume is not known when the case file is read).
  scene.fill.count = 629;
  CHECK_THROWS_WITH(SceneRun(scene, gravel(), build_scene_walls(scene)),
                    Catch::Contains("Scene/Fill/Count (629)") &&
                        Catch::Contains("hold, 628: the solid of 'fill_tilted_box.step'"));
  scene.fill.count = 60;
  // Moved down by 30 mm it pokes through the floor: refused, naming the wall.
  {
    wear::meshes::GmshSession session("fill solid low");
    const int box = gmsh::model::occ::addBox(-30, -20, -10, 60, 40, 40);
    gmsh::model::occ::rotate({{3, box}}, 0, 0, 10, 1, 0, 0, wear::pi / 6);
    gmsh::model::occ::synchronize();
    gmsh::write("fill_low_box.step");
  }
  scene.fill.file = "fill_low_box.step";
  CHECK_THROWS_WITH(SceneRun(scene, gravel(), build_scene_walls(scene)),
                    Catch::Contains("Scene/Fill: the solid of 'fill_low_box.step'") &&
                        Catch::Contains("intersects wall 'floor'"));
  scene.fill.count = 0;
  scene.fill.bed_height = 0.02;
  CHECK_THROWS_WITH(validate(scene), Catch::Contains("Scene/Fill/Count: a fill from a mesh"));
}
TEST_CASE("scene run: a bed on an endless belt, periodic along it, goes round and is kept") {
  // A belt (a plane moving as a 'surface translation' at 0.5 m/s along x) between two fixed
  // side plates, the scene periodic in x over 0.2 m (the walls reach 50 mm past both planes):
  // the bed of 300 particles is carried along, leaves through x = 0.1 m and comes back
  // through x = -0.1 m; none is lost, all stay in the slab, and the net mass through the plane
  // x = 0 over 1 s is more than half the bed's (each particle at least 2/7 V, a ball rolling on
  // the belt, for 1 s: 0.14 m of the 0.2 m period; measured: 1.7 beds, the bed riding at a mean
  // 0.47 m/s). The plane counts a particle wrapped through the periodic planes as not crossing
  // (without that, the wraps cancel the crossings and the net mass is about 0).
  SceneParameters scene = endless_belt();
  SceneRun run(scene, gravel(), build_scene_walls(scene));
  run.setup();
  const SceneWindow w = run.advance(1.0);
  const auto& p = run.system().particles;
  REQUIRE(p.n_real == 300);
  double mass = 0, vx = 0;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    REQUIRE(p.position[i].x >= -0.1 - 1e-3); // wrapped, drifting at most half a skin
    REQUIRE(p.position[i].x < 0.1 + 1e-3);
    mass += p.mass[i];
    vx += p.velocity[i].x / double(p.n_real);
  }
  INFO("net mass through x = 0: " << w.flux_mass[0] << " kg of " << mass << " kg; mean vx " << vx);
  CHECK(w.flux_mass[0] > 0.5 * mass);
  CHECK(vx > 2.0 / 7.0 * 0.5 * 0.9);
  // A fill reaching past the slab is refused, naming it.
  scene.fill.maximum[0] = 0.12;
  CHECK_THROWS_WITH(SceneRun(scene, gravel(), build_scene_walls(scene)),
                    Catch::Contains("Scene/Fill: the box") &&
                        Catch::Contains("reaches outside the periodic slab"));
  scene.fill.maximum[0] = 0.095;
  // Over ranks it is cut along its period; another axis is refused, naming the parameter.
  scene.rank_slabs_along = "y";
  CHECK_THROWS_WITH(validate(scene), Catch::Contains("Scene/Rank slabs along = y") &&
                                         Catch::Contains("along its period"));
  scene.rank_slabs_along = "auto";
  scene.periodic_angle_deg = 30;
  CHECK_THROWS_WITH(validate(scene), Catch::Contains("exclude each other"));
}

TEST_CASE(
    "scene run: a wall's new surface pushes out the particles it would overlap, to touch it") {
  // A lid (a plane) far above a settled bed in the pinhole bin is lowered into its top layer:
  // every particle the lowered lid overlaps by more than the tolerance (1 % of its radius)
  // moves down along the lid's normal (its closest point -> centre) to touch it, the others
  // stay where they are (System::push_out_of_wall).
  SceneParameters scene = testing::pinhole_bin_cylinder_fill("bin, floor, lid");
  auto& lid = scene.walls[2];
  lid.source = "plane";
  lid.origin = {-0.08, -0.08, 0.28};
  lid.edge_u = {0.16, 0, 0};
  lid.edge_v = {0, 0.16, 0};
  lid.mesh_size = 0.04;
  SceneRun run(scene, gravel(), build_scene_walls(scene));
  run.setup();
  run.advance(0.3);
  const auto& p = run.system().particles;
  double top = 0;
  for (std::size_t i = 0; i < p.n_real; ++i)
    top = std::max(top, p.position[i].z);
  const double z_lid = top + 0.5 * 0.003; // half a radius above the highest centre
  const std::vector<Vec3> before(p.position.begin(), p.position.begin() + long(p.n_real));
  int expected = 0;
  double deepest = 0;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const double overlap = p.radius[i] - (z_lid - before[i].z);
    if (overlap > 0.01 * p.radius[i]) {
      ++expected;
      deepest = std::max(deepest, overlap);
    }
  }
  REQUIRE(expected > 0);
  auto lowered = run.walls()[2].surface.mesh;
  for (auto& v : lowered.vertices)
    v.z = z_lid;
  const PushReport pushed = run.replace_wall_surface(2, lowered, 0.01);
  CHECK(pushed.n_pushed == expected);
  CHECK(pushed.max_distance == Approx(deepest).epsilon(1e-9));
  for (std::size_t i = 0; i < p.n_real; ++i) {
    INFO("particle " << i);
    const double overlap = p.radius[i] - (z_lid - before[i].z);
    if (overlap > 0.01 * p.radius[i]) { // now touching the lid, moved straight down
      CHECK(p.position[i].z == Approx(z_lid - p.radius[i]).epsilon(1e-12));
      CHECK(p.position[i].x == Approx(before[i].x).margin(1e-12)); // (the closest point's
      CHECK(p.position[i].y == Approx(before[i].y).margin(1e-12)); // rounding)
    } else
      CHECK(p.position[i].z == before[i].z);
  }
  CHECK(run.walls()[2].surface.mesh.vertices[0].z == z_lid);
}

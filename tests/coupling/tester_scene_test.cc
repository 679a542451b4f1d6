// The wear tester written as a scene (dem/tester/tester_scene.h, `wearsim tester-scene`): the
// scene keeps the tester's machine (walls, sector, rotation, consolidator, fill, stage and
// record times, against the tester's own figures), and the case file written reads back as
// the same case, setting none of the tester's own entries.
#include "coupling/parameters/tester_scene_case.h"
#include "dem/tester/tester_scene.h"
#include "error_of.h"
#include "meshes/constants.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace wear;
using Catch::Matchers::Contains;

namespace {

const dem::SceneWallParameters& wall(const dem::SceneParameters& s, const std::string& name) {
  for (const auto& w : s.walls)
    if (w.name == name)
      return w;
  FAIL("no wall " << name);
  return s.walls.front();
}

meshes::Vec3 vec(const std::vector<double>& v) {
  return {v.at(0), v.at(1), v.at(2)};
}

} // namespace

TEST_CASE("the reference tester written as a scene keeps the tester's machine", "[tester-scene]") {
  const meshes::GeometryParameters g; // docs/wear-tester.md: 150 deg, 0.29 to 0.5 m
  const dem::TesterDemParameters d;   // 90 deg/s, 130 mm, 10 samples a revolution
  const auto& t = g.tester;
  const dem::SceneParameters s = dem::tester_scene(g, d, 2);
  CHECK(s.wall_names == "floor, inner, outer, consolidator, holder, sample");
  CHECK(s.periodic_angle_deg == 150);
  // a revolution is one pass through the sector: 150 / 90 s; a stage two of them
  const double revolution = 150.0 / 90.0;
  CHECK(s.stage_duration == Approx(2 * revolution).epsilon(1e-15));
  CHECK(s.output_interval == Approx(revolution / 10).epsilon(1e-15));
  CHECK_FALSE(s.particle_snapshots);
  const double omega = 90 * wear::pi / 180;
  for (const char* name : {"floor", "inner", "outer"}) {
    const auto& w = wall(s, name);
    CHECK(w.motion == "surface rotation");
    CHECK(vec(w.rotation_axis).z == 1);
    CHECK(w.angular_velocity == Approx(omega).epsilon(1e-15));
  }
  CHECK(wall(s, "floor").radius == t.outer_radius);
  CHECK(wall(s, "floor").radius_inner == t.inner_radius);
  CHECK(wall(s, "inner").radius == t.inner_radius);
  CHECK(wall(s, "outer").radius == t.outer_radius);
  CHECK(vec(wall(s, "outer").axis).z == t.wall_height);
  CHECK(wall(s, "sample").wears);
  CHECK_FALSE(wall(s, "holder").wears);

  // The consolidator: a flat plate at its height, its corners inside the annulus, centred on
  // its angle, its area that of the tester's annular sector within 3 %.
  const auto& c = wall(s, "consolidator");
  const meshes::Vec3 o = vec(c.origin), u = vec(c.edge_u), v = vec(c.edge_v);
  for (const meshes::Vec3& corner : {o, o + u, o + v, o + u + v}) {
    const double r = std::hypot(corner.x, corner.y);
    CHECK(corner.z == t.consolidator_height);
    CHECK(r > t.inner_radius);
    CHECK(r < t.outer_radius);
  }
  const meshes::Vec3 centre = o + u * 0.5 + v * 0.5;
  CHECK(std::atan2(centre.y, centre.x) * 180 / wear::pi ==
        Approx(t.consolidator_angle_deg).epsilon(1e-12));
  const double plate = meshes::norm(meshes::cross(u, v));
  const double sector = 0.5 * t.consolidator_extent_deg * wear::pi / 180 *
                        (t.outer_radius * t.outer_radius - t.inner_radius * t.inner_radius);
  CHECK(plate == Approx(sector).epsilon(0.03));
  CHECK(s.fill.clear_above == "consolidator");
  CHECK(s.fill.bed_height == d.fill_height);
  CHECK(s.fill.radius_inner > t.inner_radius);
  CHECK(s.fill.radius < t.outer_radius);

  // Without consolidator and holder, in a full circle: neither wall, no period.
  meshes::GeometryParameters bare = g;
  bare.tester.consolidator = bare.tester.holder = false;
  bare.tester.sector_angle_deg = 360;
  const auto b = dem::tester_scene(bare, d, 1);
  CHECK(b.wall_names == "floor, inner, outer, sample");
  CHECK(b.periodic_angle_deg == 0);
  CHECK(b.fill.clear_above.empty());
  CHECK_THAT(error_of([&] { dem::tester_scene(g, d, 0); }),
             Contains("Coupling/Revolutions per stage"));
}

TEST_CASE("a tester case written by wearsim tester-scene reads back as the same case",
          "[tester-scene]") {
  const auto p = coupling::read_case(WEAR_SOURCE_DIR "/cases/sector-30/plain.prm");
  const auto s = coupling::tester_scene_case(p);
  const std::string path = "tester_scene_test.prm";
  {
    std::ofstream out(path);
    out << coupling::tester_scene_text(s, p.case_file);
  }
  std::ostringstream warnings;
  // read_case refuses every entry a scene does not use: the tester's own are not written
  const auto q = coupling::read_case(path, warnings);
  CHECK(warnings.str().empty());
  CHECK(coupling::changed_parameters(q) == coupling::changed_parameters(s));
  CHECK(q.scene.stage_duration == s.scene.stage_duration); // bit for bit through the text
  CHECK(q.scene.output_interval * p.dem.samples_per_revolution ==
        Approx(q.scene.stage_duration / p.coupling.revolutions_per_stage).epsilon(1e-15));
  CHECK(q.scene.wall_names == "floor, inner, outer, sample");
  // the sector's walls (0.3 m) are lower than the loose fill (2.5 x 0.13 m): the fill reaches
  // above them, as a scene's fill must
  CHECK(q.scene.fill.axis.at(2) >= q.dem.loose_factor * q.scene.fill.bed_height);
  CHECK(vec(q.scene.walls[1].axis).z == p.geometry.tester.wall_height);
  CHECK(q.scene.periodic_angle_deg == p.geometry.tester.sector_angle_deg);
  CHECK(q.dem.psd.scaling_factor == p.dem.psd.scaling_factor);
  CHECK(q.dem.settle_time == p.dem.settle_time);
  CHECK(q.dem.seed == p.dem.seed);
  CHECK(q.coupling.schedule == p.coupling.schedule);
  CHECK(q.coupling.amplification == p.coupling.amplification);
  CHECK(q.geometry.sample.mesh_size == p.geometry.sample.mesh_size);
  CHECK(q.geometry.placement.angle_deg == p.geometry.placement.angle_deg);
  CHECK(q.output.directory == p.output.directory); // `wearsim tester-scene` appends "-scene"

  // A reference (node-moving) case keeps its update interval as a scene, the one Deformation
  // entry a scene reads, and only with reference stages.
  auto reference = p;
  reference.coupling.schedule = "4 reference";
  reference.deformation.update_interval = 200;
  {
    std::ofstream out(path);
    out << coupling::tester_scene_text(coupling::tester_scene_case(reference), p.case_file);
  }
  const auto r = coupling::read_case(path, warnings);
  CHECK(r.deformation.update_interval == 200);
  CHECK(r.coupling.schedule == "4 reference");
  {
    std::ofstream out(path);
    out << coupling::tester_scene_text(s, p.case_file)
        << "subsection Deformation\n  set Update interval = 200\nend\n";
  }
  CHECK_THAT(error_of([&] { coupling::read_case(path, warnings); }),
             Contains("Deformation/Update interval") && Contains("no reference stage"));
  std::filesystem::remove(path);
  CHECK_THAT(error_of([&] { coupling::tester_scene_case(q); }), Contains("is a scene already"));
}

TEST_CASE("wearsim run and wearsim dem run a tester case as its scene", "[tester-scene]") {
  auto p = coupling::read_case(WEAR_SOURCE_DIR "/cases/sector-30/convex.prm");
  // run: the tester's schedule and stages, its evaluation, the scene's own walls
  const auto r = coupling::run_case_of(p);
  CHECK(r.scene.wall_names == "floor, inner, outer, sample");
  CHECK(r.coupling.schedule == p.coupling.schedule);
  CHECK(r.scene.evaluation.wall == "sample");
  CHECK(coupling::run_case_of(r).scene.wall_names == r.scene.wall_names); // a scene as it is
  // dem: DEM/Revolutions dem-only stages of one revolution, stopped after steady
  p.dem.revolutions = 7;
  p.dem.revolutions_after_steady = 2;
  const auto d = coupling::dem_case_of(p);
  CHECK(d.coupling.schedule == "7 dem-only");
  CHECK(d.scene.stage_duration == Approx(d.scene.evaluation.period).epsilon(1e-15));
  CHECK(d.scene.evaluation.periods_after_steady == 2);
  // dem with the node-moving method: reference stages at its amplification
  p.deformation.enabled = true;
  p.deformation.amplification = 3;
  p.deformation.update_interval = 250;
  const auto m = coupling::dem_case_of(p);
  CHECK(m.coupling.schedule == "7 reference");
  CHECK(m.coupling.amplification == 3);
  CHECK(m.deformation.update_interval == 250);
  CHECK_FALSE(m.deformation.enabled);
  // run refuses dem's switch, naming it and where a run's reference stages are
  CHECK_THAT(error_of([&] { coupling::run_case_of(p); }),
             Contains("Deformation/Reference method") && Contains("Coupling/Schedule"));
  CHECK_THAT(error_of([&] { coupling::dem_case_of(r); }), Contains("is a scene"));
}

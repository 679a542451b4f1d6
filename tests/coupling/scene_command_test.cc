// The Scene subsection and `wearsim scene` (issue 33, first part): walls from a STEP file in
// millimetres and from primitives are read by their names, built with their analytic size,
// written with their labels, and their parameters round-trip through the resolved file; bad
// scenes are refused naming the wall and the problem before anything is written, and the
// tester's commands refuse a scene.
#include "coupling/app/scene_command.h"
#include "coupling/output/scene_series.h"
#include "dem/scene/scene_run.h"
#include "dem/scene/scene_walls.h"
#include "error_of.h"
#include "meshes/atomic_file.h"
#include "meshes/constants.h"
#include "meshes/gmsh_session.h"
#include "meshes/stl_io.h"
#include "tests/dem/scene_fixtures.h"

#include <catch2/catch.hpp>

#include <gmsh.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace wear::coupling;

namespace {

// A 100 x 200 x 50 mm plate written by OpenCASCADE as STEP, in millimetres.
void write_plate(const std::string& path) {
  wear::meshes::GmshSession session("plate");
  gmsh::model::occ::addBox(0, 0, 0, 100, 200, 50);
  gmsh::model::occ::synchronize();
  gmsh::write(path);
}

std::string scene_case(const std::string& dir, const std::string& liner_extra = "",
                       const std::string& walls = "liner, floor, drum") {
  return "subsection Scene\n"
         "  set Walls = " +
         walls +
         "\n"
         "  subsection Wall liner\n"
         "    set File = scene_plate.step\n"
         "    set Unit = mm\n"
         "    set Mesh size = 0.02\n"
         "    set Wears = true\n"
         "    set Material = sample\n" +
         liner_extra +
         "  end\n"
         "  subsection Wall floor\n"
         "    set Source = disc\n"
         "    set Origin = 0, 0, -0.01\n"
         "    set Radius = 0.5\n"
         "    set Mesh size = 0.02\n"
         "  end\n"
         "  subsection Wall drum\n"
         "    set Source = cylinder\n"
         "    set Origin = 0, 0, -0.01\n"
         "    set Axis = 0, 0, 0.4\n"
         "    set Radius = 0.5\n"
         "    set Mesh size = 0.02\n"
         "    set Motion = rotation\n"
         "    set Angular velocity = 1.5\n"
         "  end\n"
         "end\n"
         "subsection Output\n"
         "  set Directory = " +
         dir + "\nend\n";
}

CaseParameters read_text(const std::string& name, const std::string& text) {
  std::ofstream(name) << text;
  std::ostringstream warnings;
  return read_case(name, warnings);
}

} // namespace

TEST_CASE("wearsim scene: walls from STEP and primitives by name, with their sizes",
          "[coupling][scene]") {
  write_plate("scene_plate.step");
  std::filesystem::remove_all("scene_out");
  const auto p = read_text("scene_ok.prm", scene_case("scene_out"));
  REQUIRE(p.scene.walls.size() == 3);
  CHECK(p.scene.walls[0].name == "liner");
  CHECK(p.scene.walls[0].unit == "mm");
  CHECK(p.scene.walls[0].wears);
  CHECK(p.scene.walls[2].motion == "rotation");
  CHECK(p.scene.walls[2].angular_velocity == 1.5);
  // The resolved file declares and keeps every wall's values.
  const auto again = read_text("scene_resolved.prm", resolved_parameters(p));
  REQUIRE(again.scene.walls.size() == 3);
  CHECK(again.scene.walls[1].radius == 0.5);
  CHECK(again.scene.walls[2].axis == std::vector<double>{0, 0, 0.4});

  std::ostringstream log;
  run_scene_command(p, log);
  INFO(log.str());
  const auto liner = wear::meshes::read_stl("scene_out/scene/liner.stl");
  CHECK(wear::meshes::enclosed_volume(liner) == Approx(0.1 * 0.2 * 0.05).epsilon(1e-12));
  CHECK(liner.labels().size() == 6);
  const auto drum = wear::meshes::read_stl("scene_out/scene/drum.stl");
  CHECK(wear::meshes::total_area(drum) == Approx(2 * wear::pi * 0.5 * 0.4).epsilon(2e-3));
  CHECK(std::filesystem::exists("scene_out/scene/floor.vtu"));
  CHECK(std::filesystem::exists("scene_out/parameters.prm"));
  // The wearing liner's surfaces by CAD number and role: all wear, none is clamped.
  CHECK(log.str().find("surface   1 S1:") != std::string::npos);
  CHECK(log.str().find("surface   6 S6:") != std::string::npos);
}

TEST_CASE("wearsim scene: bad scenes are refused naming the wall, before anything is written",
          "[coupling][scene]") {
  write_plate("scene_plate.step");
  const auto refused = [](const std::string& name, const std::string& text) {
    std::filesystem::remove_all("scene_bad_out");
    const std::string e = error_of([&] {
      const auto p = read_text(name, text);
      std::ostringstream log;
      run_scene_command(p, log);
    });
    CHECK(!std::filesystem::exists("scene_bad_out/scene"));
    return e;
  };
  // The plate read in metres is 200 m long: outside the default domain of +-10 m.
  CHECK(refused("scene_unit.prm", scene_case("scene_bad_out", "    set Unit = m\n"))
            .find("Scene/Wall liner (File = scene_plate.step, Unit = m)") != std::string::npos);
  CHECK(refused("scene_missing.prm",
                scene_case("scene_bad_out", "    set File = no_such_plate.step\n"))
            .find("'no_such_plate.step' does not exist") != std::string::npos);
  // An open surface (a plane) as a wearing part.
  CHECK(refused("scene_open.prm",
                scene_case("scene_bad_out", "    set Source = plane\n    set Edge u = 0.1, 0, 0\n"))
            .find("a wearing wall must be a closed solid") != std::string::npos);
  CHECK(refused("scene_twice.prm", scene_case("scene_bad_out", "", "liner, floor, liner"))
            .find("'liner' is listed twice") != std::string::npos);
  CHECK(refused("scene_unknown.prm", scene_case("scene_bad_out", "    set Colour = red\n"))
            .find("Colour") != std::string::npos);
  // A wall named in Scene/Walls without its subsection takes the defaults: a file source
  // without a file.
  CHECK(refused("scene_nofile.prm", scene_case("scene_bad_out", "", "liner, floor, drum, chute"))
            .find("Scene/Wall chute/File: a file is needed") != std::string::npos);

  // The tester's commands refuse a scene rather than ignore it.
  const auto p = read_text("scene_run.prm", scene_case("scene_bad_out"));
  CHECK(error_of([&] {
          require_no_scene(p, "dem");
        }).find("`wearsim dem` takes a wear-tester case") != std::string::npos);
  CaseParameters tester;
  CHECK_NOTHROW(require_no_scene(tester, "dem"));
}

TEST_CASE("a scene's series writes a wall that keeps its place once, a moving body at every "
          "record",
          "[coupling][scene]") {
  // The belt's surface moves in place (surface translation), the left side stands, the right
  // side moves as a rigid body: only the last changes between records.
  auto scene = wear::dem::testing::endless_belt();
  scene.periodic_direction = "none";
  scene.flux_plane_names = "";
  scene.flux_planes.clear();
  auto& right = scene.walls[2];
  right.motion = "translation";
  right.velocity = {0, 0.01, 0};
  const wear::meshes::GeometryParameters geometry;
  const wear::dem::DemParameters dem;
  const wear::dem::SceneRun run(scene, dem, wear::dem::build_scene_walls(scene, geometry));
  const std::string dir = "scene_series_walls";
  std::filesystem::remove_all(dir);
  wear::meshes::ensure_directory(dir);
  SceneSeries series(dir, run);
  for (int k = 1; k <= 2; ++k)
    series.add(wear::dem::SceneWindow{}, run, wear::dem::Particles{}, nullptr, false);
  for (const char* name : {"belt", "left"}) {
    CHECK(std::filesystem::exists(dir + "/walls/" + name + ".vtu"));
    CHECK_FALSE(std::filesystem::exists(dir + "/walls_1/" + name + ".vtu"));
  }
  CHECK_FALSE(std::filesystem::exists(dir + "/walls/right.vtu"));
  CHECK(std::filesystem::exists(dir + "/walls_1/right.vtu"));
  CHECK(std::filesystem::exists(dir + "/walls_2/right.vtu"));
}

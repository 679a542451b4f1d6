// `wearsim life` measures a run's kept surfaces on the elements' unworn footprints: a round
// half-ellipsoid element (radius 4 mm, height 3 mm) on a block, written as a run writes its
// stages. Stage 2's surface is stage 1's with the base's label 1.5 mm up the element's flank,
// as labels handed on from surface to surface move: its footprint volume is stage 1's to
// round-off (the volume above the labels' foot falls by some 45 %, tests/meshes). A stub
// stage (a run continued from a kept checkpoint) is named and left out; a folder without
// parts, with two parts and no --part, or a part whose first surface is not kept (and is no
// tester sample to mesh again) is refused, naming what is wrong.
#include "coupling/app/life_command.h"
#include "coupling/output/grid_history.h"
#include "coupling/output/hdf5_file.h"
#include "error_of.h"
#include "meshes/constants.h"
#include "meshes/sample_generator.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace wear;
namespace fs = std::filesystem;

namespace {

const int element = meshes::label::convex_element(1, 1);

meshes::SurfaceMesh block(double label_radius) {
  const double r = 4e-3, c = 3e-3;
  const auto inside = [=](double x, double y) {
    return (std::pow(x - 8e-3, 2) + std::pow(y - 8e-3, 2)) / (r * r);
  };
  return meshes::testing::height_field_block(
      64, 64, 16e-3, 16e-3,
      [=](double x, double y) { return 5e-3 + c * std::sqrt(std::max(0.0, 1 - inside(x, y))); },
      [=](double x, double y) {
        return std::sqrt(inside(x, y)) * r < label_radius ? element : meshes::label::base;
      });
}

void write_surface(coupling::GridHistory& history, int stage, const meshes::SurfaceMesh& s) {
  meshes::VtuGrid g;
  g.points = s.vertices;
  for (const auto& t : s.triangles)
    g.connectivity.insert(g.connectivity.end(), t.begin(), t.end());
  g.cell_data.push_back({"label", 1, {s.face_labels.begin(), s.face_labels.end()}});
  history.add_stage(stage, stage, g);
}

// The rows of element_life.csv: stage -> volume [m^3] of the element.
std::map<int, double> volumes(const std::string& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3,"
                  "measured_by");
  std::map<int, double> v;
  while (std::getline(in, line)) {
    std::vector<std::string> c;
    std::stringstream row(line);
    for (std::string x; std::getline(row, x, ',');)
      c.push_back(x);
    REQUIRE(c.size() == 7);
    REQUIRE(c[3] == "C11");
    v[std::stoi(c[0])] = std::stod(c[5]);
  }
  return v;
}

} // namespace

TEST_CASE("wearsim life measures the kept surfaces on the unworn footprints", "[life]") {
  const fs::path run = fs::temp_directory_path() / "life-command-test";
  fs::remove_all(run);
  const fs::path part = run / "parts" / "plate";
  fs::create_directories(part);
  {
    coupling::GridHistory history(part.string(), "surface");
    write_surface(history, 0, block(4.3e-3));
    write_surface(history, 1, block(4.3e-3));
    write_surface(history, 2, block(2.5e-3));
    coupling::Hdf5File stub(history.stage_path(3, ".h5"));
    stub.attribute("/", "xdmf", std::string("<Grid/>"));
    stub.commit();
  }
  std::ofstream(part / "part_life.csv")
      << "stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3\n"
      << "1,0,0,C11,0.003,1e-07\n1,0,0,part,0.005,1e-06\n"
      << "2,10,280,C11,0.002,5e-08\n2,10,280,part,0.005,1e-06\n"
      << "3,20,560,C11,0.001,4e-08\n3,20,560,part,0.005,1e-06\n";
  std::ostringstream out;
  REQUIRE(coupling::run_life_command({run.string()}, out) == 0);
  INFO(out.str());
  CHECK(out.str().find("not measured (no surface kept in the folder): 3") != std::string::npos);
  const auto v = volumes((part / "element_life.csv").string());
  REQUIRE(v.size() == 2);
  const double half_ellipsoid = 2.0 / 3.0 * wear::pi * 4e-3 * 4e-3 * 3e-3;
  CHECK(v.at(1) == Approx(half_ellipsoid).epsilon(0.02));
  CHECK(v.at(2) == Approx(v.at(1)).epsilon(1e-12));

  // What is refused.
  CHECK_THAT(error_of([&] { coupling::run_life_command({(run / "parts").string()}, out); }),
             Catch::Contains("holds no parts/ folder"));
  fs::create_directories(run / "parts" / "other");
  CHECK_THAT(error_of([&] { coupling::run_life_command({run.string()}, out); }),
             Catch::Contains("has 2 parts; name one with --part"));
  CHECK_THAT(error_of([&] {
               coupling::run_life_command({run.string(), "--part", "other"}, out);
             }),
             Catch::Contains("part_life.csv"));
  fs::remove(part / "surface" / "stage_0000.h5");
  CHECK_THAT(error_of([&] {
               coupling::run_life_command({run.string(), "--part", "plate"}, out);
             }),
             Catch::Contains("does not hold the first surface"));
  fs::remove_all(run);
}

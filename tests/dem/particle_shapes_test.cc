// The shape library (dem/scene/particle_shapes.cc): each shape's stated Zingg ratios are those
// of its integrated body, to the two digits the description gives; template files are read with
// their comments and refused, by file and line, when a line is not four numbers.
#include "dem/scene/particle_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <string>

using namespace wear::dem;

TEST_CASE("each library shape has the aspect ratios its description states", "[dem][clump]") {
  std::set<std::string> names;
  const std::regex ratios(R"(I/L = ([0-9.]+), S/I = ([0-9.]+))");
  for (const auto& e : particle_shapes()) {
    CAPTURE(e.name);
    CHECK(names.insert(e.name).second);
    CHECK(e.members.size() >= 1);
    CHECK(e.members.size() <= 8);
    std::smatch m;
    REQUIRE(std::regex_search(e.description, m, ratios));
    const Vec3 x = body_extents(clump_shape({e.name, e.members}));
    CAPTURE(x.y / x.x, x.z / x.y);
    CHECK(std::abs(x.y / x.x - std::stod(m[1])) < 0.006);
    CHECK(std::abs(x.z / x.y - std::stod(m[2])) < 0.006);
  }
  CHECK(particle_shapes().front().name == "sphere");
}

TEST_CASE("an unknown shape name is refused with the parameter and the library's names",
          "[dem][clump]") {
  CHECK(named_clump_template("flat 4", "DEM/Particle shape").members.size() == 4);
  CHECK_THROWS_WITH(named_clump_template("cube", "DEM/Particle shape"),
                    Catch::Contains("DEM/Particle shape = 'cube' is not a shape") &&
                        Catch::Contains("crushed stone 8"));
}

TEST_CASE("a template file is read line by line, comments skipped, bad lines named",
          "[dem][clump]") {
  const std::string path = "particle_shapes_test_template.txt";
  {
    std::ofstream f(path);
    f << "# a two-sphere grain\n0 0 0 1.0\n\n  1.2 0 0 0.8 # the smaller end\n";
  }
  const ClumpTemplate t = read_clump_template(path);
  REQUIRE(t.members.size() == 2);
  CHECK(t.members[1].centre.x == 1.2);
  CHECK(t.members[1].radius == 0.8);
  {
    std::ofstream f(path);
    f << "0 0 0 1\n0 0 1\n";
  }
  CHECK_THROWS_WITH(read_clump_template(path),
                    Catch::Contains(path + "', line 2: expected four numbers"));
  {
    std::ofstream f(path);
    f << "0 0 0 -1\n";
  }
  CHECK_THROWS_WITH(read_clump_template(path),
                    Catch::Contains("line 1: the radius must be positive"));
  {
    std::ofstream f(path);
    f << "# nothing\n";
  }
  CHECK_THROWS_WITH(read_clump_template(path), Catch::Contains("holds no member sphere"));
  std::remove(path.c_str());
  CHECK_THROWS_WITH(read_clump_template(path), Catch::Contains("cannot be opened"));
}

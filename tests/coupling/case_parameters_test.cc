#include "coupling/case_parameters.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

using namespace wear::coupling;

namespace {
std::string write(const std::string& name, const std::string& text) {
  std::ofstream(name) << text;
  return name;
}
} // namespace

TEST_CASE("reference case files parse and validate", "[coupling][parameters]") {
  const auto c = read_case(WEAR_SOURCE_DIR "/cases/reference/convex.prm");
  CHECK(c.geometry.sample.convex);
  CHECK(c.geometry.sample.pattern.a == 8e-3);
  CHECK(c.geometry.placement.incline_deg == 2);
  const auto p = read_case(WEAR_SOURCE_DIR "/cases/reference/plain.prm");
  CHECK_FALSE(p.geometry.sample.convex);
}

TEST_CASE("resolved parameters round-trip", "[coupling][parameters]") {
  auto c = read_case(WEAR_SOURCE_DIR "/cases/reference/convex.prm");
  c.geometry.sample.pattern.h = 5.5e-3;
  c.output.directory = "elsewhere";
  write_resolved_parameters(c, "resolved.prm");
  const auto r = read_case("resolved.prm");
  CHECK(r.geometry.sample.pattern.h == 5.5e-3);
  CHECK(r.output.directory == "elsewhere");
  CHECK(r.geometry.tester.outer_radius == c.geometry.tester.outer_radius);
}

TEST_CASE("bad case files fail naming the parameter", "[coupling][parameters]") {
  CHECK_THROWS_WITH(read_case("missing.prm"), Catch::Contains("missing.prm"));
  const auto misspelled = write("misspelled.prm", "subsection Geometry\n subsection Sample\n"
                                                  "  set Thicknes = 0.01\n end\nend\n");
  CHECK_THROWS_WITH(read_case(misspelled), Catch::Contains("Thicknes"));
  const auto bad_value = write("bad_value.prm", "subsection Geometry\n subsection Sample\n"
                                                "  set Thickness = ten\n end\nend\n");
  CHECK_THROWS_WITH(read_case(bad_value), Catch::Contains("Thickness"));
  const auto negative = write("negative.prm", "subsection Geometry\n subsection Sample\n"
                                              "  subsection Pattern\n   set b = -2e-3\n  end\n"
                                              " end\nend\n");
  CHECK_THROWS_WITH(read_case(negative), Catch::Contains("Pattern/b"));
  const auto mm = write("mm.prm", "subsection Geometry\n subsection Sample\n"
                                  "  set Mesh size = 1\n end\nend\n");
  CHECK_THROWS_WITH(read_case(mm), Catch::Contains("Mesh size"));
}

TEST_CASE("every parameter is documented", "[coupling][parameters]") {
  std::ostringstream out;
  print_parameters(out);
  const auto text = out.str();
  for (const char* name : {"Mesh size", "First column offset", "Consolidator angle", "Directory"})
    CHECK(text.find(name) != std::string::npos);
}

#include "coupling/parameters/case_consistency.h"
#include "coupling/parameters/case_parameters.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
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
  // docs/wear-tester.md defaults
  CHECK(c.dem.psd.scaling_factor == 4);
  CHECK(c.dem.particle_wall.friction == 0.30);
  CHECK(c.wear_law.archard_coefficient == 5e-9);
}

TEST_CASE("every case file under cases/ parses, validates, passes the consistency checks "
          "without a warning and writes its own folder",
          "[coupling][parameters]") {
  // Case files are run from the repository root, where their INCLUDE paths start.
  struct InDirectory {
    std::filesystem::path before = std::filesystem::current_path();
    explicit InDirectory(const std::filesystem::path& p) { std::filesystem::current_path(p); }
    ~InDirectory() { std::filesystem::current_path(before); }
  } in_root(WEAR_SOURCE_DIR);
  std::set<std::string> directories;
  int n_files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(WEAR_SOURCE_DIR "/cases")) {
    // A folder that holds a checkpoint (or a kept, compressed one) or a summary is a kept run
    // (a run to be continued, or
    // the calibration kept for the report): its parameters.prm is the resolved copy of a case,
    // naming that case's output folder, and its calibration.prm a written result, not a case.
    if (e.path().extension() != ".prm" ||
        std::filesystem::exists(e.path().parent_path() / "checkpoint.h5") ||
        std::filesystem::exists(e.path().parent_path() / "checkpoint.h5.xz") ||
        std::filesystem::exists(e.path().parent_path() / "summary.csv"))
      continue;
    INFO(e.path().string());
    ++n_files;
    std::ostringstream warnings;
    const auto c = read_case(e.path().string(), warnings);
    CHECK(directories.insert(c.output.directory).second); // no two cases share an output
    // The quick tester's cases set DEM/Threads = 2; on a machine with one core that warns.
    std::string text = warnings.str();
    if (text.find("DEM/Threads") != std::string::npos)
      text.clear();
    CHECK(text.empty());
    CHECK(check_consistency(c).size() == (warnings.str().empty() ? 0u : 1u));
  }
  CHECK(n_files >= 20);
}

TEST_CASE("resolved parameters round-trip", "[coupling][parameters]") {
  auto c = read_case(WEAR_SOURCE_DIR "/cases/reference/convex.prm");
  c.geometry.sample.pattern.h = 5.5e-3;
  c.output.directory = "elsewhere";
  c.dem.psd.diameters = {1e-3, 2e-3};
  c.dem.psd.mass_fractions = {0.4, 0.6};
  c.dem.snapshot_revolutions = {2, 5};
  c.wear_law.model = "frictional-work";
  write_resolved_parameters(c, "resolved.prm");
  const auto r = read_case("resolved.prm");
  CHECK(r.geometry.sample.pattern.h == 5.5e-3);
  CHECK(r.output.directory == "elsewhere");
  CHECK(r.dem.psd.diameters == std::vector<double>{1e-3, 2e-3});
  CHECK(r.dem.psd.mass_fractions == std::vector<double>{0.4, 0.6});
  CHECK(r.dem.snapshot_revolutions == std::vector<int>{2, 5});
  CHECK(r.wear_law.model == "frictional-work");
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
  const auto law = write("law.prm", "subsection Wear law\n set Model = archrad\nend\n");
  CHECK_THROWS_WITH(read_case(law), Catch::Contains("archrad"));
  const auto alpha =
      write("alpha.prm", "subsection Wear law\n set Archard coefficient = -5e-9\nend\n");
  CHECK_THROWS_WITH(read_case(alpha), Catch::Contains("Archard coefficient"));
  const auto dt = write("dt.prm", "subsection DEM\n set Time step fraction = 0.6\nend\n");
  CHECK_THROWS_WITH(read_case(dt), Catch::Contains("DEM/Time step fraction"));
  const auto width =
      write("width.prm", "subsection DEM\n set Coarse-graining width = -1e-3\nend\n");
  CHECK_THROWS_WITH(read_case(width), Catch::Contains("DEM/Coarse-graining width"));
  const auto traction =
      write("traction.prm", "subsection DEM\n set Wall traction = smoothed\nend\n");
  CHECK_THROWS_WITH(read_case(traction), Catch::Contains("Wall traction"));
  const auto psd = write("psd.prm", "subsection DEM\n set PSD diameters = 2e-3, -2.65e-3, "
                                    "3.35e-3\nend\n");
  CHECK_THROWS_WITH(read_case(psd), Catch::Contains("diameter"));
  const auto fractions =
      write("fractions.prm", "subsection DEM\n set PSD mass fractions = 0.25, 0.5\nend\n");
  CHECK_THROWS(read_case(fractions));
  const auto radius =
      write("radius.prm", "subsection FEM\n set Stress averaging radius = -1e-3\nend\n");
  CHECK_THROWS_WITH(read_case(radius), Catch::Contains("FEM/Stress averaging radius"));
}

TEST_CASE("the stress averaging radius is the mean particle radius unless set",
          "[coupling][parameters]") {
  // Number fractions n_k ~ f_k / d_k^3 of the default PSD (2.0, 2.65, 3.35 mm; 0.25, 0.5,
  // 0.25 by mass) give a mean diameter of 2.408 mm at s = 1; the radius at s = 4: 4.8165 mm.
  CaseParameters p;
  CHECK(stress_averaging_radius(p) == Approx(4.8165e-3).epsilon(1e-4));
  p.dem.psd.scaling_factor = 1;
  CHECK(stress_averaging_radius(p) == Approx(4.8165e-3 / 4).epsilon(1e-4));
  p.fem.elasticity.averaging_radius = 2e-3;
  CHECK(stress_averaging_radius(p) == 2e-3);
}

TEST_CASE("every parameter is documented", "[coupling][parameters]") {
  std::ostringstream out;
  print_parameters(out);
  const auto text = out.str();
  for (const char* name :
       {"Mesh size", "First column offset", "Consolidator angle", "Directory", "Scaling factor",
        "Archard coefficient", "frictional-work", "Reference method", "Update interval",
        "PSD mass fractions", "Coarse-graining width", "Wall traction", "Wear field"})
    CHECK(text.find(name) != std::string::npos);
}

TEST_CASE("the a-priori depth estimate lies above the measured wear, within its floor",
          "[coupling][parameters]") {
  // Measured wear per revolution over the wear-face area (wearsim mesh) against the estimate's
  // mean depth alpha p Theta R: the estimate must stay an upper one (the bed cannot slide
  // past the sample faster than the floor turns), and the check's floor
  // depth_efficiency_floor must lie at least 5 times below the lowest measured ratio, or the
  // depth-cap check could refuse a run that works.
  struct Measured {
    const char* case_file;
    double wear;      ///< [m^3] per revolution
    double wear_area; ///< [m^2] base top and elements
  };
  const Measured runs[] = {
      {"/cases/reference/plain.prm", 62.48e-9, 12000e-6},  // CHANGELOG.md, 2026-11-22 (1 mm)
      {"/cases/reference/convex.prm", 34.97e-9, 14900e-6}, // the same
      {"/cases/sector-30/plain.prm", 1.88e-9, 12000e-6},   // CHANGELOG.md, seed 20111
      {"/cases/sector-30/convex.prm", 1.24e-9, 14625e-6},  // the same, seed 2 (the lowest)
  };
  double lowest = 1;
  for (const auto& m : runs) {
    INFO(m.case_file);
    auto c = read_case(std::string(WEAR_SOURCE_DIR) + m.case_file);
    c.coupling.amplification = 1;
    c.coupling.revolutions_per_stage = 1;
    const StageDepthEstimate e = stage_depth_estimate(c);
    REQUIRE(e.known);
    const double ratio = m.wear / m.wear_area / e.mean_depth;
    CHECK(ratio < 1);
    lowest = std::min(lowest, ratio);
  }
  CHECK(lowest == Approx(0.072).margin(0.005));
  CHECK(depth_efficiency_floor * 5 < lowest);
}

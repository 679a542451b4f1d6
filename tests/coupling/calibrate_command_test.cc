// `wearsim calibrate`: a plain-sample DEM run is calibrated to a chosen wear per revolution,
// and the same run with the calibrated coefficient wears exactly that (the wear law is linear
// in its coefficient and does not act on the flow of a fixed geometry). Bad input is refused
// naming the option or the file.
#include "coupling/app/calibrate_command.h"
#include "coupling/app/run_command.h"
#include "coupling/parameters/tester_scene_case.h"
#include "error_of.h"
#include "small_tester.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace wear::coupling;

namespace {

double wear_of_first_revolution(const std::string& dir) {
  std::ifstream in(dir + "/parts/sample/summary.csv");
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  std::stringstream h(header), r(row);
  for (std::string name, cell; std::getline(h, name, ',') && std::getline(r, cell, ',');)
    if (name == "wear_volume_m3")
      return std::stod(cell);
  return -1;
}
} // namespace

TEST_CASE("volumes need a unit and a positive value", "[coupling][calibrate]") {
  CHECK(parse_volume("35.2mm^3", "--measured") == Approx(35.2e-9).epsilon(1e-15));
  CHECK(parse_volume("35.2 mm3", "--measured") == Approx(35.2e-9).epsilon(1e-15));
  CHECK(parse_volume("0.5 cm^3", "--measured") == Approx(0.5e-6).epsilon(1e-15));
  CHECK(parse_volume("3e-8 m^3", "--measured") == Approx(3e-8).epsilon(1e-15));
  CHECK(error_of([] { parse_volume("35.2", "--measured"); }).find("needs a volume unit") !=
        std::string::npos);
  CHECK(error_of([] { parse_volume("35.2 g", "--measured"); }).find("not 'g'") !=
        std::string::npos);
  CHECK(error_of([] { parse_volume("-1 mm^3", "--measured"); }).find("positive") !=
        std::string::npos);
  CHECK(error_of([] { parse_volume("abc", "--measured"); }).find("--measured") !=
        std::string::npos);
}

TEST_CASE("wearsim calibrate: the calibrated coefficient reproduces the measured wear",
          "[coupling][calibrate]") {
  auto p = small_tester_case("calibrate_run", false);
  p.dem.revolutions = 1;
  std::filesystem::remove_all(p.output.directory);
  std::ostringstream log;
  run_scene_case(dem_case_of(p), log, {false, 0});
  const double simulated = wear_of_first_revolution(p.output.directory);
  REQUIRE(simulated > 0);

  // One revolution does not reach steady state: refused unless --from names the start.
  CHECK(error_of([&] {
          calibrate(p.output.directory, 1e-9, 10);
        }).find("never reached steady state") != std::string::npos);
  CHECK(error_of([&] {
          std::ostringstream out;
          run_calibrate_command(
              {p.output.directory, "--measured", "12", "--revolutions", "10", "--from", "1"}, out);
        }).find("needs a volume unit") != std::string::npos);
  CHECK(error_of([] {
          calibrate("no_such_run", 1e-9, 10, 1);
        }).find("no_such_run/parameters.prm") != std::string::npos);

  // A "measured" 2.5 x the simulated wear per revolution over 40 simulated revolutions.
  const double measured = 40 * 2.5 * simulated;
  std::ostringstream out;
  char volume[64];
  std::snprintf(volume, sizeof volume, "%.17g m^3", measured);
  REQUIRE(run_calibrate_command(
              {p.output.directory, "--measured", volume, "--revolutions", "40", "--from", "1"},
              out) == 0);
  INFO(out.str());
  const auto c = calibrate(p.output.directory, measured, 40, 1);
  CHECK(c.calibrated == Approx(2.5 * p.wear_law.archard_coefficient).epsilon(1e-12));
  std::ifstream file(p.output.directory + "/calibration.prm");
  std::stringstream text;
  text << file.rdbuf();
  CHECK(text.str().find("set Archard coefficient") != std::string::npos);
  {
    // A case file takes the value with an INCLUDE line after its own Wear law subsection.
    std::ofstream prm("calibrated_case.prm");
    prm << "subsection Wear law\n  set Archard coefficient = 1e-9\nend\n"
        << "INCLUDE " << std::filesystem::absolute(p.output.directory + "/calibration.prm").string()
        << "\n";
  }
  CHECK(read_case("calibrated_case.prm").wear_law.archard_coefficient ==
        Approx(c.calibrated).epsilon(1e-8));

  // The same run with the calibrated coefficient: the wear per revolution is the measured one.
  auto q = p;
  q.output.directory = "calibrate_check";
  q.wear_law.archard_coefficient = c.calibrated;
  std::filesystem::remove_all(q.output.directory);
  std::ostringstream log2;
  run_scene_case(dem_case_of(q), log2, {false, 0});
  CHECK(wear_of_first_revolution(q.output.directory) == Approx(measured / 40).epsilon(1e-9));
}

TEST_CASE("wearsim calibrate: a law of sliding and impact scales both coefficients alike",
          "[coupling][calibrate][impact]") {
  // The sliding-impact law is linear in its two coefficients together: the calibration
  // scales both by one factor (their ratio kept), and the run with them wears the measured
  // volume, its impact part included.
  auto p = small_tester_case("calibrate_impact_run", false);
  p.dem.revolutions = 1;
  p.wear_law.model = "sliding-impact";
  p.wear_law.sliding_coefficient = 5e-9;
  p.wear_law.impact_coefficient = 2e-8;
  std::filesystem::remove_all(p.output.directory);
  std::ostringstream log;
  run_scene_case(dem_case_of(p), log, {false, 0});
  const double simulated = wear_of_first_revolution(p.output.directory);
  REQUIRE(simulated > 0);
  const double measured = 10 * 0.4 * simulated;
  const auto c = calibrate(p.output.directory, measured, 10, 1);
  CHECK(c.coefficient_name == "Sliding coefficient");
  CHECK(c.calibrated == Approx(0.4 * 5e-9).epsilon(1e-12));
  REQUIRE(c.also_scaled.size() == 1);
  CHECK(c.also_scaled[0].first == "Impact energy coefficient");
  CHECK(c.also_scaled[0].second == 2e-8);
  std::ostringstream out;
  char volume[64];
  std::snprintf(volume, sizeof volume, "%.17g m^3", measured);
  REQUIRE(run_calibrate_command(
              {p.output.directory, "--measured", volume, "--revolutions", "10", "--from", "1"},
              out) == 0);
  const CaseParameters calibrated = [&] {
    std::ofstream prm("calibrated_impact_case.prm");
    prm << "subsection Wear law\n  set Model = sliding-impact\nend\n"
        << "INCLUDE " << std::filesystem::absolute(p.output.directory + "/calibration.prm").string()
        << "\n";
    prm.close();
    return read_case("calibrated_impact_case.prm");
  }();
  CHECK(calibrated.wear_law.sliding_coefficient == Approx(0.4 * 5e-9).epsilon(1e-8));
  CHECK(calibrated.wear_law.impact_coefficient == Approx(0.4 * 2e-8).epsilon(1e-8));
  auto q = p;
  q.output.directory = "calibrate_impact_check";
  q.wear_law = calibrated.wear_law;
  std::filesystem::remove_all(q.output.directory);
  std::ostringstream log2;
  run_scene_case(dem_case_of(q), log2, {false, 0});
  CHECK(wear_of_first_revolution(q.output.directory) == Approx(measured / 10).epsilon(1e-9));
}

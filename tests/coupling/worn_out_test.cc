// A run ends once its part is worn out (Coupling/Worn out when): the small tester case of the
// stop-and-resume test (30-degree sector, s = 4, wear amplified 20 times) with a worn-out
// thickness a tenth of a micrometre under the unworn base top stops after its first staged
// stage, says "worn out at 560 h" (one revolution at 20x, 28 h a revolution), and its part's
// life table holds the stages it ran.
#include "coupling/app/life_command.h"
#include "wearsim_process.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string case_text(const std::string& dir, const std::string& worn_out) {
  return small_tester_case_file(dir, "1 dem-only, 3 staged",
                                "  set Hours per revolution = 28\n" + worn_out);
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

} // namespace

TEST_CASE("wearsim run: a run ends after the stage its part is worn out in",
          "[coupling][run][worn_out]") {
  const std::string dir = "worn_out_thickness";
  fs::remove_all(dir);
  std::ofstream(dir + ".prm") << case_text(dir, "  set Worn out when = thickness\n"
                                                "  set Worn-out thickness = 0.0099999");
  REQUIRE(run_wearsim(dir + ".prm", "", dir + ".log") == 0);
  const std::string log = file_text(dir + ".log");
  INFO(log);
  CHECK_THAT(log, Catch::Contains("part 'sample' worn out at 560 h after stage 2: its thinnest "
                                  "point"));
  const auto stages = lines_of(dir + "/parts/sample/stages.csv");
  CHECK(stages.size() == 3); // the header, the dem-only stage and the first staged one
  const auto life = lines_of(dir + "/parts/sample/part_life.csv");
  REQUIRE(life.size() > 2);
  CHECK(life.front() == "stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3");
  // Stage 1 (dem-only) stands for no hours, stage 2 for 560; the part row's thinnest point
  // is the unworn base top, then below the worn-out thickness.
  std::string part1, part2;
  for (const auto& l : life) {
    if (l.rfind("1,0,0,part,", 0) == 0)
      part1 = l;
    if (l.rfind("2,20,560,part,", 0) == 0)
      part2 = l;
  }
  INFO(file_text(dir + "/parts/sample/part_life.csv"));
  REQUIRE(!part1.empty());
  REQUIRE(!part2.empty());
  const auto height = [](const std::string& row) {
    std::stringstream s(row);
    std::string field;
    for (int k = 0; k < 5; ++k)
      std::getline(s, field, ',');
    return std::stod(field);
  };
  CHECK(height(part1) == Approx(0.010).epsilon(1e-9));
  CHECK(height(part2) < 0.0099999);
  // An element row per convex element standing: the convex sample has 23.
  std::size_t n_elements = 0;
  for (const auto& l : life)
    n_elements += l.rfind("1,0,0,C", 0) == 0;
  CHECK(n_elements == 23);
  // element_life.csv: the same 23 on their unworn footprints; on the unworn mesh (stage 1) within
  // 0.5 % of part_life.csv's total (the outlines are the labels' loops; steep flank faces that
  // face down count there only), less after the staged stage; `wearsim life` on the run's kept
  // surfaces writes the same table.
  const std::string on_footprints = dir + "/parts/sample/element_life.csv";
  const auto kept = lines_of(on_footprints);
  REQUIRE(kept.size() == 1 + 2 * 23);
  CHECK(kept.front() == "stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3,"
                        "measured_by");
  const auto total = [](const std::vector<std::string>& rows, const std::string& stage) {
    double v = 0;
    for (const auto& l : rows)
      if (l.rfind(stage + "C", 0) == 0) {
        std::stringstream s(l);
        std::string field;
        for (int k = 0; k < 6; ++k)
          std::getline(s, field, ',');
        v += std::stod(field);
      }
    return v;
  };
  CHECK(total(kept, "1,0,0,") == Approx(total(life, "1,0,0,")).epsilon(0.005));
  CHECK(total(kept, "2,20,560,") < total(kept, "1,0,0,"));
  const std::string written = file_text(on_footprints);
  fs::remove(on_footprints);
  std::ostringstream out;
  REQUIRE(wear::coupling::run_life_command({dir}, out) == 0);
  CHECK(file_text(on_footprints) == written);
}

TEST_CASE("wearsim run: 'Worn out when = elements gone' on a part without elements is refused",
          "[coupling][run][worn_out]") {
  const std::string dir = "worn_out_plain";
  fs::remove_all(dir);
  std::string text = case_text(dir, "  set Worn out when = elements gone");
  text.replace(text.find("convex"), 6, "plain");
  std::ofstream(dir + ".prm") << text;
  CHECK(run_wearsim(dir + ".prm", "", dir + ".log") != 0);
  CHECK_THAT(file_text(dir + ".log"),
             Catch::Contains("Coupling/Worn out when = elements gone: part 'sample' has no "
                             "convex elements"));
}

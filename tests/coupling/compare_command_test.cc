// `wearsim compare` on run folders written by the run output itself (RunOutput::write_tables
// and write_resolved_parameters) from constructed revolutions: wear per revolution an AR(1)
// series (phi = 0.5) around a chosen mean, steady from revolution 5.
// - one run per side: the interval comes from one run's revolutions (batch means) and says
//   so; the printed means and the reduction are those of coupling/analysis/interval.h;
// - two runs per side (two seeds): the interval is across runs, and two sides drawn around
//   the same mean are called not significant at 95 %;
// - bad input (missing folder, no steady state, mixed sample kinds, a repeated seed, too few
//   revolutions, wrong syntax) stops with a message naming the side, folder and parameter;
// - scene runs (`--part`): a wearing part's wear per stage from its first staged stage, two
//   seeds a side, the interval across runs of each run's mean; a scene run without --part, a
//   part the run does not have, and --part without a name are refused.
#include "coupling/analysis/interval.h"
#include "coupling/app/calibrate_command.h"
#include "coupling/app/compare_command.h"
#include "coupling/output/run_output.h"
#include "meshes/constants.h"
#include "plate_scene.h"
#include "small_tester.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>

using namespace wear::coupling;

namespace {
struct FakeRun {
  bool convex = false;
  std::uint64_t seed = 1;
  double mean = 1e-9; ///< [m^3] wear per revolution around which the series varies
  int n_revolutions = 30;
  int steady_revolution = 5; ///< 0: never steady
};

// The wear per revolution of a fake run: mean (1 + 0.1 x AR(1), phi = 0.5), from its seed.
std::vector<double> wear_series(const FakeRun& f) {
  std::mt19937_64 rng(f.seed);
  const auto uniform = [&] { return (double(rng() >> 11) + 0.5) * 0x1.0p-53; };
  std::vector<double> w;
  double v = 0;
  for (int r = 1; r <= f.n_revolutions; ++r) {
    const double z = std::sqrt(-2 * std::log(uniform())) * std::cos(2 * wear::pi * uniform());
    v = 0.5 * v + z;
    w.push_back(f.mean * (1 + 0.1 * v));
  }
  return w;
}

void write_run(const std::string& dir, const FakeRun& f) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  CaseParameters p = small_tester_case(dir, f.convex);
  p.dem.seed = f.seed;
  write_resolved_parameters(p, dir + "/parameters.prm");
  const auto wear = wear_series(f);
  std::vector<wear::dem::RevolutionRecord> revolutions;
  double cumulative = 0;
  for (int r = 1; r <= f.n_revolutions; ++r) {
    wear::dem::RevolutionRecord rec;
    rec.revolution = r;
    rec.wear_volume = wear[std::size_t(r - 1)];
    cumulative += rec.wear_volume;
    rec.wear_volume_cumulative = cumulative;
    rec.column_wear = {0.4 * rec.wear_volume, 0.6 * rec.wear_volume};
    rec.column_normal_force.resize(2); // summary.csv has a force column per wear column
    rec.steady_revolution = r >= f.steady_revolution ? f.steady_revolution : 0;
    rec.steady = rec.steady_revolution > 0;
    revolutions.push_back(rec);
  }
  std::vector<StageRecord> stages(2);
  for (int s = 0; s < 2; ++s) {
    stages[std::size_t(s)].stage = s + 1;
    stages[std::size_t(s)].first_revolution = s * f.n_revolutions / 2 + 1;
    stages[std::size_t(s)].last_revolution = (s + 1) * f.n_revolutions / 2;
    stages[std::size_t(s)].max_von_mises_ball = (s + 1) * 1e6;
    stages[std::size_t(s)].max_von_mises_qp = (s + 1) * 3e6;
    stages[std::size_t(s)].safety_factor = 250.0 / (s + 1);
    stages[std::size_t(s)].cumulative_applied = (s + 1) * 1e-9;
  }
  RunOutput(dir).write_tables(revolutions, stages, 2, {});
}

std::string compare(const std::vector<std::string>& args) {
  std::ostringstream out;
  REQUIRE(run_compare_command(args, out) == 0);
  return out.str();
}

std::string error_of(const std::vector<std::string>& args) {
  std::ostringstream out;
  try {
    run_compare_command(args, out);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::vector<double> after_steady(const FakeRun& f) {
  const auto w = wear_series(f);
  return {w.begin() + f.steady_revolution, w.end()};
}

std::string mm3(const Estimate& e) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g +- %.2g", e.mean * 1e9, e.half_width * 1e9);
  return buf;
}
} // namespace

TEST_CASE("wearsim compare: one run per side gives batch-means intervals and says so",
          "[coupling][compare]") {
  const FakeRun plain{false, 11, 1e-9}, convex{true, 12, 0.6e-9};
  write_run("compare_plain", plain);
  write_run("compare_convex", convex);
  const std::string table = compare({"compare_plain", "compare_convex"});
  INFO(table);
  CHECK(table.find("A (plain): interval from one run's 25 revolutions, batch means") !=
        std::string::npos);
  CHECK(table.find("B (convex): interval from one run's 25 revolutions, batch means") !=
        std::string::npos);
  // The printed figures are the batch means of revolutions 6 to 30.
  const Estimate a = batch_means(after_steady(plain)), b = batch_means(after_steady(convex));
  CHECK(table.find(mm3(a)) != std::string::npos);
  CHECK(table.find(mm3(b)) != std::string::npos);
  const Estimate r = reduction(a, b);
  char reduction_text[64];
  std::snprintf(reduction_text, sizeof reduction_text, "%+.1f +- %.1f %%", 100 * r.mean,
                100 * r.half_width);
  CHECK(table.find(reduction_text) != std::string::npos);
  // 40 % less wear with 10 % noise on each revolution: far outside either interval.
  CHECK(std::abs(r.mean - 0.4) < 0.1);
  CHECK(table.find("not significant") == std::string::npos);
  CHECK(table.find("column 2 wear [mm^3]") != std::string::npos);
  CHECK(table.find("stage 2 peak ball-averaged von Mises [MPa]") != std::string::npos);
  CHECK(table.find("plot: /usr/bin/python3 coupling/output/plot_run.py --compare compare_plain "
                   "-- compare_convex") != std::string::npos);
}

TEST_CASE("wearsim compare: several runs per side give intervals across runs",
          "[coupling][compare]") {
  // Two seeds per side, both sides around the same mean.
  const std::vector<FakeRun> runs = {
      {false, 21, 1e-9}, {false, 22, 1e-9}, {true, 23, 1e-9}, {true, 24, 1e-9}};
  const std::vector<std::string> dirs = {"compare_a1", "compare_a2", "compare_b1", "compare_b2"};
  for (std::size_t k = 0; k < runs.size(); ++k)
    write_run(dirs[k], runs[k]);
  const std::string table = compare({dirs[0], dirs[1], "--", dirs[2], dirs[3]});
  INFO(table);
  CHECK(table.find("A (plain): interval across 2 runs") != std::string::npos);
  CHECK(table.find("B (convex): interval across 2 runs") != std::string::npos);
  CHECK(table.find("batch means") == std::string::npos);
  // Side A: the mean and t_{0.975,1} interval of the two runs' means after steady state.
  const auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v)
      s += x;
    return s / double(v.size());
  };
  const Estimate a = independent_mean({mean(after_steady(runs[0])), mean(after_steady(runs[1]))});
  CHECK(table.find(mm3(a)) != std::string::npos);
  CHECK(table.find("not significant at 95 %") != std::string::npos);
  // Totals and per-stage figures get an interval across runs too (equal here: +- 0).
  const auto at = table.find("stage 1 peak ball-averaged von Mises [MPa]");
  REQUIRE(at != std::string::npos);
  const std::string stage_line = table.substr(at, table.find('\n', at) - at);
  CHECK(stage_line.find(" 1 +- 0 ") != std::string::npos);
}

TEST_CASE("wearsim compare: bad input names the side, the folder and what is wrong",
          "[coupling][compare]") {
  write_run("compare_ok", {false, 31, 1e-9});
  write_run("compare_ok2", {false, 32, 1e-9});
  write_run("compare_never_steady", {false, 33, 1e-9, 30, 0});
  write_run("compare_convex_side", {true, 34, 1e-9});
  write_run("compare_same_seed", {false, 31, 1e-9});
  write_run("compare_late_steady", {false, 35, 1e-9, 30, 29});
  CHECK_THAT(error_of({"compare_ok", "no_such_run"}),
             Catch::Contains("side B") && Catch::Contains("'no_such_run' does not exist"));
  CHECK_THAT(error_of({"compare_ok", "compare_never_steady"}),
             Catch::Contains("never reached steady state") && Catch::Contains("--from"));
  // --from names the first revolution when a run never became steady.
  CHECK(compare({"--from", "3", "compare_ok", "compare_never_steady"}).find("28 revolutions") !=
        std::string::npos);
  CHECK_THAT(error_of({"compare_ok", "compare_convex_side", "--", "compare_ok2"}),
             Catch::Contains("side A mixes sample kinds") &&
                 Catch::Contains("Geometry/Sample/Type"));
  CHECK_THAT(error_of({"compare_ok", "compare_same_seed", "--", "compare_ok2"}),
             Catch::Contains("same DEM/Seed (31)"));
  CHECK_THAT(error_of({"compare_ok", "compare_late_steady"}),
             Catch::Contains("one run with 1 revolution averaged gives no interval"));
  CHECK_THAT(error_of({"compare_ok", "compare_ok2", "compare_convex_side"}),
             Catch::Contains("'--' between the sides"));
  CHECK_THAT(error_of({"compare_ok", "--"}), Catch::Contains("side B names no run folder"));
  CHECK_THAT(error_of({"--from", "x", "compare_ok", "compare_ok2"}), Catch::Contains("--from 'x'"));
}

namespace {
/// A scene run of the plate case (plate_scene.h) with seed `seed`: its part 'plate' has a
/// dem-only stage and 12 staged ones whose wear is `mean` (1 + 0.1 x AR(1)).
std::vector<double> write_scene_run(const std::string& dir, std::uint64_t seed, double mean) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/parts/plate");
  CaseParameters p = read_text(dir + ".prm", plate_case(dir));
  p.dem.seed = seed;
  write_resolved_parameters(p, dir + "/parameters.prm");
  const auto wear = wear_series({false, seed, mean, 13, 1});
  std::vector<StageRecord> stages(13);
  for (std::size_t k = 0; k < stages.size(); ++k) {
    stages[k].stage = int(k) + 1;
    stages[k].scheme = k == 0 ? Scheme::dem_only : Scheme::staged;
    stages[k].dem_wear_volume = k == 0 ? 5 * mean : wear[k];
    stages[k].max_von_mises_ball = k == 0 ? 0 : 1e6;
    stages[k].cumulative_applied = double(k) * 1e-9;
  }
  RunOutput(dir + "/parts/plate").write_tables({}, stages, 0, {});
  return {wear.begin() + 1, wear.end()}; // the staged stages
}
} // namespace

TEST_CASE("wearsim compare --part: a scene's wearing part, per stage from its first staged one",
          "[coupling][compare]") {
  const auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v)
      s += x;
    return s / double(v.size());
  };
  const std::vector<double> a1 = write_scene_run("compare_scene_a1", 41, 1e-9),
                            a2 = write_scene_run("compare_scene_a2", 42, 1e-9),
                            b1 = write_scene_run("compare_scene_b1", 43, 0.5e-9),
                            b2 = write_scene_run("compare_scene_b2", 44, 0.5e-9);
  const std::string table = compare({"--part", "plate", "compare_scene_a1", "compare_scene_a2",
                                     "--", "compare_scene_b1", "compare_scene_b2"});
  INFO(table);
  CHECK(table.find("A (part 'plate'): interval across 2 runs") != std::string::npos);
  CHECK(table.find("compare_scene_a1: stages 2-13 of 13") != std::string::npos);
  CHECK(table.find("per stage of part 'plate'") != std::string::npos);
  // The dem-only stage (5 times the wear) is left out: the figures are the staged stages'.
  const Estimate a = independent_mean({mean(a1), mean(a2)}),
                 b = independent_mean({mean(b1), mean(b2)});
  CHECK(table.find(mm3(a)) != std::string::npos);
  CHECK(table.find(mm3(b)) != std::string::npos);
  const Estimate r = reduction(a, b);
  CHECK(std::abs(r.mean - 0.5) < 0.1);
  CHECK(table.find("plot:") == std::string::npos);
  // Refusals naming what is wrong.
  CHECK_THAT(error_of({"compare_scene_a1", "compare_scene_b1"}),
             Catch::Contains("is a scene's") && Catch::Contains("--part"));
  CHECK_THAT(error_of({"--part", "skirt", "compare_scene_a1", "compare_scene_b1"}),
             Catch::Contains("no wearing part 'skirt'") && Catch::Contains("wearing walls: plate"));
  CHECK_THAT(error_of({"compare_scene_a1", "compare_scene_b1", "--part"}),
             Catch::Contains("--part needs the name"));
}

TEST_CASE("wearsim calibrate --part: a scene's part per second of its staged stages",
          "[coupling][calibrate]") {
  const std::string dir = "calibrate_scene";
  const std::vector<double> staged = write_scene_run(dir, 45, 1e-9);
  double sum = 0;
  for (double v : staged)
    sum += v;
  const CaseParameters p = read_case(dir + "/parameters.prm");
  const double rate = sum / double(staged.size()) / p.scene.stage_duration; // [m^3/s]
  // 2 mm^3 measured over 100 s of operation: the coefficient scales by (2e-9 / 100) / rate;
  // the dem-only stage, five times the wear, is left out.
  const Calibration c = calibrate(dir, 2e-9, 100, 0, "plate");
  CHECK(c.unit == "s");
  CHECK(c.n_revolutions == 12);
  CHECK(c.first_revolution == 2);
  // (stages.csv keeps 10 digits)
  CHECK(c.simulated_per_rev == Approx(rate).epsilon(1e-8));
  CHECK(c.calibrated / c.coefficient == Approx(2e-11 / rate).epsilon(1e-8));
  CHECK(calibrate(dir, 2e-9, 100, 5, "plate").n_revolutions == 9); // --from 5: stages 5 to 13
  // through the command: the part without an evaluation takes --time, not --revolutions
  std::ostringstream out;
  REQUIRE(run_calibrate_command({dir, "--part", "plate", "--measured", "2mm^3", "--time", "100"},
                                out) == 0);
  CHECK_THAT(out.str(), Catch::Contains("per s") && Catch::Contains("part 'plate'"));
  CHECK(std::filesystem::exists(dir + "/calibration.prm"));
  const auto refused = [&](const std::vector<std::string>& args) {
    std::ostringstream o;
    try {
      run_calibrate_command(args, o);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("not refused");
  };
  CHECK_THAT(refused({dir, "--part", "plate", "--measured", "2mm^3", "--revolutions", "4"}),
             Catch::Contains("--time"));
  CHECK_THAT(refused({dir, "--measured", "2mm^3", "--time", "100"}), Catch::Contains("--part"));
  CHECK_THAT(refused({dir, "--part", "skirt", "--measured", "2mm^3", "--time", "100"}),
             Catch::Contains("no wearing part 'skirt'"));
}

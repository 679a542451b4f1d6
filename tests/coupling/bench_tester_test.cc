// The tester workload of `wearsim bench dem` builds its reference case in code; it must be
// the case of cases/reference (all but the run length and the output folder), so the bench
// times what `wearsim run cases/reference/convex.prm` runs (the tester as a scene). Its options
// replace the case's values, and bad values stop the command naming the option before anything is
// built. A bed state written with --state is continued from the file instead of being filled again.
#include "coupling/app/bench_command.h"
#include "coupling/app/bench_tester.h"
#include "small_tester.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>

using namespace wear::coupling;

namespace {
const std::string reference_dir = std::string(WEAR_SOURCE_DIR) + "/cases/reference/";

CaseParameters read_quietly(const std::string& path) {
  std::ostringstream warnings;
  return read_case(path, warnings);
}
} // namespace

TEST_CASE("the bench's built-in reference tester is the case of cases/reference",
          "[coupling][bench]") {
  for (const bool convex : {true, false}) {
    const CaseParameters file =
        read_quietly(reference_dir + (convex ? "convex" : "plain") + ".prm");
    CaseParameters code = reference_tester_case(convex, file.dem.psd.scaling_factor);
    // What the bench does not use.
    code.dem.revolutions = file.dem.revolutions;
    code.dem.samples_per_revolution = file.dem.samples_per_revolution;
    code.dem.snapshot_revolutions = file.dem.snapshot_revolutions;
    code.output.directory = file.output.directory;
    INFO((convex ? "convex" : "plain"));
    CHECK(resolved_parameters(code) == resolved_parameters(file));
  }
}

TEST_CASE("the tester workload's options replace the case's values", "[coupling][bench]") {
  TesterBenchOptions o;
  CHECK(tester_bench_case(o).dem.psd.scaling_factor == 3);
  CHECK(tester_bench_case(o).geometry.sample.convex);
  o.scale = 6;
  o.convex = false;
  CHECK(tester_bench_case(o).dem.psd.scaling_factor == 6);
  CHECK(!tester_bench_case(o).geometry.sample.convex);
  o = {};
  o.case_file = reference_dir + "plain.prm";
  CHECK(tester_bench_case(o).dem.psd.scaling_factor == 4); // the file's
  CHECK(!tester_bench_case(o).geometry.sample.convex);
  o.convex = true;
  CHECK(tester_bench_case(o).geometry.sample.convex);
}

TEST_CASE("wearsim bench dem: a bad tester option stops naming the option", "[coupling][bench]") {
  std::ostringstream out;
  const auto run = [&](std::vector<std::string> args) {
    args.insert(args.begin(), {"dem", "--workload", "tester"});
    run_bench_command(args, out);
  };
  CHECK_THROWS_WITH(run({"--scale", "-1"}), Catch::Contains("--scale"));
  CHECK_THROWS_WITH(run({"--scale", "3x"}), Catch::Contains("--scale"));
  CHECK_THROWS_WITH(run({"--sample", "foo"}), Catch::Contains("--sample"));
  CHECK_THROWS_WITH(run({"--case", reference_dir + "missing.prm"}), Catch::Contains("missing.prm"));
  CHECK_THROWS_WITH(run_bench_command({"dem", "--workload", "annulus", "--scale", "2"}, out),
                    Catch::Contains("--workload tester"));
  CHECK(out.str().empty()); // stopped before any workload was built
}

TEST_CASE("wearsim bench dem --state: a flowing bed written once and continued from the file",
          "[coupling][bench]") {
  // The small tester (2,300 particles) as a case file; the state goes beside it.
  namespace fs = std::filesystem;
  const std::string dir = "bench_state";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_resolved_parameters(small_tester_case(dir, true), dir + "/case.prm");
  const std::string state = dir + "/state.h5";
  const auto bench = [&](std::vector<std::string> extra) {
    std::vector<std::string> args{"dem",     "--workload", "tester", "--case", dir + "/case.prm",
                                  "--state", state,        "--warm", "0",      "--steps",
                                  "20",      "--threads",  "2"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::ostringstream out;
    run_bench_command(args, out);
    return out.str();
  };
  const std::string first = bench({"--flow", "200"});
  CHECK_THAT(first, Catch::Contains("state written to " + state));
  CHECK_THAT(first, Catch::Contains("200 steps of flow, t = "));
  REQUIRE(fs::exists(state));
  const std::string second = bench({});
  CHECK_THAT(second, Catch::Contains("state from " + state));
  CHECK_THAT(second, !Catch::Contains("state written"));
  // The second bench continues from where the first one's flow ended.
  const auto time_after = [](const std::string& text, const std::string& before) {
    const auto at = text.find(before);
    REQUIRE(at != std::string::npos);
    return text.substr(at + before.size(), text.find(' ', at + before.size()) - at - before.size());
  };
  CHECK(time_after(second, "state from " + state + ": t = ") ==
        time_after(first, "200 steps of flow, t = "));
  // Another case (here another particle size) does not continue that bed.
  CHECK_THROWS_WITH(bench({"--scale", "5"}),
                    Catch::Contains("--state") && Catch::Contains("another case"));
  std::ostringstream out;
  CHECK_THROWS_WITH(
      run_bench_command(
          {"dem", "--workload", "tester", "--case", dir + "/case.prm", "--flow", "100000000"}, out),
      Catch::Contains("--flow"));
  fs::remove_all(dir);
}

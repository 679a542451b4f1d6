// The wear tester's evaluation on a scene (Scene/Evaluation, dem/scene/scene_evaluation.h): the
// small tester written as a scene by `wearsim tester-scene` and run by `wearsim run`, its
// sample evaluated per revolution. Checked: one record per revolution at the revolution's
// end; the records' wear adds up to the stages' wear-law volume (two sums of the same windows,
// one per stage for the FEM and one per revolution for the evaluation); the columns partition
// the wear face; the normal force on the wear face carries the weight of the bed above it
// (hydrostatic, the packing's bulk density, within the shear and the walls' friction); and a
// run stopped by SIGTERM inside a revolution resumes its evaluation bit for bit.
#include "coupling/app/calibrate_command.h"
#include "coupling/app/compare_command.h"
#include "coupling/parameters/tester_scene_case.h"
#include "small_tester.h"
#include "wearsim_process.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

using namespace wear;
using namespace wear::coupling;

namespace {

/// The records without their wall-clock figures.
std::vector<std::vector<double>> physical(std::vector<dem::RevolutionRecord> records) {
  std::vector<std::vector<double>> out;
  for (auto& r : records) {
    r.wall_seconds = r.particle_steps_per_second = 0;
    out.push_back({r.time, r.wear_volume, r.wear_volume_other, r.contact_total_wear_volume,
                   r.normal_force.mean, r.normal_force.std, r.bottom_speed.mean, r.bottom_spin.mean,
                   r.bed_height.mean, r.speed_over_sample.mean, double(r.steady_revolution),
                   r.fits.a});
    out.back().insert(out.back().end(), r.column_wear.begin(), r.column_wear.end());
  }
  return out;
}

} // namespace

TEST_CASE("a tester case through its scene: the sample evaluated per revolution, and resumed "
          "inside a revolution bit for bit",
          "[tester-scene][scene]") {
  // 2 revolutions of 5 samples a stage, a dem-only and a staged stage; a checkpoint after
  // every window.
  const auto case_of = [](const std::string& dir) {
    CaseParameters p = small_tester_case(dir, true);
    p.coupling.schedule = "1 dem-only, 1 staged";
    p.coupling.revolutions_per_stage = 2;
    p.output.checkpoint_interval = 1e-6;
    const CaseParameters s = tester_scene_case(p);
    std::ofstream(dir + ".prm") << tester_scene_text(s, "small_tester.h");
    return s;
  };
  const std::string a = "scene_evaluation_a";
  const CaseParameters s = case_of(a);
  const std::string run_a = s.output.directory;
  std::filesystem::remove_all(run_a);
  REQUIRE(run_wearsim(a + ".prm", "", a + ".log") == 0);
  INFO(file_text(a + ".log"));
  const Checkpoint ca = read_checkpoint(run_a + "/checkpoint.h5");
  REQUIRE(ca.scene.parts.size() == 1);
  const auto& part = ca.scene.parts[0];
  REQUIRE(part.evaluation);
  const auto& records = part.evaluation->history;
  const double revolution = s.scene.evaluation.period; // 30 deg at 90 deg/s
  CHECK(revolution == Approx(1.0 / 3).epsilon(1e-12));
  REQUIRE(records.size() == 4);
  REQUIRE(part.stages.size() == 2);
  const double t0 = ca.scene.time - 4 * revolution; // the stages begin after the settling
  for (std::size_t k = 0; k < records.size(); ++k) {
    INFO("revolution " << k + 1);
    CHECK(records[k].revolution == int(k) + 1);
    // a window ends on the step at or after its time: within a step (0.1 ms) of the nominal
    CHECK(std::abs(records[k].time - (t0 + double(k + 1) * revolution)) < 2e-4);
    double columns = 0;
    for (double c : records[k].column_wear)
      columns += c;
    CHECK(columns == Approx(records[k].wear_volume).epsilon(1e-12));
    CHECK(records[k].wear_volume > 0);
    CHECK(records[k].element_wear.size() > 0); // the convex sample's elements
    // The normal force on the wear face against the weight of the bed over it: density x
    // packing x g x bed height above the face x footprint (the elements' tops stand in the
    // bed, so the footprint is the whole face's). The bed turns over a sample whose elements
    // hold it back: their flanks take normal force from its drag besides its weight, and the
    // bed over the face thins while the bed around it bears on it. Measured 1.17 to 1.42 times
    // the weight (3 seeds, Loose factor 2.5 and 3, 4 revolutions each); held to 0.9 .. 1.5.
    const auto& g = s.geometry.sample;
    const double weight = s.dem.particle.density * s.dem.assumed_packing * 9.81 *
                          records[k].bed_height.mean * g.width * g.length;
    CHECK(records[k].normal_force.mean > 0.9 * weight);
    CHECK(records[k].normal_force.mean < 1.5 * weight);
  }
  for (std::size_t st = 0; st < 2; ++st) { // revolutions 2 st + 1 and 2 st + 2 are stage st + 1's
    INFO("stage " << st + 1);
    CHECK(part.stages[st].first_revolution == int(2 * st) + 1);
    CHECK(part.stages[st].last_revolution == int(2 * st) + 2);
    CHECK(records[2 * st].wear_volume + records[2 * st + 1].wear_volume ==
          Approx(part.stages[st].dem_wear_volume).epsilon(1e-10));
  }
  CHECK(physical_columns(run_a + "/parts/sample/summary.csv").size() == 5); // header + 4
  // `wearsim calibrate` averages the same records of the evaluated part (--part sample, or
  // without it): revolutions 2 to 4
  const Calibration cal = calibrate(run_a, 1e-9, 1, 2, "sample");
  CHECK(calibrate(run_a, 1e-9, 1, 2).simulated_per_rev == cal.simulated_per_rev);
  CHECK(cal.unit == "revolution");
  CHECK(cal.n_revolutions == 3);
  CHECK(cal.simulated_per_rev ==
        Approx((records[1].wear_volume + records[2].wear_volume + records[3].wear_volume) / 3)
            .epsilon(1e-9));

  const std::string b = "scene_evaluation_b";
  const std::string run_b = case_of(b).output.directory;
  std::filesystem::remove_all(run_b);
  const pid_t pid = start_wearsim(b + ".prm", "", b + ".log");
  // Inside a revolution of the staged stage: a checkpoint there with samples open.
  bool inside = false;
  while (!inside && waitpid(pid, nullptr, WNOHANG) == 0) {
    try {
      const Checkpoint c = read_checkpoint(run_b + "/checkpoint.h5");
      inside = c.stages_done == 1 && c.scene.n_records % 5 == 2;
    } catch (const std::exception&) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  REQUIRE(inside);
  kill(pid, SIGTERM);
  const int status = wait_for(pid);
  INFO(file_text(b + ".log"));
  REQUIRE(status == 128 + SIGTERM);
  const Checkpoint stopped = read_checkpoint(run_b + "/checkpoint.h5");
  REQUIRE(stopped.scene.parts[0].evaluation);
  if (stopped.scene.parts[0].evaluation->n_windows == 0)
    WARN("the signal came at a revolution's end; the resume below continues from there");
  REQUIRE(run_wearsim(b + ".prm", "--resume", b + ".resumed.log") == 0);
  INFO(file_text(b + ".resumed.log"));
  const Checkpoint cb = read_checkpoint(run_b + "/checkpoint.h5");
  CHECK(physical(cb.scene.parts[0].evaluation->history) == physical(records));
  for (const char* table : {"/parts/sample/summary.csv", "/parts/sample/stages.csv"}) {
    INFO(table);
    CHECK(physical_columns(run_b + table) == physical_columns(run_a + table));
  }
  // `wearsim compare` reads the evaluated sample as a tester's run: the same records on both
  // sides, no reduction; without --part the scene's evaluated part, as with it.
  std::ostringstream table, named;
  REQUIRE(run_compare_command({"--from", "2", run_a, "--", run_b}, table) == 0);
  INFO(table.str());
  CHECK_THAT(table.str(), Catch::Contains("A (convex)") && Catch::Contains("B (convex)") &&
                              Catch::Contains("+0.0"));
  REQUIRE(run_compare_command({"--part", "sample", "--from", "2", run_a, "--", run_b}, named) == 0);
  CHECK(named.str() == table.str());
}

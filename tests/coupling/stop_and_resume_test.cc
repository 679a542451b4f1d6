// `wearsim run` stopped inside a stage and resumed, as a cluster job or a user stops it: the
// wearsim program on a small tester case (30-degree sector, s = 4, one dem-only and two staged
// stages, wear amplified 20 times, 2 threads, an in-stage checkpoint every 0.5 s) is
// - stopped by SIGTERM at a random moment inside the DEM part of stage 2: it writes a
//   checkpoint, says how to resume and exits with 128 + 15;
// - killed by SIGKILL at a random moment inside stage 2 (after an in-stage checkpoint);
// and each, resumed with --resume, ends with the sample's stages.csv and summary.csv identical to
// the uninterrupted run in every physical column (wall-clock columns left out) and the same final
// surface and volume mesh, bit for bit. The random moment is printed (Catch's seed decides it).
// Also: the checkpoint a write replaces is kept, and a damaged latest checkpoint falls back to
// it with a warning; a folder holding a run is refused without --resume or --overwrite, and
// --overwrite deletes the old run only after the new run's first checkpoint.
#include "coupling/output/checkpoint.h"
#include "wearsim_process.h"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <thread>

using namespace wear::coupling;
namespace fs = std::filesystem;

namespace {

std::string case_text(const std::string& dir) {
  return small_tester_case_file(dir, "1 dem-only, 2 staged", "", "  set Checkpoint interval = 0.5");
}

// Waits until the run's latest checkpoint lies inside stage `stage` (at least one in-stage
// checkpoint written there); false if the run ended first.
bool wait_inside_stage(pid_t pid, const std::string& dir, int stage) {
  for (;;) {
    if (waitpid(pid, nullptr, WNOHANG) == pid)
      return false;
    try {
      const Checkpoint c = read_checkpoint(dir + "/checkpoint.h5");
      // inside a stage the open stage's loads cover a window or more
      if (c.stages_done == stage - 1 && !c.scene.parts.empty() &&
          c.scene.parts[0].open.duration > 0)
        return true;
    } catch (const std::exception&) { // not written yet
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

std::string write_case(const std::string& dir) {
  fs::remove_all(dir);
  fs::remove_all(dir + ".replaced");
  const std::string path = dir + ".prm";
  std::ofstream(path) << case_text(dir);
  return path;
}

} // namespace

TEST_CASE("wearsim run: stopped inside a stage by SIGTERM or SIGKILL, resumed bit for bit",
          "[coupling][run][stop]") {
  std::mt19937 random(Catch::rngSeed());
  std::uniform_int_distribution<int> delay_ms(0, 400);

  const std::string a = "stop_resume_a";
  const std::string case_a = write_case(a);
  REQUIRE(run_wearsim(case_a, "", a + ".log") == 0);
  INFO(file_text(a + ".log"));

  for (const int signal : {SIGTERM, SIGKILL}) {
    const std::string b = signal == SIGTERM ? "stop_resume_term" : "stop_resume_kill";
    const std::string case_b = write_case(b);
    const pid_t pid = start_wearsim(case_b, "", b + ".log");
    REQUIRE(wait_inside_stage(pid, b, 2));
    const int ms = delay_ms(random);
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    kill(pid, signal);
    const int status = wait_for(pid);
    const std::string stop_log = file_text(b + ".log");
    INFO((signal == SIGTERM ? "SIGTERM" : "SIGKILL") << " " << ms << " ms after the first "
                                                     << "in-stage checkpoint of stage 2\n"
                                                     << stop_log);
    CHECK(status == 128 + signal);
    if (signal == SIGTERM) {
      CHECK_THAT(stop_log, Catch::Contains("stopped by SIGTERM in stage 2 of 3") &&
                               Catch::Contains("wearsim run --resume"));
      CHECK(read_checkpoint(b + "/checkpoint.h5").scene.parts.at(0).open.duration > 0);
    }
    REQUIRE(run_wearsim(case_b, "--resume", b + ".resumed.log") == 0);
    const std::string resumed = file_text(b + ".resumed.log");
    INFO(resumed);
    CHECK_THAT(resumed, Catch::Contains("resumed after stage 1 of 3, inside stage 2"));
    check_same_run(a, b);
  }
}

TEST_CASE("wearsim run: a damaged latest checkpoint falls back to the one before it and a "
          "finished run is not overwritten unless asked",
          "[coupling][run][stop]") {
  const std::string dir = "stop_resume_guard";
  const std::string case_file = write_case(dir);
  REQUIRE(run_wearsim(case_file, "", dir + ".log") == 0);
  const std::string latest = dir + "/checkpoint.h5", previous = dir + "/checkpoint.previous.h5";
  REQUIRE(fs::exists(previous));
  const Checkpoint before = read_checkpoint(previous);
  CHECK(read_checkpoint(latest).stages_done == 3);
  CHECK(before.stages_done == 2);

  // A damaged latest checkpoint: the one before is read, with a warning naming both.
  const std::string whole = file_text(latest);
  std::ofstream(latest, std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() / 3);
  std::ostringstream warnings;
  const Checkpoint fallback = read_latest_checkpoint(latest, warnings);
  CHECK(fallback.stages_done == before.stages_done);
  CHECK(fallback.dem.position == before.dem.position);
  CHECK_THAT(warnings.str(),
             Catch::Contains("checkpoint.h5") && Catch::Contains("checkpoint.previous.h5"));
  std::ofstream(latest, std::ios::binary | std::ios::trunc) << whole;

  // The folder holds a run: refused without an option, named, nothing touched.
  const std::string stages_csv = "/parts/sample/stages.csv";
  const auto stages = file_text(dir + stages_csv);
  CHECK(run_wearsim(case_file, "", dir + ".again.log") == 1);
  CHECK_THAT(file_text(dir + ".again.log"), Catch::Contains("Output/Directory") &&
                                                Catch::Contains("--overwrite") &&
                                                Catch::Contains(dir));
  CHECK(file_text(dir + stages_csv) == stages);

  // --overwrite: the old run is moved aside, and deleted once the new run has its first
  // checkpoint (the run is killed then; its first stage is not needed here).
  const pid_t pid = start_wearsim(case_file, "--overwrite", dir + ".overwrite.log");
  bool aside_seen = false;
  const std::string deleted = "the replaced run in '" + dir + ".replaced' is deleted";
  while (waitpid(pid, nullptr, WNOHANG) != pid &&
         file_text(dir + ".overwrite.log").find(deleted) == std::string::npos) {
    aside_seen = aside_seen || fs::exists(dir + ".replaced" + stages_csv);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  wait_for(pid);
  const std::string log = file_text(dir + ".overwrite.log");
  INFO(log);
  CHECK(aside_seen);
  CHECK_THAT(log, Catch::Contains(deleted));
  CHECK(read_checkpoint(dir + "/checkpoint.h5").stages_done == 0);
  CHECK_FALSE(fs::exists(dir + ".replaced"));
}

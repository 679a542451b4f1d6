// `wearsim run` under mpirun: the wearsim program started by `mpiexec -np 2` on a small tester
// case (30-degree sector, one dem-only and two staged stages, wear amplified 20 times, one
// thread per rank, an in-stage checkpoint every 0.5 s), each run in its own folder with the
// case's Output/Directory relative to it (so that a run's folder can be copied and resumed as
// the same case):
// - stopped by SIGUSR1 (to mpiexec, which passes it to the ranks; Open MPI's mpiexec ends the
//   job a second after a SIGTERM, before a scene's window ends, so a job is stopped with
//   SIGUSR1, as cases/cluster/slurm-run.sh does) inside the DEM part of
//   stage 2, and killed by SIGKILL there after an in-stage checkpoint, each resumed on 2
//   ranks: the tables' physical columns, the worn surface and the bed equal the
//   uninterrupted 2-rank run's, bit for bit;
// - the stopped 2-rank run resumed as one process, and a stopped one-process run resumed on 2
//   ranks: they finish, say the scene is decomposed again, hold every particle, and the stage
//   they continue wears within 50 % of the uninterrupted run's: the stage's first part is the
//   same, the rest another realisation of the flow, and in this small bed one revolution's
//   wear differs by up to 70 % between realisations (a one-process run against a 2-rank run:
//   revolution 3, 7.4 against 4.4e-11 m^3). That the bed goes on as the decomposed one would
//   is checked in tests/dem_mpi/merged_state_test.cc, to 1e-12 m.
// [long]: the small sector (cases/sector-30/plain.prm) at 1, 2 and 4 ranks, its wear per
// revolution over the staged revolutions within the seeds' 95 % interval of its README.
#include "coupling/output/checkpoint.h"
#include "small_tester.h"
#include "wearsim_process.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <thread>

using namespace wear::coupling;
namespace fs = std::filesystem;

namespace {

/// The small tester of the coupling tests (small_tester.h), convex, one thread per rank, three
/// stages and an in-stage checkpoint every 0.5 s, its output in `out` beside the case file.
CaseParameters small_case() {
  CaseParameters p = small_tester_case("out", true);
  p.geometry.sample.mesh_size_bottom = 5e-3;
  p.dem.n_threads = 1;
  p.coupling.schedule = "1 dem-only, 2 staged";
  p.coupling.amplification = 20;
  p.coupling.max_depth_fraction = 5;
  p.output.checkpoint_interval = 0.5;
  return p;
}

/// A fresh folder holding the case file `case.prm` (the small case, or `text`).
std::string fresh(const std::string& dir, const std::string& text = "") {
  fs::remove_all(dir);
  fs::create_directories(dir);
  if (text.empty())
    write_resolved_parameters(small_case(), dir + "/case.prm");
  else
    std::ofstream(dir + "/case.prm") << text;
  return dir;
}

/// Waits until the run's latest checkpoint lies inside stage 2; false if the run ended first.
bool wait_inside_stage_2(pid_t pid, const std::string& out) {
  for (;;) {
    if (waitpid(pid, nullptr, WNOHANG) == pid)
      return false;
    try {
      const Checkpoint c = read_checkpoint(out + "/checkpoint.h5");
      if (c.stages_done == 1 && !c.scene.parts.empty() && c.scene.parts[0].open.duration > 0)
        return true;
    } catch (const std::exception&) { // not written yet
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

/// A run stopped by `signal` inside stage 2; returns its exit status.
int stop_inside_stage_2(const std::string& dir, int n_ranks, int signal) {
  const pid_t pid = start_in(dir, n_ranks, "", "case.prm", "stop.log");
  if (!wait_inside_stage_2(pid, dir + "/out"))
    return -1;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, signal);
  return wait_for(pid);
}

/// The wear of each stage (the sample's stages.csv, dem_wear_volume_m3).
std::vector<double> stage_wear(const std::string& out) {
  const auto rows = physical_columns(out + "/parts/sample/stages.csv");
  std::size_t column = 0;
  while (column < rows.at(0).size() && rows[0][column] != "dem_wear_volume_m3")
    ++column;
  std::vector<double> wear;
  for (std::size_t k = 1; k < rows.size(); ++k)
    wear.push_back(std::stod(rows[k].at(column)));
  return wear;
}

/// A run resumed on another rank count: it finishes, says so, holds the bed, and its stage 2
/// wears within 50 % of the uninterrupted run's.
void check_resumed_elsewhere(const std::string& a, const std::string& dir) {
  const std::string log = file_text(dir + "/resume.log");
  INFO(log);
  CHECK_THAT(log, Catch::Contains("decomposed again") &&
                      Catch::Contains("resumed after stage 1 of 3, inside stage 2"));
  const auto ca = read_checkpoint(a + "/checkpoint.h5");
  const auto cb = read_checkpoint(dir + "/out/checkpoint.h5");
  REQUIRE(cb.stages_done == 3);
  CHECK(cb.dem.position.size() == ca.dem.position.size()); // merged: the whole bed
  const auto wa = stage_wear(a), wb = stage_wear(dir + "/out");
  REQUIRE(wb.size() == 3);
  CHECK(wb[0] == wa[0]); // before the stop
  INFO("stage 2 wore " << wb[1] << " m^3, uninterrupted " << wa[1] << " m^3");
  CHECK(wb[1] == Approx(wa[1]).epsilon(0.5));
}

} // namespace

TEST_CASE("wearsim run over 2 ranks: stopped or killed inside a stage and resumed bit for bit, "
          "and resumed on another rank count",
          "[coupling][run][mpi]") {
  const std::string a = fresh("run_mpi_a");
  REQUIRE(run_in(a, 2, "", "case.prm", "run.log") == 0);
  INFO(file_text(a + "/run.log"));
  CHECK_THAT(file_text(a + "/run.log"), Catch::Contains("over 2 MPI rank(s)"));

  // SIGUSR1: every rank writes its part of a checkpoint and stops; resumed on 2 ranks and, from
  // a copy, as one process.
  const std::string b = fresh("run_mpi_term");
  const int status = stop_inside_stage_2(b, 2, SIGUSR1);
  const std::string stop_log = file_text(b + "/stop.log");
  INFO(stop_log);
  REQUIRE(status > 0);
  CHECK_THAT(stop_log, Catch::Contains("stopped by SIGUSR1 in stage 2 of 3"));
  const Checkpoint stopped = read_checkpoint(b + "/out/checkpoint.h5", {1, 2});
  CHECK(stopped.scene.parts.at(0).open.duration > 0);
  CHECK(stopped.dem_ranks == 2);
  CHECK(stopped.dem.rank == 1);
  const std::string b1 = "run_mpi_term_on_1";
  fs::remove_all(b1);
  fs::copy(b, b1, fs::copy_options::recursive);
  REQUIRE(run_in(b, 2, "--resume", "case.prm", "resume.log") == 0);
  check_same_run(a + "/out", b + "/out", {0, 2});
  REQUIRE(run_in(b1, 0, "--resume", "case.prm", "resume.log") == 0);
  check_resumed_elsewhere(a + "/out", b1);

  // SIGKILL after an in-stage checkpoint: resumed from it on 2 ranks.
  const std::string c = fresh("run_mpi_kill");
  CHECK(stop_inside_stage_2(c, 2, SIGKILL) > 0);
  REQUIRE(run_in(c, 2, "--resume", "case.prm", "resume.log") == 0);
  INFO(file_text(c + "/resume.log"));
  check_same_run(a + "/out", c + "/out", {0, 2});

  // A one-process run stopped inside stage 2, resumed on 2 ranks.
  const std::string d = fresh("run_mpi_one_on_2");
  const std::string one = fresh("run_mpi_one");
  REQUIRE(run_in(one, 0, "", "case.prm", "run.log") == 0);
  CHECK(stop_inside_stage_2(d, 0, SIGTERM) == 128 + SIGTERM);
  REQUIRE(run_in(d, 2, "--resume", "case.prm", "resume.log") == 0);
  check_resumed_elsewhere(one + "/out", d);
}

TEST_CASE("the small sector at 1, 2 and 4 ranks wears within the seeds' interval",
          "[coupling][run][mpi][long]") {
  // The small sector's seeds, cases/sector-30/README.md: "| mean +- 95 % interval | 3.1 +- 0.95 |
  // ...".
  const std::string readme = file_text(std::string(WEAR_SOURCE_DIR) + "/cases/sector-30/README.md");
  std::smatch m;
  REQUIRE(std::regex_search(
      readme, m, std::regex(R"(\| mean \+- 95 % interval \| ([0-9.]+) \+- ([0-9.]+) \|)")));
  const double mean = std::stod(m[1]), half = std::stod(m[2]);
  std::string text = file_text(std::string(WEAR_SOURCE_DIR) + "/cases/sector-30/plain.prm");
  text = std::regex_replace(text, std::regex("output/sector-30/plain"), "out");
  for (const int n_ranks : {1, 2, 4}) {
    const std::string dir = fresh("run_mpi_quick_" + std::to_string(n_ranks), text);
    REQUIRE(run_in(dir, n_ranks, "", "case.prm", "run.log") == 0);
    const auto wear = stage_wear(dir + "/out");
    REQUIRE(wear.size() == 6);
    const double per_revolution = 1e9 * (wear[2] + wear[3] + wear[4] + wear[5]) / 4;
    INFO(n_ranks << " rank(s): " << per_revolution << " mm^3 per revolution over revolutions 3 "
                 << "to 6; the seeds' interval " << mean << " +- " << half);
    CHECK(std::abs(per_revolution - mean) <= half);
  }
}

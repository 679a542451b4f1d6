#pragma once
// The wearsim program as a child process, for the tests that stop and resume it: start it
// with its output to a log, wait for it, read its files, and compare the physical columns of
// its tables (the wall-clock columns left out), and check that two runs of one case ended alike.
#include "coupling/output/checkpoint.h"

#include <catch2/catch.hpp>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// The small tester case of the run tests: a 30-degree sector at s = 4, the convex sample at
/// 3 mm, 2 threads, `schedule` at 20x amplification, output to `dir`; `coupling` and `output`
/// are lines added to those subsections.
std::string small_tester_case_file(const std::string& dir, const std::string& schedule,
                                   const std::string& coupling = "",
                                   const std::string& output = "") {
  return R"(subsection Geometry
  subsection Sample
    set Type                 = convex
    set Mesh size            = 3e-3
    set Mesh size bottom     = 5e-3
    set Curvature refinement = false
  end
  subsection Placement
    set Angle = 15
  end
  subsection Tester
    set Sector angle = 30
    set Consolidator = false
    set Wall height  = 0.2
  end
end
subsection DEM
  set Fill height            = 0.055
  set Settle time            = 0.15
  set Time step fraction     = 0.35
  set Samples per revolution = 5
  set Threads                = 2
end
subsection Coupling
  set Schedule      = )" +
         schedule + R"(
  set Amplification = 20
  set Maximum depth fraction = 5
)" + coupling +
         R"(
end
subsection Output
  set Directory = )" +
         dir + "\n" + output + "\nend\n";
}

/// `wearsim <command> [option] <case_file>` with stdout and stderr to `log`.
pid_t start_wearsim(const std::string& case_file, const std::string& option, const std::string& log,
                    const char* command = "run") {
  std::ofstream(log, std::ios::trunc).flush(); // no earlier run's log is read while it starts
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    if (option.empty())
      execl(WEARSIM_BINARY, "wearsim", command, case_file.c_str(), (char*)nullptr);
    else
      execl(WEARSIM_BINARY, "wearsim", command, option.c_str(), case_file.c_str(), (char*)nullptr);
    _exit(127);
  }
  return pid;
}

// The exit status, or 128 + the signal that ended it.
int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int run_wearsim(const std::string& case_file, const std::string& option, const std::string& log,
                const char* command = "run") {
  return wait_for(start_wearsim(case_file, option, log, command));
}

#ifdef MPIEXEC_BINARY
/// `[mpiexec -np n] wearsim <command> [option] <case>` in folder `dir`, its output to dir/<log>,
/// one thread per rank; n = 0: the program alone, as one process.
pid_t start_in(const std::string& dir, int n_ranks, const std::string& option,
               const std::string& case_file, const std::string& log, const char* command = "run") {
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0)
      _exit(126);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    setenv("OMP_NUM_THREADS", "1", 1);
    setenv("OMPI_MCA_mpi_yield_when_idle", "1", 1); // ranks sharing cores yield while waiting
    std::vector<const char*> argv;
    const std::string np = std::to_string(n_ranks);
    if (n_ranks > 0)
      argv = {MPIEXEC_BINARY, "--allow-run-as-root", "--oversubscribe", "-np", np.c_str()};
    argv.push_back(WEARSIM_BINARY);
    argv.push_back(command);
    if (!option.empty())
      argv.push_back(option.c_str());
    argv.push_back(case_file.c_str());
    argv.push_back(nullptr);
    execv(argv[0], const_cast<char* const*>(argv.data()));
    _exit(127);
  }
  return pid;
}

int run_in(const std::string& dir, int n_ranks, const std::string& option,
           const std::string& case_file, const std::string& log, const char* command = "run") {
  return wait_for(start_in(dir, n_ranks, option, case_file, log, command));
}

#endif

// A CSV as rows of cells, leaving out the wall-clock columns (seconds of work, speeds).
std::vector<std::vector<std::string>> physical_columns(const std::string& path) {
  std::istringstream in(file_text(path));
  std::vector<std::vector<std::string>> rows;
  const std::set<std::string> wall_clock{
      "wall_seconds", "particle_steps_per_s", "dem_s",    "wear_s",
      "fem_solve_s",  "mesh_motion_s",        "remesh_s", "output_s"};
  std::vector<bool> keep;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells, kept;
    std::istringstream l(line);
    for (std::string cell; std::getline(l, cell, ',');)
      cells.push_back(cell);
    if (keep.empty())
      for (const auto& name : cells)
        keep.push_back(wall_clock.count(name) == 0);
    for (std::size_t k = 0; k < cells.size() && k < keep.size(); ++k)
      if (keep[k])
        kept.push_back(cells[k]);
    rows.push_back(kept);
  }
  return rows;
}

/// Two runs of the same 3-stage case (one stopped and resumed) ended alike: their sample's
/// tables (parts/sample/, the wall-clock columns left out), the worn sample and the bed, bit for
/// bit. `part` reads the checkpoints of a run over ranks (each of them then holds
/// `part.n_ranks` DEM parts).
void check_same_run(const std::string& a, const std::string& b,
                    const wear::coupling::DemPart& part = {}) {
  for (const char* csv : {"/parts/sample/stages.csv", "/parts/sample/summary.csv"}) {
    INFO(csv);
    const auto ra = physical_columns(a + csv), rb = physical_columns(b + csv);
    REQUIRE(ra.size() == 4); // header + 3 stages (or revolutions)
    CHECK(ra == rb);
  }
  // The elements on their footprints, from the footprints the checkpoint carried.
  CHECK(file_text(b + "/parts/sample/element_life.csv") ==
        file_text(a + "/parts/sample/element_life.csv"));
  const auto ca = wear::coupling::read_checkpoint(a + "/checkpoint.h5", part);
  const auto cb = wear::coupling::read_checkpoint(b + "/checkpoint.h5", part);
  REQUIRE(cb.stages_done == 3);
  CHECK(cb.dem_ranks == part.n_ranks);
  REQUIRE(ca.scene.parts.size() == 1);
  REQUIRE(cb.scene.parts.size() == 1);
  const auto &sa = ca.scene.parts[0].sample, &sb = cb.scene.parts[0].sample;
  CHECK(sb.surface.vertices == sa.surface.vertices);
  CHECK(sb.vertices == sa.vertices);
  CHECK(sb.removed_volume == sa.removed_volume);
  CHECK(cb.dem.position == ca.dem.position);
  CHECK(cb.dem.pair_history == ca.dem.pair_history);
}

} // namespace

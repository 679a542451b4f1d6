#pragma once
// The wearsim program as a child process, for the tests that stop and resume it: start it
// with its output to a log, wait for it, read its files, and compare the physical columns of
// its tables (the wall-clock columns left out).
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

} // namespace

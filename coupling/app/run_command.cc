// `wearsim run`: reads the options and the case file and hands them to the run of its kind: a
// scene (Scene/Walls names walls) to SceneCoupledRun, the built-in wear tester to CoupledRun.
#include "coupling/app/run_command.h"

#include "coupling/loop/coupled_run.h"
#include "coupling/loop/scene_coupled_run.h"

#include <deal.II/base/multithread_info.h>

#include <stdexcept>

namespace wear::coupling {

std::string parse_run_arguments(const std::vector<std::string>& args, const std::string& command,
                                RunOptions& options) {
  const std::string name = "wearsim " + command;
  std::string case_file;
  for (const auto& a : args) {
    if (a == "--resume")
      options.resume = true;
    else if (a == "--overwrite")
      options.overwrite = true;
    else if (a.rfind("--", 0) == 0)
      throw std::invalid_argument(name + ": unknown option '" + a + "'");
    else if (case_file.empty())
      case_file = a;
    else
      throw std::invalid_argument(name + ": expected one case file, got '" + case_file + "' and '" +
                                  a + "'");
  }
  if (case_file.empty())
    throw std::invalid_argument(name + ": expected a case file: " + name +
                                " [--resume | --overwrite] <case.prm>");
  if (options.resume && options.overwrite)
    throw std::invalid_argument(name + ": --resume and --overwrite exclude each other");
  return case_file;
}

int run_run_command(const std::vector<std::string>& args, std::ostream& log, dem::RankLink* ranks) {
  RunOptions options;
  options.ranks = ranks;
  const std::string case_file = parse_run_arguments(args, "run", options);
  CaseParameters p = read_case(case_file);
  if (!p.scene.walls.empty())
    return SceneCoupledRun(p, log, options).run();
  // Over ranks each rank's FEM stage keeps to the rank's own threads (DEM/Threads), not all of
  // the node's cores.
  if (ranks && p.dem.n_threads > 0)
    dealii::MultithreadInfo::set_thread_limit(unsigned(p.dem.n_threads));
  CoupledRun run(p, log, options);
  return run.run();
}

} // namespace wear::coupling

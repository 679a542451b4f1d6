// `wearsim run` and `wearsim dem`: read the options and the case file and hand the case, as a
// scene (a wear-tester case written as one, coupling/parameters/tester_scene_case.h), to the
// one coupled loop, SceneCoupledRun.
#include "coupling/app/run_command.h"

#include "coupling/parameters/tester_scene_case.h"

#include <deal.II/base/multithread_info.h>

#include <stdexcept>

namespace wear::coupling {

std::string parse_run_arguments(const std::vector<std::string>& args, const std::string& command,
                                RunOptions& options) {
  const std::string name = "wearsim " + command;
  options.command = command;
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

int run_scene_case(const CaseParameters& scene_case, std::ostream& log, const RunOptions& options) {
  // Over ranks each rank's FEM stage keeps to the rank's own threads (DEM/Threads), not all of
  // the node's cores.
  if (options.ranks && scene_case.dem.n_threads > 0)
    dealii::MultithreadInfo::set_thread_limit(unsigned(scene_case.dem.n_threads));
  return SceneCoupledRun(scene_case, log, options).run();
}

int run_run_command(const std::vector<std::string>& args, std::ostream& log, dem::RankLink* ranks) {
  RunOptions options;
  options.ranks = ranks;
  const std::string case_file = parse_run_arguments(args, "run", options);
  return run_scene_case(run_case_of(read_case(case_file)), log, options);
}

int run_dem_command(const std::vector<std::string>& args, std::ostream& log, dem::RankLink* ranks) {
  RunOptions options;
  options.ranks = ranks;
  const std::string case_file = parse_run_arguments(args, "dem", options);
  return run_scene_case(dem_case_of(read_case(case_file)), log, options);
}

} // namespace wear::coupling

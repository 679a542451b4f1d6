// `wearsim scene-run [--resume | --overwrite] <case.prm>`: a scene's run
// (coupling/loop/scene_coupled_run.h): its DEM to Scene/End time with a record every Output
// interval, or with a wearing part and Scene/Stage duration the wear loop's stages. Under
// `mpirun -np N` every rank runs it, the scene decomposed over the ranks.
#include "coupling/app/scene_run_command.h"

#include "coupling/app/run_command.h"

#include <ostream>
#include <stdexcept>

namespace wear::coupling {

int run_scene_run_command(const std::vector<std::string>& args, std::ostream& log,
                          dem::RankLink* ranks) {
  RunOptions options;
  options.ranks = ranks;
  const std::string case_file = parse_run_arguments(args, "scene-run", options);
  const CaseParameters p = read_case(case_file);
  if (p.scene.walls.empty())
    throw std::invalid_argument("case file '" + p.case_file +
                                "': Scene/Walls is empty: there is no scene to run");
  return run_scene_case(p, log, options);
}

} // namespace wear::coupling

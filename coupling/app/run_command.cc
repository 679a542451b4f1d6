// `wearsim run`: reads the options and the case file and hands them to CoupledRun.
#include "coupling/app/run_command.h"

#include "coupling/loop/coupled_run.h"

#include <stdexcept>

namespace wear::coupling {

int run_run_command(const std::vector<std::string>& args, std::ostream& log) {
  RunOptions options;
  std::string case_file;
  for (const auto& a : args) {
    if (a == "--resume")
      options.resume = true;
    else if (a == "--overwrite")
      options.overwrite = true;
    else if (a.rfind("--", 0) == 0)
      throw std::invalid_argument("wearsim run: unknown option '" + a + "'");
    else if (case_file.empty())
      case_file = a;
    else
      throw std::invalid_argument("wearsim run: expected one case file, got '" + case_file +
                                  "' and '" + a + "'");
  }
  if (case_file.empty())
    throw std::invalid_argument("wearsim run: expected a case file: wearsim run [--resume | "
                                "--overwrite] <case.prm>");
  CaseParameters p = read_case(case_file);
  require_no_scene(p, "run");
  CoupledRun run(p, log, options);
  return run.run();
}

} // namespace wear::coupling

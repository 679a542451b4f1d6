#pragma once
// `wearsim run [--resume] <case.prm>`: the coupled DEM-FEM run of a case file.
#include "coupling/loop/coupled_run.h"

#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// The case file and the options (--resume, --overwrite) of `wearsim <command>`; throws
/// std::invalid_argument naming the command for an unknown option, no or two case files, or
/// both options.
std::string parse_run_arguments(const std::vector<std::string>& args, const std::string& command,
                                RunOptions& options);

/// Runs (or resumes) the case: a scene's run (SceneCoupledRun, as `wearsim scene-run`) or the
/// built-in wear tester's schedule (CoupledRun); returns the exit code. `ranks`: under mpirun,
/// the DEM over these ranks (a scene's slabs, or the tester's ring of angular slabs).
int run_run_command(const std::vector<std::string>& args, std::ostream& log,
                    dem::RankLink* ranks = nullptr);

} // namespace wear::coupling

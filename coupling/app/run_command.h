#pragma once
// `wearsim run [--resume | --overwrite] <case.prm>`: the coupled DEM-FEM run of a case file,
// and `wearsim dem`, the same run with the wear tester's revolutions as dem-only stages.
#include "coupling/loop/scene_coupled_run.h"

#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// The case file and the options (--resume, --overwrite) of `wearsim <command>`; throws
/// std::invalid_argument naming the command for an unknown option, no or two case files, or
/// both options.
std::string parse_run_arguments(const std::vector<std::string>& args, const std::string& command,
                                RunOptions& options);

/// Runs (or resumes) scene case `scene_case` (run_case_of, dem_case_of, scene-run's) through the
/// one loop, SceneCoupledRun; returns the exit code. Over ranks each rank's FEM keeps to
/// DEM/Threads.
int run_scene_case(const CaseParameters& scene_case, std::ostream& log, const RunOptions& options);

/// `wearsim run`: the case as a scene (a wear-tester case written as one by tester_scene_case);
/// returns the exit code. `ranks`: under mpirun, the DEM over these ranks (the scene's slabs).
int run_run_command(const std::vector<std::string>& args, std::ostream& log,
                    dem::RankLink* ranks = nullptr);

/// `wearsim dem`: a wear-tester case in DEM alone (dem_case_of); as run_run_command.
int run_dem_command(const std::vector<std::string>& args, std::ostream& log,
                    dem::RankLink* ranks = nullptr);

} // namespace wear::coupling

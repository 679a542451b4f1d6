#pragma once
#include "coupling/parameters/case_parameters.h"
#include "dem/engine/rank_link.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace wear::coupling {

/// `wearsim scene-run`: the case's scene. Without Scene/Stage duration, the DEM run
/// (dem/scene/scene_run.h) to Scene/End time with a record every Scene/Output interval
/// (coupling/output/scene_series.h) and the resolved parameters beside; with it, the wear loop
/// of the scene's wearing part; checkpoints and --resume (coupling/loop/scene_coupled_run.h).
/// Returns the exit status.
/// `args`: the options (--resume, --overwrite) and the case file.
int run_scene_run_command(const std::vector<std::string>& args, std::ostream& log,
                          dem::RankLink* ranks = nullptr);

} // namespace wear::coupling

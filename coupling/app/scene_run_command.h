#pragma once
#include "coupling/parameters/case_parameters.h"

#include <iosfwd>

namespace wear::coupling {

/// `wearsim scene-run`: the DEM run of the case's scene (dem/scene/scene_run.h) to
/// Scene/End time, a record every Scene/Output interval: a progress line, the tables
/// <Output/Directory>/scene_series.csv and scene_wear.csv (per wall and label; both
/// rewritten whole after every record), particle
/// snapshots particles_<k>.vtu and the walls where they are (walls_<k>/<name>.vtu), with the
/// resolved parameters beside.
void run_scene_run_command(const CaseParameters& p, std::ostream& log);

} // namespace wear::coupling

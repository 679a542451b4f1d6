#pragma once
// `wearsim life <run> [--part <name>]`: a worn part's convex elements measured again on the
// surfaces its stages kept, each on its unworn footprint (meshes::footprint_standing), into
// <run>/parts/<part>/element_life.csv beside the run's own part_life.csv: what a run of this
// engine writes itself, for the runs of engines older than that.
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// Runs the command; prints per stage the elements' volume on their footprints beside the one
/// part_life.csv holds (above the foot the worn labels span).
int run_life_command(const std::vector<std::string>& args, std::ostream& out);

} // namespace wear::coupling

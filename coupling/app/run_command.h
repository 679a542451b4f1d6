#pragma once
// `wearsim run [--resume] <case.prm>`: the coupled DEM-FEM run of a case file.
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// Runs (or resumes) the case's schedule; returns the exit code.
int run_run_command(const std::vector<std::string>& args, std::ostream& log);

} // namespace wear::coupling

#pragma once
#include "coupling/parameters/case_parameters.h"

#include <iosfwd>

namespace wear::coupling {

/// `wearsim scene`: builds the case's scene walls (CAD files, primitives) with their checks
/// (dem/scene/scene_walls.h), writes each as <Output/Directory>/scene/<name>.stl (labels
/// kept) and .vtu with the resolved parameters, and prints a table per wall and per label.
void run_scene_command(const CaseParameters& p, std::ostream& log);

} // namespace wear::coupling

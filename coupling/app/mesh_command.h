#pragma once
#include "coupling/parameters/case_parameters.h"

#include <iosfwd>

namespace wear::coupling {

/// `wearsim mesh`: writes the sample (.msh, .stl, .vtu) and the tester walls (.stl) into the
/// output folder with the resolved parameters, and prints a table per label.
void run_mesh_command(const CaseParameters& p, std::ostream& log);

} // namespace wear::coupling

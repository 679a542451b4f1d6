#pragma once
#include "coupling/parameters/case_parameters.h"

#include <iosfwd>

namespace wear::coupling {

struct DemCommandOptions {
  bool progress = true; ///< live progress line on the terminal (stderr)
};

/// `wearsim dem <case.prm>`: the wear tester in DEM only. Generates the sample surface,
/// fills and settles the bed, runs the revolutions and writes history.h5/.xdmf,
/// summary.csv and parameters.prm into the output folder, with a progress line.
void run_dem_command(const CaseParameters& p, std::ostream& log,
                     const DemCommandOptions& options = {});

} // namespace wear::coupling

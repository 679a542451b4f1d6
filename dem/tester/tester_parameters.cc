// The checks of a wear-tester case's DEM entries (tester_parameters.h): each names its entry
// and says what is wrong, before anything is built.
#include "dem/tester/tester_parameters.h"

#include <cmath>

namespace wear::dem {

void validate(const TesterDemParameters& p) {
  validate(static_cast<const DemParameters&>(p));
  require_dem(p.fill_height > 0, "Fill height", "must be positive [m]");
  require_dem(p.rotation_rate_deg > 0 && std::isfinite(p.rotation_rate_deg), "Rotation rate",
              "must be positive [deg/s]");
  require_dem(p.revolutions >= 1, "Revolutions", "must be at least 1");
  require_dem(p.samples_per_revolution >= 2, "Samples per revolution", "must be at least 2");
  require_dem(p.steady_threshold > 0, "Steady threshold", "must be positive");
  require_dem(p.steady_revolutions >= 1, "Steady revolutions", "must be at least 1");
  for (const int r : p.snapshot_revolutions)
    require_dem(r >= 1, "Snapshot revolutions", "must be revolutions from 1 on");
}

} // namespace wear::dem

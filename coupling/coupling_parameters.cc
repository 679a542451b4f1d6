// Schedule parsing and validation of the coupling and FEM parameters.
//
// A schedule is a comma-separated list of "N scheme" items, run in order; e.g.
// "6 dem-only, 10 staged" settles and reaches steady state on the fixed geometry, then
// couples. The reference scheme moves surface nodes inside the DEM and cannot be mixed with
// the staged scheme (one sample geometry per run).
#include "coupling/coupling_parameters.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wear::coupling {

std::string scheme_name(Scheme s) {
  switch (s) {
  case Scheme::staged:
    return "staged";
  case Scheme::reference:
    return "reference";
  default:
    return "dem-only";
  }
}

double StressInformedWear::factor(double von_mises) const {
  if (!enabled)
    return 1;
  return 1 + sensitivity * std::pow(std::max(0.0, von_mises) / reference_stress, exponent);
}

std::vector<ScheduleItem> parse_schedule(const std::string& text) {
  std::vector<ScheduleItem> items;
  std::stringstream all(text);
  std::string part;
  const auto fail = [&](const std::string& what) {
    throw std::invalid_argument("Coupling/Schedule: '" + text + "': " + what +
                                " (expected items 'N scheme' separated by commas, scheme one "
                                "of staged, reference, dem-only)");
  };
  while (std::getline(all, part, ',')) {
    std::istringstream item(part);
    ScheduleItem it;
    std::string name, extra;
    if (!(item >> it.n_stages >> name) || (item >> extra))
      fail("cannot read '" + part + "'");
    if (it.n_stages < 1)
      fail("a stage count must be at least 1");
    if (name == "staged")
      it.scheme = Scheme::staged;
    else if (name == "reference")
      it.scheme = Scheme::reference;
    else if (name == "dem-only")
      it.scheme = Scheme::dem_only;
    else
      fail("unknown scheme '" + name + "'");
    items.push_back(it);
  }
  if (items.empty())
    fail("no stages");
  bool staged = false, reference = false;
  for (const auto& it : items) {
    staged |= it.scheme == Scheme::staged;
    reference |= it.scheme == Scheme::reference;
  }
  if (staged && reference)
    fail("'reference' and 'staged' cannot be mixed in one run");
  if (reference && items.size() > 1)
    fail("'reference' runs alone (its node moves start with the first revolution)");
  return items;
}

void validate(const CouplingParameters& c, const FemParameters& f) {
  const auto require = [](bool ok, const std::string& parameter, const std::string& what) {
    if (!ok)
      throw std::invalid_argument(parameter + ": " + what);
  };
  parse_schedule(c.schedule);
  require(c.revolutions_per_stage >= 1, "Coupling/Revolutions per stage", "must be at least 1");
  require(c.amplification > 0 && std::isfinite(c.amplification), "Coupling/Amplification",
          "must be positive");
  require(c.max_depth_fraction > 0 && c.max_depth_fraction <= 10, "Coupling/Maximum depth fraction",
          "must lie in (0, 10]");
  require(!c.adaptive_amplification ||
              (c.min_amplification > 0 && c.min_amplification <= c.amplification),
          "Coupling/Minimum amplification", "must lie in (0, Coupling/Amplification]");
  require(c.push_tolerance >= 0 && c.push_tolerance < 0.5, "Coupling/Push tolerance",
          "must lie in [0, 0.5)");
  const auto& s = c.stress_informed;
  require(s.sensitivity >= 0, "Coupling/Stress-informed wear/Sensitivity", "must be >= 0");
  require(s.reference_stress > 0, "Coupling/Stress-informed wear/Reference stress",
          "must be positive [Pa]");
  require(s.exponent > 0, "Coupling/Stress-informed wear/Exponent", "must be positive");
  const auto& e = f.elasticity;
  require(e.youngs_modulus > 0 && std::isfinite(e.youngs_modulus), "FEM/Youngs modulus",
          "must be positive [Pa]");
  require(e.poisson_ratio > -1 && e.poisson_ratio < 0.5, "FEM/Poisson ratio",
          "must lie in (-1, 0.5)");
  require(e.yield_stress > 0, "FEM/Yield stress", "must be positive [Pa]");
  require(e.degree == 1 || e.degree == 2, "FEM/Degree", "must be 1 or 2");
  require(e.relative_tolerance > 0 && e.relative_tolerance < 1e-2, "FEM/Solver tolerance",
          "must lie in (0, 1e-2)");
  require(f.remesh_min_scaled_jacobian > 0 && f.remesh_min_scaled_jacobian < 1,
          "FEM/Remesh scaled Jacobian", "must lie in (0, 1)");
  require(f.feature_angle_deg > 0 && f.feature_angle_deg < 180, "FEM/Feature angle",
          "must lie in (0, 180) degrees");
  require(f.chord_tolerance > 0, "FEM/Chord tolerance", "must be positive [m]");
  require(f.remesh_min_tet_quality > 0 && f.remesh_min_tet_quality < 1,
          "FEM/Remesh tetrahedron quality", "must lie in (0, 1)");
  require(f.worn_through_thickness > 0, "FEM/Worn-through thickness", "must be positive [m]");
}

} // namespace wear::coupling

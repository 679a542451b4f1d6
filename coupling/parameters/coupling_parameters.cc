// Schedule parsing and validation of the coupling parameters (the FEM ones by fem::validate).
//
// A schedule is a comma-separated list of "N scheme" items, run in order; e.g.
// "6 dem-only, 10 staged" settles and reaches steady state on the fixed geometry, then
// couples. The reference scheme moves surface nodes inside the DEM and cannot be mixed with
// the staged scheme (one sample geometry per run).
#include "coupling/parameters/coupling_parameters.h"

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

int scheme_index(Scheme s) {
  switch (s) {
  case Scheme::staged:
    return 0;
  case Scheme::reference:
    return 1;
  default:
    return 2;
  }
}

Scheme scheme_from_index(int index) {
  switch (index) {
  case 0:
    return Scheme::staged;
  case 1:
    return Scheme::reference;
  case 2:
    return Scheme::dem_only;
  default:
    throw std::runtime_error("a stored stage record names scheme " + std::to_string(index) +
                             " (known: 0 staged, 1 reference, 2 dem-only)");
  }
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

WornOutCriterion worn_out_criterion(const std::string& name) {
  if (name == "never")
    return WornOutCriterion::never;
  if (name == "elements gone")
    return WornOutCriterion::elements_gone;
  if (name == "thickness")
    return WornOutCriterion::thickness;
  if (name == "worn through")
    return WornOutCriterion::worn_through;
  throw std::invalid_argument("Coupling/Worn out when: '" + name +
                              "' is none of never, elements gone, thickness, worn through");
}

void validate(const CouplingParameters& c, const fem::FemParameters& f) {
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
  require(worn_out_criterion(c.worn_out_when) != WornOutCriterion::thickness ||
              c.worn_out_thickness > 0,
          "Coupling/Worn-out thickness", "must be positive [m] with Worn out when = thickness");
  require(c.worn_out_thickness >= 0, "Coupling/Worn-out thickness", "must be >= 0 [m]");
  require(c.hours_per_revolution >= 0 && std::isfinite(c.hours_per_revolution),
          "Coupling/Hours per revolution", "must be >= 0 [h]");
  fem::validate(f);
}

} // namespace wear::coupling

#pragma once
// Consistency of a case as a whole: combinations of parameters, each valid alone, that would
// stop a run later (after the bed is filled, after hours of DEM) or make it meaningless.
// read_case runs these checks after every module's own validate(), before any file is
// written or any particle created. Each refusal is a std::invalid_argument naming the
// parameters by their case-file paths and a value that would pass; what cannot be refused
// (the run would work, only worse) is returned as a warning. The checks and the estimate
// they use: docs/user-guide.md ("What is checked before a run starts"), docs/coupling.md.
#include "coupling/parameters/case_parameters.h"

#include <string>
#include <vector>

namespace wear::coupling {

/// The a-priori estimate of one staged stage's wear depth (docs/coupling.md, "The depth cap
/// before a run starts"): the bed's hydrostatic pressure on the wear face, the path of the
/// bed past the sample at the floor's speed, the wear law's coefficient.
struct StageDepthEstimate {
  bool known = false;     ///< false for a wear law the estimate does not cover
  double pressure = 0;    ///< [Pa] rho phi g (fill height - wear face height)
  double path = 0;        ///< [m] Theta r per revolution, times the revolutions per stage
  double coefficient = 0; ///< [1/Pa] Archard alpha, or work coefficient x particle-wall friction
  double mean_depth = 0;  ///< [m] A c p s: the stage's mean depth if the bed slid at floor speed
  /// [-] the smallest largest vertex depth over its longest edge a stage can ask, from
  /// mean_depth times the lowest measured efficiency (depth_efficiency_floor) over the
  /// longest mean edge (edge_length_bound x Mesh size); at the declared amplification.
  double fraction_lower_bound = 0;
};

/// [-] The lowest measured wear over the slide-at-floor-speed estimate (0.072, cases/sector-30
/// convex), divided by 7: the bound's margin.
constexpr double depth_efficiency_floor = 0.01;
/// [-] Area-weighted mean of the longest wear-face edge at a vertex over Mesh size: 1.00 to
/// 1.15 on the shipped samples, taken as 1.5.
constexpr double edge_length_bound = 1.5;
/// [-] Solid fraction of random sequential insertion at jamming: 0.38 for equal spheres, a
/// little more with a size spread; a fill asking more than this in its insertion region
/// cannot be inserted.
constexpr double insertion_fraction_limit = 0.45;

/// The estimate for the case's parameters (at Coupling/Amplification).
StageDepthEstimate stage_depth_estimate(const CaseParameters& p);

/// Throws std::invalid_argument naming the parameters when a combination would fail later;
/// returns warnings (one sentence each) for combinations that run but not as intended.
/// Expects the parameters each module's validate() accepted.
std::vector<std::string> check_consistency(const CaseParameters& p);

} // namespace wear::coupling

#pragma once
// The DEM part of a wear-tester case: the DEM parameters every scene uses
// (dem/scene/dem_parameters.h) and what only the tester adds, its fill height, rotation, run
// length, evaluation and steady state; and the DEM subsection of a case file that fills it
// (visit_parameters, meshes/parameter_visitor.h).
#include "dem/scene/dem_parameters.h"

#include <vector>

namespace wear::dem {

/// The DEM part of a wear-tester case (case file subsection "DEM"): the scenes' DEM
/// parameters and the tester's own; defaults are those of docs/wear-tester.md where it gives
/// them.
struct TesterDemParameters : DemParameters {
  double fill_height = 0.130;    ///< [m] settled bed height above the floor
  double rotation_rate_deg = 90; ///< [deg/s] of floor and cylinders
  int revolutions = 9;           ///< one revolution = one pass through the sector
  /// `wearsim dem` stops this many revolutions after the steady revolution (0: runs all
  /// `revolutions`, which stay the maximum).
  int revolutions_after_steady = 0;
  int samples_per_revolution = 10;          ///< evaluation samples (force, speeds, heights)
  double steady_threshold = 0.1;            ///< [-] coefficient of variation for steady state
  int steady_revolutions = 2;               ///< consecutive revolutions below the threshold
  std::vector<int> snapshot_revolutions{1}; ///< particle snapshots after these (plus the last)
};

/// Throws std::invalid_argument naming the DEM entry that is out of range.
void validate(const TesterDemParameters& p);

/// The DEM subsection's entries that only the wear tester uses (inside the subsection): a
/// scene's case may not set them (coupling/parameters/case_scope.h).
template <typename Visitor>
void visit_tester_parameters(TesterDemParameters& d, Visitor& v) {
  v.real("Fill height", d.fill_height, "[m] Settled bed height above the floor.");
  v.real("Rotation rate", d.rotation_rate_deg, "[deg/s] Rotation of the floor and cylinders.");
  v.integer("Revolutions", d.revolutions, 1, 100000,
            "Revolutions to run (one revolution = one pass of the bed through the sector).");
  v.integer("Revolutions after steady", d.revolutions_after_steady, 0, 100000,
            "A wear-tester case's run (wearsim dem, wearsim run) stops this many revolutions "
            "after the first steady revolution (see Steady threshold; Scene/Evaluation/Periods "
            "after steady of its scene); 0 runs all its revolutions.");
  v.integer("Samples per revolution", d.samples_per_revolution, 2, 100000,
            "Evaluation samples per revolution (forces, speeds, bed height, wear rate).");
  v.real("Steady threshold", d.steady_threshold,
         "[-] Coefficient of variation below which a revolution counts as steady.");
  v.integer("Steady revolutions", d.steady_revolutions, 1, 1000,
            "Consecutive steady revolutions that judge the run steady.");
  v.int_list("Snapshot revolutions", d.snapshot_revolutions,
             "Revolutions after which particle snapshots are written (the last always is).");
}

/// The DEM subsection: the scenes' entries and the tester's.
template <typename Visitor>
void visit_parameters(TesterDemParameters& d, Visitor& v) {
  v.enter("DEM");
  visit_common_parameters(d, v);
  visit_tester_parameters(d, v);
  v.leave();
}

} // namespace wear::dem

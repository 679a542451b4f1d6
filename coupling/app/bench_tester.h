#pragma once
// The `tester` workload of `wearsim bench dem`: the wear tester of a case (by default the
// reference of cases/reference, built in code) as the scene `wearsim run` runs it, filled and
// settled as a run does, then timed with the walls turning and the sample accumulating wear.
#include "coupling/parameters/case_parameters.h"
#include "dem/scene/scene_run.h"

#include <cstdint>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace wear::coupling {

struct TesterBenchOptions {
  std::optional<double> scale; ///< [-] --scale, the particle scaling factor (reference: 3)
  std::optional<bool> convex;  ///< --sample convex|plain (reference: convex)
  std::string case_file;       ///< --case: this case file instead of the built-in reference
  /// --state: a bed state to start from (read when the file exists, written after the flow
  /// steps otherwise), so that repeated timings skip the settling and start from one flow.
  std::string state_file;
  std::uint64_t flow_steps = 0; ///< --flow: steps of the open revolution before the timing
  bool any_given() const {
    return scale || convex || !case_file.empty() || !state_file.empty() || flow_steps > 0;
  }
};

/// The reference tester of cases/reference/{convex,plain}.prm, built in code: the parameter
/// defaults (which are the reference geometry, materials and bed) plus what those files set,
/// DEM/Time step fraction 0.3 and the Archard law with 5e-9 /Pa, at scaling factor `scale`.
/// The run length (revolutions, samples, snapshots) and the output folder stay the defaults.
CaseParameters reference_tester_case(bool convex, double scale);

/// The case the options ask for: the built-in reference, or the case file, with --scale and
/// --sample replacing its values when given.
CaseParameters tester_bench_case(const TesterBenchOptions& o);

/// The tester as a scene, ready to be timed.
struct TesterWorkload {
  std::unique_ptr<dem::SceneRun> scene;
  double revolution_time = 0;             ///< [s] one pass of the bed through the sector
  std::uint64_t steps_per_revolution = 0; ///< round(revolution_time / dt)
};

/// Writes the case as the scene `wearsim run` runs (tester_scene_case), builds its walls,
/// fills and settles it as a run does on `threads` threads (`settle` false: the shortest
/// settling the fill allows, one 0.02 s check), then runs o.flow_steps steps with the walls
/// turning and the sample's wear integrals open, as a run's first window does. With
/// o.state_file, an existing file is the state to continue instead (it must come from the same
/// case and thread count; the continuation is exact, System::resume_state), and a missing one
/// receives the state reached. Logs the bed; `seconds` receives the wall time of all this [s].
TesterWorkload tester_workload(const TesterBenchOptions& o, bool settle, int threads,
                               double& seconds, std::ostream& out);

/// Steps per revolution and, per thread count, the minutes one revolution takes at the
/// median rate [particle-steps/s] given for it.
void report_tester(const TesterWorkload& tester, const std::map<int, double>& median_rates,
                   std::ostream& out);

} // namespace wear::coupling

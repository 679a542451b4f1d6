#pragma once
// The `tester` workload of `wearsim bench dem`: the wear tester of a case (by default the
// reference of cases/reference, built in code) filled and settled as `wearsim dem` does it,
// then timed with the walls rotating and the sample accumulating wear.
#include "coupling/parameters/case_parameters.h"
#include "dem/tester/wear_tester.h"

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

/// Generates the case's sample surface, builds the tester, fills it and settles it as
/// `wearsim dem` does on `threads` threads (`settle` false: the shortest settling the fill
/// allows, one 0.02 s check), then starts the walls' rotation and the sample's wear window as
/// a revolution does and runs o.flow_steps of it. With o.state_file, an existing file is the
/// state to continue instead (it must come from the same case and thread count; the
/// continuation is exact, System::resume_state), and a missing one receives the state reached.
/// Logs the bed; `seconds` receives the wall time of all this [s].
std::unique_ptr<dem::WearTester> tester_workload(const TesterBenchOptions& o, bool settle,
                                                 int threads, double& seconds, std::ostream& out);

/// Steps per revolution and, per thread count, the minutes one revolution takes at the
/// median rate [particle-steps/s] given for it.
void report_tester(const dem::WearTester& tester, const std::map<int, double>& median_rates,
                   std::ostream& out);

} // namespace wear::coupling

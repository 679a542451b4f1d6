#pragma once
// `wearsim calibrate <run> --measured <volume> --revolutions <n>`: scales the wear
// coefficient of a finished run so its steady wear per revolution matches a measurement
// that n simulated revolutions stand for (the reference study: 56 h of the laboratory test
// = 2 revolutions, docs/theory.md section 4). `--part <wall>`: a scene's wearing part, per
// period when the scene evaluates it (Scene/Evaluation), else per second of its staged
// stages against a measurement over `--time <s>` of operation.
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// Parses a volume with its unit: "35.2mm^3", "35.2 mm3", "3.52e-8 m^3", "0.0352 cm^3" [m^3].
/// Throws naming `what` for a missing or unknown unit, a non-number or a value <= 0.
double parse_volume(const std::string& text, const std::string& what);

struct Calibration {
  std::string unit = "revolution"; ///< what the wear is per: revolution, or s (a scene's part)
  std::string model;               ///< the run's wear law
  std::string coefficient_name;    ///< "Archard coefficient" or "Work coefficient"
  double coefficient = 0;          ///< of the run [1/Pa] or [m^3/J]
  double calibrated = 0;           ///< giving the measured wear per revolution
  /// Further coefficients the law's volume is linear in (WearLawParameter::scales_with_first),
  /// each with its run's value: scaled by the same factor.
  std::vector<std::pair<std::string, double>> also_scaled;
  int first_revolution = 0;     ///< first revolution (or a part's stage) averaged
  int n_revolutions = 0;        ///< revolutions (or a part's stages) averaged
  double simulated_per_rev = 0; ///< [m^3] mean wear-face wear per revolution (per s: [m^3/s])
  double measured_per_rev = 0;  ///< [m^3] measured volume / simulated revolutions (or time)
};

/// Reads <run>/summary.csv and <run>/parameters.prm. The revolutions averaged are those
/// after the run's steady revolution, or from `from_revolution` when > 0; a run that never
/// reached steady state is refused unless `from_revolution` is given.
/// `part` names a scene's wearing part (empty: the tester's run, or the part the scene
/// evaluates, Scene/Evaluation/Wall): the part the scene evaluates
/// reads its parts/<part>/summary.csv alike (periods for revolutions); another part reads its
/// stages.csv: the wear-law volume of its staged stages (from its first staged stage, or
/// `from_revolution` as a stage) per second of Scene/Stage duration, and `revolutions` is then
/// the measurement's time [s].
Calibration calibrate(const std::string& run, double measured_volume, double revolutions,
                      int from_revolution = 0, const std::string& part = "");

/// Runs the command; writes <run>/calibration.prm (atomically) and prints the result.
int run_calibrate_command(const std::vector<std::string>& args, std::ostream& out);

} // namespace wear::coupling

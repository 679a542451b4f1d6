// Calibration of the wear coefficient against a measured wear volume.
//
// Every law is linear in its coefficient (Archard: V = alpha sum F_n ds; frictional work:
// V = beta sum F_t . ds; finnie and oka: V = k sum over impacts; sliding-impact in its two
// coefficients together, which are scaled alike), and on a fixed geometry the coefficient does
// not feed back into the particle motion, so the calibrated value is exact for the same run:
//   coefficient_cal = coefficient * (V_measured / N_test) / (sum_{r in R} V_r / |R|),
// with V_r the wear-face volume of revolution r of the run and R the revolutions after steady
// state (docs/theory.md section 7: wear is judged on the steady flow). For a coupled run with a
// geometry that wears, the scaled coefficient is the first-order answer: the flow changes with the
// shape. A scene's wearing part (--part; without it, the part the scene evaluates) that the
// scene evaluates (Scene/Evaluation) has periods for revolutions; another part has no steady-state
// judgement and is calibrated per second:
//   coefficient_cal = coefficient * (V_measured / t_test) / (sum_{k in K} V_k / (|K| T_stage)),
// V_k the wear-law volume of its staged stage k (from its first staged stage, or --from).
#include "coupling/app/calibrate_command.h"

#include "coupling/parameters/case_parameters.h"
#include "meshes/atomic_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace wear::coupling {

double parse_volume(const std::string& text, const std::string& what) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw std::invalid_argument(what + ": '" + text + "' is not a number with a volume unit");
  }
  std::string unit;
  for (std::size_t k = used; k < text.size(); ++k)
    if (!std::isspace(static_cast<unsigned char>(text[k])))
      unit += text[k];
  static const std::map<std::string, double> units = {{"m^3", 1.0},  {"m3", 1.0},    {"cm^3", 1e-6},
                                                      {"cm3", 1e-6}, {"mm^3", 1e-9}, {"mm3", 1e-9}};
  const auto it = units.find(unit);
  if (it == units.end())
    throw std::invalid_argument(what + ": '" + text + "' needs a volume unit (m^3, cm^3 or mm^3)" +
                                (unit.empty() ? "" : ", not '" + unit + "'"));
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(what + ": '" + text + "' must be a positive volume");
  return value * it->second;
}

namespace {
std::vector<std::map<std::string, std::string>> read_summary(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("calibrate: cannot read '" + path + "' (is it a wearsim run folder?)");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream h(line);
  for (std::string c; std::getline(h, c, ',');)
    names.push_back(c);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    std::map<std::string, std::string> row;
    std::string cell;
    for (std::size_t k = 0; k < names.size() && std::getline(r, cell, ','); ++k)
      row[names[k]] = cell;
    rows.push_back(row);
  }
  return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& column,
              const std::string& path) {
  const auto it = row.find(column);
  if (it == row.end())
    throw std::runtime_error("calibrate: '" + path + "' has no column '" + column + "'");
  return std::stod(it->second);
}

// The coefficient a law of the catalogue is linear in (its first parameter; of a sum, the
// first law's); none for a law without parameters.
const dem::WearLawParameter* linear_coefficient(const std::string& model) {
  const auto laws = dem::wear_laws_of(model);
  return laws.front()->parameters.empty() ? nullptr : &laws.front()->parameters.front();
}

struct CalibrateArguments {
  std::string run, measured; ///< run folder; measured volume as given, with its unit
  double revolutions = 0;    ///< simulated revolutions the measurement stands for
  double time = 0;           ///< [s] of operation the measurement stands for (a scene's part)
  int from = 0;              ///< first revolution to average (0: after steady state)
  std::string part;          ///< a scene's wearing part (--part)
};

double number_argument(const std::string& option, const std::string& v) {
  try {
    return std::stod(v);
  } catch (const std::exception&) {
    throw std::invalid_argument("wearsim calibrate: " + option + " '" + v + "' is not a number");
  }
}

int from_argument(const std::string& v) {
  int from = 0;
  try {
    from = std::stoi(v);
  } catch (const std::exception&) {
    throw std::invalid_argument("wearsim calibrate: --from '" + v + "' is not a revolution");
  }
  if (from <= 0)
    throw std::invalid_argument("wearsim calibrate: --from must be a revolution >= 1");
  return from;
}

CalibrateArguments calibrate_arguments(const std::vector<std::string>& args) {
  const std::string usage = "usage: wearsim calibrate <run> [--part <wall>] --measured <volume "
                            "with unit> (--revolutions <n> | --time <s>) [--from <revolution>]";
  CalibrateArguments a;
  for (std::size_t k = 0; k < args.size(); ++k) {
    const auto value = [&]() -> std::string {
      if (k + 1 >= args.size())
        throw std::invalid_argument("wearsim calibrate: " + args[k] + " needs a value; " + usage);
      return args[++k];
    };
    if (args[k] == "--measured")
      a.measured = value();
    else if (args[k] == "--revolutions")
      a.revolutions = number_argument("--revolutions", value());
    else if (args[k] == "--time")
      a.time = number_argument("--time", value());
    else if (args[k] == "--part")
      a.part = value();
    else if (args[k] == "--from")
      a.from = from_argument(value());
    else if (a.run.empty() && args[k].rfind("--", 0) != 0)
      a.run = args[k];
    else
      throw std::invalid_argument("wearsim calibrate: unexpected argument '" + args[k] + "'; " +
                                  usage);
  }
  if (a.run.empty() || a.measured.empty() || (a.revolutions == 0) == (a.time == 0))
    throw std::invalid_argument("wearsim calibrate: " + usage);
  return a;
}

/// What the calibration averaged: revolutions, or a scene part's stages (per second).
const char* averaged(const Calibration& c) {
  return c.unit == "s" ? "stages" : "revolutions";
}

void print_calibration(const CalibrateArguments& a, const Calibration& c, std::ostream& out) {
  char line[512];
  std::snprintf(line, sizeof line,
                "run %s%s, wear law %s\n"
                "simulated wear per %s %.6g mm^3 (mean of %d %s from %d)\n"
                "measured wear per %s  %.6g mm^3\n"
                "%s: %.6g -> %.6g (x %.4g)\n",
                a.run.c_str(), a.part.empty() ? "" : (", part '" + a.part + "'").c_str(),
                c.model.c_str(), c.unit.c_str(), c.simulated_per_rev * 1e9, c.n_revolutions,
                averaged(c), c.first_revolution, c.unit.c_str(), c.measured_per_rev * 1e9,
                c.coefficient_name.c_str(), c.coefficient, c.calibrated,
                c.calibrated / c.coefficient);
  out << line;
  for (const auto& [name, value] : c.also_scaled) {
    std::snprintf(line, sizeof line, "%s: %.6g -> %.6g (the same factor)\n", name.c_str(), value,
                  value * c.calibrated / c.coefficient);
    out << line;
  }
}

// <run>/calibration.prm: the Wear law subsection with the calibrated coefficient.
void write_calibration(const CalibrateArguments& a, const Calibration& c, const std::string& file) {
  meshes::write_atomically(file, [&](std::ostream& f) {
    char text[1024];
    std::snprintf(text, sizeof text,
                  "# wearsim calibrate: %s scaled so the steady wear per %s of\n"
                  "# %s%s (%.9g m^3, mean of %d %s from %d) equals the measured\n"
                  "# %.9g m^3 per %s (%s over %g %s).\n"
                  "# Copy this subsection into a case file, or INCLUDE this file after it.\n"
                  "subsection Wear law\n"
                  "  set Model = %s\n"
                  "  set %s = %.9g\n",
                  c.coefficient_name.c_str(), c.unit.c_str(), a.run.c_str(),
                  a.part.empty() ? "" : (", part " + a.part).c_str(), c.simulated_per_rev,
                  c.n_revolutions, averaged(c), c.first_revolution, c.measured_per_rev,
                  c.unit.c_str(), a.measured.c_str(), c.unit == "s" ? a.time : a.revolutions,
                  c.unit == "s" ? "s of operation" : "simulated revolutions", c.model.c_str(),
                  c.coefficient_name.c_str(), c.calibrated);
    f << text;
    for (const auto& [name, value] : c.also_scaled) {
      std::snprintf(text, sizeof text, "  set %s = %.9g\n", name.c_str(),
                    value * c.calibrated / c.coefficient);
      f << text;
    }
    f << "end\n";
  });
}
} // namespace

namespace {

/// Whether a run is calibrated per second (a scene's part without an evaluation) or per
/// revolution (the tester's run, or the part a scene evaluates: its periods). Throws for a
/// scene without --part and for a part that is not one of its wearing walls.
bool per_second(const CaseParameters& p, const std::string& run, const std::string& part) {
  if (p.scene.walls.empty())
    return false;
  if (part.empty())
    throw std::invalid_argument("calibrate: run '" + run +
                                "' is a scene's that evaluates no part (Scene/Evaluation/Wall); "
                                "name its wearing part with --part <wall name>");
  if (std::none_of(p.scene.walls.begin(), p.scene.walls.end(),
                   [&](const auto& w) { return w.name == part && w.wears; }))
    throw std::runtime_error("calibrate: run '" + run + "' has no wearing part '" + part +
                             "' (--part)");
  return p.scene.evaluation.wall != part;
}

// A scene's part without an evaluation: its staged stages' wear-law volume per second.
void calibrate_per_second(const std::string& run, const std::string& part, const CaseParameters& p,
                          double measured_volume, double time, int from_stage, Calibration& c) {
  const std::string path = run + "/parts/" + part + "/stages.csv";
  const auto rows = read_summary(path);
  if (rows.empty())
    throw std::runtime_error("calibrate: '" + path + "' holds no finished stage");
  double sum = 0;
  for (const auto& row : rows) {
    const int stage = int(number(row, "stage", path));
    const bool staged = int(number(row, "scheme", path)) == int(Scheme::staged);
    if (from_stage > 0 ? stage < from_stage : (!staged && c.n_revolutions == 0))
      continue;
    if (c.n_revolutions == 0)
      c.first_revolution = stage;
    sum += number(row, "dem_wear_volume_m3", path);
    ++c.n_revolutions;
  }
  if (c.n_revolutions == 0)
    throw std::runtime_error("calibrate: '" + path + "' has no " +
                             (from_stage > 0 ? "stage from " + std::to_string(from_stage)
                                             : std::string("staged stage")) +
                             " (name the first stage to average with --from)");
  c.unit = "s";
  c.simulated_per_rev = sum / (c.n_revolutions * p.scene.stage_duration);
  c.measured_per_rev = measured_volume / time;
}

} // namespace

Calibration calibrate(const std::string& run, double measured_volume, double revolutions,
                      int from_revolution, const std::string& named) {
  if (!(revolutions > 0) || !std::isfinite(revolutions))
    throw std::invalid_argument(std::string("calibrate: ") +
                                (named.empty() ? "--revolutions" : "--revolutions or --time") +
                                " must be a positive number");
  const CaseParameters p = read_case(run + "/parameters.prm");
  const bool scene = !p.scene.walls.empty();
  const std::string part = run_part(p, named);
  const bool by_time = per_second(p, run, part);
  Calibration c;
  c.model = p.wear_law.model;
  const dem::WearLawParameter* coefficient = linear_coefficient(c.model);
  if (!coefficient)
    throw std::runtime_error("calibrate: the wear law '" + c.model + "' of '" + run +
                             "/parameters.prm' has no coefficient to calibrate");
  c.coefficient_name = coefficient->name;
  c.coefficient = p.wear_law.*coefficient->member;
  // The law's other coefficients it is linear in, and a sum's other laws' coefficients.
  const auto laws = dem::wear_laws_of(c.model);
  for (std::size_t k = 0; k < laws.size(); ++k)
    for (std::size_t i = 0; i < laws[k]->parameters.size(); ++i) {
      const auto& other = laws[k]->parameters[i];
      if (other.scales_with_first || (k > 0 && i == 0))
        c.also_scaled.emplace_back(other.name, p.wear_law.*other.member);
    }
  if (by_time) {
    calibrate_per_second(run, part, p, measured_volume, revolutions, from_revolution, c);
    if (!(c.simulated_per_rev > 0))
      throw std::runtime_error("calibrate: part '" + part + "' of '" + run + "' wore nothing");
    c.calibrated = c.coefficient * c.measured_per_rev / c.simulated_per_rev;
    return c;
  }
  const std::string path = (scene ? run + "/parts/" + part : run) + "/summary.csv";
  const auto rows = read_summary(path);
  if (rows.empty())
    throw std::runtime_error("calibrate: '" + path + "' holds no finished revolution");
  int first = from_revolution;
  if (first <= 0) {
    const int steady = int(number(rows.back(), "steady_revolution", path));
    if (steady == 0)
      throw std::runtime_error(
          "calibrate: the run '" + run + "' never reached steady state (" +
          (scene ? "Scene/Evaluation" : "DEM") +
          "/Steady threshold); "
          "run more revolutions, or name the first revolution to average with --from");
    first = steady + 1;
  }
  double sum = 0;
  for (const auto& row : rows)
    if (int(number(row, "revolution", path)) >= first) {
      sum += number(row, "wear_volume_m3", path);
      ++c.n_revolutions;
    }
  if (c.n_revolutions == 0)
    throw std::runtime_error("calibrate: '" + path + "' has no revolution from " +
                             std::to_string(first) +
                             " on (steady state was reached at its end;"
                             " run more revolutions)");
  c.first_revolution = first;
  c.simulated_per_rev = sum / c.n_revolutions;
  if (!(c.simulated_per_rev > 0))
    throw std::runtime_error("calibrate: the run '" + run + "' wore nothing on the wear face");
  c.measured_per_rev = measured_volume / revolutions;
  c.calibrated = c.coefficient * c.measured_per_rev / c.simulated_per_rev;
  return c;
}

int run_calibrate_command(const std::vector<std::string>& args, std::ostream& out) {
  CalibrateArguments a = calibrate_arguments(args);
  const CaseParameters p = read_case(a.run + "/parameters.prm");
  a.part = run_part(p, a.part);
  const bool by_time = per_second(p, a.run, a.part);
  if (by_time && a.time == 0)
    throw std::invalid_argument("wearsim calibrate: part '" + a.part +
                                "' has no revolutions (Scene/Evaluation); give the time the "
                                "measurement stands for with --time <s>");
  if (!by_time && a.revolutions == 0)
    throw std::invalid_argument("wearsim calibrate: give the revolutions the measurement stands "
                                "for with --revolutions <n> (--time is for a scene's part "
                                "without an evaluation)");
  const Calibration c = calibrate(a.run, parse_volume(a.measured, "--measured"),
                                  by_time ? a.time : a.revolutions, a.from, a.part);
  print_calibration(a, c, out);
  const std::string file = a.run + "/calibration.prm";
  write_calibration(a, c, file);
  out << "written: " << file << "\n";
  return 0;
}

} // namespace wear::coupling

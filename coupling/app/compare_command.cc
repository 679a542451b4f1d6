// `wearsim compare [--from <k>] <A1> [<A2> ...] -- <B1> [<B2> ...]` (or `<runA> <runB>`):
// the figures of side A and side B, each as mean +- the half-width of its two-sided 95 %
// interval, and the reduction R = 1 - B/A in percent (positive: B wears less) with its
// interval; a reduction whose interval contains 0 is called not significant at 95 %.
//
// Per-revolution figures (wear on the wear face, per column) use the revolutions after the
// run's steady revolution (summary.csv, DEM/Steady threshold), or from --from on. Several
// runs per side (seeds): each run's mean is one independent value, the interval is across
// runs (t with n_runs - 1 dof). One run per side: batch means over that run's revolutions
// (coupling/analysis/interval.cc states the batch-size rule). Figures a run has once
// (totals, per stage) get an interval across runs, and none from a single run.
//
// `--part <name>`: the runs are scenes (`wearsim scene-run`) and the figures those of their
// wearing part <name> (parts/<name>/); without it a scene's run is read by the part it evaluates
// (Scene/Evaluation/Wall), so the tester as a scene compares as the built-in tester does. A part
// the scene evaluates (Scene/Evaluation, the tester's sample) has its revolutions (periods) with
// their steady state, compared as a tester's run, and a built-in tester's run on either side is
// read as its sample (the tester against the tester as a scene). Another part has the wear per
// stage (the wear-law volume of the stage's DEM windows, unamplified) from the first staged stage
// on, or from --from, in place of the wear per revolution after steady state; it has no
// steady-state judgement of its own, so its first staged stage (after the dem-only stages that fill
// the equipment) stands for it.
#include "coupling/app/compare_command.h"

#include "coupling/analysis/interval.h"
#include "coupling/output/hdf5_file.h"
#include "coupling/parameters/case_parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace wear::coupling {

namespace {
const double no_interval = std::numeric_limits<double>::quiet_NaN();

struct Run {
  std::string dir;
  std::string kind; ///< "plain", "convex" or "part 'liner'": what a side may not mix
  std::string unit; ///< "revolution" (the tester's runs) or "stage" (a scene's part)
  bool convex = false;
  std::uint64_t seed = 0;
  int steady_revolution = 0;                ///< first steady revolution (0: never steady)
  int first = 0;                            ///< first revolution averaged
  int n_revolutions = 0;                    ///< all revolutions of the run
  std::vector<double> wear;                 ///< [m^3] per revolution averaged, wear face
  std::vector<std::vector<double>> columns; ///< [m^3] per column, per revolution averaged
  double total_wear = 0;                    ///< [m^3] wear face, all revolutions
  std::vector<double> amplification, von_mises, safety, applied; ///< per stage [-], [Pa], [-]
};

struct Side {
  std::string label; ///< "A" or "B"
  std::vector<Run> runs;
};

// The steady_revolution column of summary.csv's last row (0: never steady).
int steady_revolution(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("cannot read '" + path + "'");
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty())
      last = line;
  std::stringstream h(header), r(last);
  for (std::string name, cell; std::getline(h, name, ',') && std::getline(r, cell, ',');)
    if (name == "steady_revolution")
      return std::stoi(cell);
  throw std::runtime_error("'" + path + "' has no column steady_revolution");
}

// The stages of a scene's wearing part `part` (parts/<part>/history.h5).
Run load_part(const std::string& dir, const std::string& side, int from, const std::string& part,
              const CaseParameters& p) {
  Run r;
  r.dir = dir;
  r.kind = "part '" + part + "'";
  r.unit = "stage";
  r.seed = p.dem.seed;
  const std::string folder = dir + "/parts/" + part;
  if (!std::filesystem::exists(folder + "/history.h5")) {
    std::string parts;
    for (const auto& w : p.scene.walls)
      if (w.wears)
        parts += (parts.empty() ? "" : ", ") + w.name;
    throw std::runtime_error("side " + side + ": run '" + dir + "' has no wearing part '" + part +
                             "' with stages (--part; its case's wearing walls: " +
                             (parts.empty() ? "none" : parts) + ")");
  }
  const Hdf5Reader h5(folder + "/history.h5");
  const auto stage = h5.doubles("/stages/stage");
  const auto scheme = h5.doubles("/stages/scheme");
  const auto wear = h5.doubles("/stages/dem_wear_volume_m3");
  r.amplification = h5.doubles("/stages/amplification");
  r.von_mises = h5.doubles("/stages/max_von_mises_ball_Pa");
  r.safety = h5.doubles("/stages/safety_factor");
  r.applied = h5.doubles("/stages/cumulative_applied_m3");
  if (stage.empty())
    throw std::runtime_error("side " + side + ": part '" + part + "' of run '" + dir +
                             "' has no finished stage yet");
  r.n_revolutions = int(stage.size());
  for (std::size_t k = 0; k < stage.size() && r.first == 0; ++k)
    if (int(scheme[k]) == int(Scheme::staged))
      r.first = int(stage[k]);
  if (from > 0)
    r.first = from;
  if (r.first == 0)
    throw std::runtime_error("side " + side + ": part '" + part + "' of run '" + dir +
                             "' has no staged stage; name the first stage to average with --from");
  for (std::size_t k = 0; k < stage.size(); ++k) {
    r.total_wear += wear[k];
    if (stage[k] >= r.first)
      r.wear.push_back(wear[k]);
  }
  if (r.wear.empty())
    throw std::runtime_error("side " + side + ": part '" + part + "' of run '" + dir +
                             "' has no stage from " + std::to_string(r.first) + " on (it has " +
                             std::to_string(r.n_revolutions) + " stages)");
  return r;
}

Run load(const std::string& dir, const std::string& side, int from, const std::string& named) {
  std::ostringstream warnings;
  const CaseParameters p = read_case(dir + "/parameters.prm", warnings);
  const bool tester = p.scene.walls.empty(); // an older engine's built-in tester run: its sample
  const std::string part = run_part(p, named);
  if (!tester && !part.empty() && p.scene.evaluation.wall != part)
    return load_part(dir, side, from, part, p);
  if (!tester && part.empty())
    throw std::runtime_error("side " + side + ": run '" + dir +
                             "' is a scene's (`wearsim scene-run`) that evaluates no part "
                             "(Scene/Evaluation/Wall); name its wearing part with --part <wall "
                             "name>");
  // the tester's run, or the part a scene evaluates as the tester's sample
  const std::string folder = tester ? dir : dir + "/parts/" + part;
  if (!tester && !std::filesystem::exists(folder + "/summary.csv"))
    throw std::runtime_error("side " + side + ": part '" + part + "' of run '" + dir +
                             "' has no finished stage yet (" + folder + "/summary.csv)");
  Run r;
  r.dir = dir;
  r.unit = "revolution";
  r.convex = p.geometry.sample.convex;
  r.kind = r.convex ? "convex" : "plain";
  r.seed = p.dem.seed;
  const Hdf5Reader h5(folder + "/history.h5");
  const auto revolution = h5.doubles("/revolutions/revolution");
  const auto wear = h5.doubles("/revolutions/wear_volume_m3");
  const auto cumulative = h5.doubles("/revolutions/wear_volume_cumulative_m3");
  const auto columns = h5.doubles("/revolutions/column_wear_m3");
  const auto dims = h5.dims("/revolutions/column_wear_m3");
  const std::size_t n_columns = dims.size() == 2 ? dims[1] : 0;
  r.amplification = h5.doubles("/stages/amplification");
  r.von_mises = h5.doubles("/stages/max_von_mises_ball_Pa");
  r.safety = h5.doubles("/stages/safety_factor");
  r.applied = h5.doubles("/stages/cumulative_applied_m3");
  if (revolution.empty())
    throw std::runtime_error("run '" + dir + "' has no finished revolution yet");
  r.n_revolutions = int(revolution.size());
  r.total_wear = cumulative.back();
  r.steady_revolution = steady_revolution(folder + "/summary.csv");
  if (from == 0 && r.steady_revolution == 0)
    throw std::runtime_error("side " + side + ": run '" + dir + "' never reached steady state (" +
                             (tester ? "DEM" : "Scene/Evaluation") +
                             "/Steady threshold), so it has no revolutions after steady state; "
                             "run more revolutions, or name the first revolution to average "
                             "with --from");
  r.first = from > 0 ? from : r.steady_revolution + 1;
  r.columns.resize(n_columns);
  for (std::size_t k = 0; k < revolution.size(); ++k) {
    if (revolution[k] < r.first)
      continue;
    r.wear.push_back(wear[k]);
    for (std::size_t c = 0; c < n_columns; ++c)
      r.columns[c].push_back(columns[k * n_columns + c]);
  }
  if (r.wear.empty())
    throw std::runtime_error("side " + side + ": run '" + dir + "' has no revolution from " +
                             std::to_string(r.first) + " on (" +
                             (from > 0 ? "--from" : "steady state was reached at its end") +
                             "; it has " + std::to_string(r.n_revolutions) + " revolutions)");
  return r;
}

Side load_side(const std::vector<std::string>& dirs, const std::string& label, int from,
               const std::string& part) {
  if (dirs.empty())
    throw std::invalid_argument("side " + label + " names no run folder");
  Side s;
  s.label = label;
  for (const auto& d : dirs)
    s.runs.push_back(load(d, label, from, part));
  const Run& first = s.runs.front();
  for (std::size_t k = 1; k < s.runs.size(); ++k) {
    const Run& r = s.runs[k];
    if (r.kind != first.kind)
      throw std::invalid_argument("side " + label + " mixes sample kinds: '" + first.dir + "' is " +
                                  first.kind + ", '" + r.dir + "' is " + r.kind +
                                  " (Geometry/Sample/Type)");
    if (r.columns.size() != first.columns.size())
      throw std::invalid_argument("side " + label + ": '" + first.dir + "' has " +
                                  std::to_string(first.columns.size()) + " columns, '" + r.dir +
                                  "' " + std::to_string(r.columns.size()));
    for (std::size_t j = 0; j < k; ++j)
      if (s.runs[j].seed == r.seed)
        throw std::invalid_argument("side " + label + ": '" + s.runs[j].dir + "' and '" + r.dir +
                                    "' have the same DEM/Seed (" + std::to_string(r.seed) +
                                    "); runs of one side must be independent (different seeds)");
  }
  if (s.runs.size() == 1 && first.wear.size() < 2)
    throw std::invalid_argument("side " + label + ": one run with " +
                                std::to_string(first.wear.size()) + " " + first.unit +
                                " averaged gives no interval; run more " + first.unit +
                                "s, or give more runs (seeds) for this side");
  return s;
}

// A per-revolution figure: batch means of one run, or the mean across runs of each run's mean.
Estimate per_revolution(const Side& s, const std::function<std::vector<double>(const Run&)>& get) {
  if (s.runs.size() == 1)
    return batch_means(get(s.runs.front()));
  std::vector<double> means;
  for (const auto& r : s.runs)
    means.push_back(mean_of(get(r)));
  return independent_mean(means);
}

// A figure each run has once: the value of one run (no interval), or the mean across runs.
Estimate per_run(const Side& s, const std::function<double(const Run&)>& get) {
  if (s.runs.size() == 1) {
    Estimate e;
    e.mean = get(s.runs.front());
    e.half_width = no_interval;
    e.n_values = 1;
    return e;
  }
  std::vector<double> values;
  for (const auto& r : s.runs)
    values.push_back(get(r));
  return independent_mean(values);
}

std::string format(const Estimate& e, double scale) {
  char buf[64];
  if (std::isnan(e.half_width))
    std::snprintf(buf, sizeof buf, "%.4g", e.mean * scale);
  else
    std::snprintf(buf, sizeof buf, "%.4g +- %.2g", e.mean * scale, e.half_width * scale);
  return buf;
}

std::string format_reduction(const Estimate& a, const Estimate& b) {
  if (a.mean == 0)
    return "-";
  char buf[64];
  if (std::isnan(a.half_width) || std::isnan(b.half_width)) {
    std::snprintf(buf, sizeof buf, "%+.1f %%", 100 * (1 - b.mean / a.mean));
    return buf;
  }
  const Estimate r = reduction(a, b);
  std::snprintf(buf, sizeof buf, "%+.1f +- %.1f %%", 100 * r.mean, 100 * r.half_width);
  return std::string(buf) + (significant(r) ? "" : "  not significant at 95 %");
}

void describe(const Side& s, const Estimate& wear, std::ostream& out) {
  const Run& first = s.runs.front();
  const char* unit = first.unit.c_str();
  out << s.label << " (" << first.kind << "): ";
  char buf[256];
  if (s.runs.size() == 1) {
    char tau[64];
    std::snprintf(tau, sizeof tau, "autocorrelation time %.2g %ss", wear.tau, unit);
    const std::string correlation = wear.tau >= 1 ? tau : "no positive autocorrelation";
    std::snprintf(buf, sizeof buf,
                  "interval from one run's %d %ss, batch means (wear per %s: "
                  "%d batches of %d, %s)\n",
                  wear.n_values, unit, unit, wear.n_batches, wear.batch_size, correlation.c_str());
    out << buf;
  } else {
    out << "interval across " << s.runs.size() << " runs (each run's mean over its " << unit << "s "
        << (first.unit == "stage" ? "averaged" : "after steady state") << "; t with "
        << s.runs.size() - 1 << " dof)\n";
  }
  for (const auto& r : s.runs) {
    if (r.unit == "stage") {
      std::snprintf(buf, sizeof buf, "  %s: stages %d-%d of %d (%s)\n", r.dir.c_str(), r.first,
                    r.n_revolutions, r.n_revolutions,
                    r.first > 0 ? "from the first staged stage, or --from" : "");
      out << buf;
      continue;
    }
    std::string steady = r.steady_revolution > 0
                             ? "steady from revolution " + std::to_string(r.steady_revolution)
                             : "never steady";
    if (r.steady_revolution == 0 || r.first != r.steady_revolution + 1)
      steady += "; averaged from --from";
    std::snprintf(buf, sizeof buf, "  %s: revolutions %d-%d of %d (%s)\n", r.dir.c_str(), r.first,
                  r.n_revolutions, r.n_revolutions, steady.c_str());
    out << buf;
  }
}

struct CompareArguments {
  std::vector<std::string> a, b;
  int from = 0;
  std::string part; ///< a scene's wearing part (--part); empty: the tester's runs
};

CompareArguments compare_arguments(const std::vector<std::string>& args) {
  const std::string usage = "usage: wearsim compare [--from <revolution or stage>] [--part "
                            "<wall name>] <runA1> [<runA2> ...] -- <runB1> [<runB2> ...], or "
                            "wearsim compare [options] <runA> <runB>";
  CompareArguments c;
  std::vector<std::string> folders;
  bool separator = false;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (args[k] == "--from") {
      if (k + 1 >= args.size())
        throw std::invalid_argument("--from needs a revolution; " + usage);
      try {
        c.from = std::stoi(args[++k]);
      } catch (const std::exception&) {
        c.from = 0;
      }
      if (c.from <= 0)
        throw std::invalid_argument("--from '" + args[k] + "' is not a revolution or stage >= 1");
    } else if (args[k] == "--part") {
      if (k + 1 >= args.size() || args[k + 1].rfind("--", 0) == 0)
        throw std::invalid_argument("--part needs the name of a scene's wearing wall; " + usage);
      c.part = args[++k];
    } else if (args[k] == "--") {
      if (separator)
        throw std::invalid_argument("'--' given twice; " + usage);
      separator = true;
      c.a = folders;
      folders.clear();
    } else if (args[k].rfind("--", 0) == 0) {
      throw std::invalid_argument("unknown option '" + args[k] + "'; " + usage);
    } else {
      folders.push_back(args[k]);
    }
  }
  if (separator) {
    c.b = folders;
  } else if (folders.size() == 2) {
    c.a = {folders[0]};
    c.b = {folders[1]};
  } else {
    throw std::invalid_argument("expected two run folders, or several per side with "
                                "'--' between the sides; " +
                                usage);
  }
  if (c.a.empty() || c.b.empty())
    throw std::invalid_argument("side " + std::string(c.a.empty() ? "A" : "B") +
                                " names no run folder; " + usage);
  return c;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v)
    s += (s.empty() ? "" : " ") + x;
  return s;
}
} // namespace

int run_compare_command(const std::vector<std::string>& args, std::ostream& out) {
  const CompareArguments c = compare_arguments(args);
  for (const auto* side : {&c.a, &c.b})
    for (const auto& dir : *side)
      if (!std::filesystem::is_directory(dir))
        throw std::runtime_error("side " + std::string(side == &c.a ? "A" : "B") +
                                 ": run folder '" + dir + "' does not exist");
  const Side a = load_side(c.a, "A", c.from, c.part), b = load_side(c.b, "B", c.from, c.part);
  const std::string unit = a.runs.front().unit;
  const auto wear = [](const Run& r) { return r.wear; };
  const Estimate wear_a = per_revolution(a, wear), wear_b = per_revolution(b, wear);
  describe(a, wear_a, out);
  describe(b, wear_b, out);
  out << "every figure: mean +- half-width of its 95 % interval; reduction = 1 - B/A (delta "
         "method)\n\n";
  char line[512];
  const auto row = [&](const std::string& what, const Estimate& ea, const Estimate& eb,
                       double scale, bool with_reduction) {
    std::snprintf(line, sizeof line, "%-38s %-22s %-22s %s\n", what.c_str(),
                  format(ea, scale).c_str(), format(eb, scale).c_str(),
                  with_reduction ? format_reduction(ea, eb).c_str() : "");
    out << line;
  };
  std::snprintf(line, sizeof line, "%-38s %-22s %-22s %s\n", "", "A", "B", "reduction");
  out << line;
  out << (unit == "stage" ? "per stage of part '" + c.part + "' (the wear law's DEM volume)\n"
                          : std::string("per revolution after steady state\n"));
  row("wear [mm^3]", wear_a, wear_b, 1e9, true);
  for (std::size_t k = 0; k < std::min(a.runs[0].columns.size(), b.runs[0].columns.size()); ++k) {
    const auto column = [k](const Run& r) { return r.columns[k]; };
    row("column " + std::to_string(k + 1) + " wear [mm^3]", per_revolution(a, column),
        per_revolution(b, column), 1e9, true);
  }
  out << "whole runs\n";
  row("DEM wear, all " + unit + "s [mm^3]", per_run(a, [](const Run& r) { return r.total_wear; }),
      per_run(b, [](const Run& r) { return r.total_wear; }), 1e9, true);
  const auto all_have = [](const Side& s, std::size_t k) {
    return std::all_of(s.runs.begin(), s.runs.end(),
                       [k](const Run& r) { return k < r.applied.size(); });
  };
  const auto last_stage = [](const Side& s) {
    std::size_t n = s.runs.front().applied.size();
    for (const auto& r : s.runs)
      n = std::min(n, r.applied.size());
    return n;
  };
  const std::size_t n_stages_a = last_stage(a), n_stages_b = last_stage(b);
  if (n_stages_a > 0 && n_stages_b > 0)
    row("removed from the geometry [mm^3]",
        per_run(a, [&](const Run& r) { return r.applied[n_stages_a - 1]; }),
        per_run(b, [&](const Run& r) { return r.applied[n_stages_b - 1]; }), 1e9, true);
  bool different_counts = false;
  for (const Side* s : {&a, &b})
    for (const auto& r : s->runs)
      different_counts |= r.n_revolutions != a.runs[0].n_revolutions;
  if (different_counts)
    out << "note: the runs have different " << unit
        << " counts; whole-run totals are not like for like\n";
  for (std::size_t k = 0; k < std::max(n_stages_a, n_stages_b); ++k) {
    if (!all_have(a, k) || !all_have(b, k)) {
      out << "stage " << k + 1 << ": not in every run\n";
      continue;
    }
    const std::string stage = "stage " + std::to_string(k + 1) + " ";
    // a stage without a stress solve (dem-only, reference) has zeros for stress and safety: not
    // a figure
    const auto solved = [k](const Side& s) {
      return std::any_of(s.runs.begin(), s.runs.end(),
                         [k](const Run& r) { return r.von_mises[k] > 0; });
    };
    if (!solved(a) && !solved(b)) {
      out << stage << "no stress solve in any run (dem-only or reference)\n";
      continue;
    }
    const auto at = [k](const std::vector<double> Run::*v) {
      return [k, v](const Run& r) { return (r.*v)[k]; };
    };
    row(stage + "amplification", per_run(a, at(&Run::amplification)),
        per_run(b, at(&Run::amplification)), 1, false);
    row(stage + "peak ball-averaged von Mises [MPa]", per_run(a, at(&Run::von_mises)),
        per_run(b, at(&Run::von_mises)), 1e-6, true);
    row(stage + "safety factor", per_run(a, at(&Run::safety)), per_run(b, at(&Run::safety)), 1,
        false);
  }
  if (unit == "stage")
    return 0; // plot_run.py draws the tester's runs
  out << "plot: /usr/bin/python3 coupling/output/plot_run.py --compare "
      << (c.from > 0 ? "--from " + std::to_string(c.from) + " " : "") << joined(c.a) << " -- "
      << joined(c.b) << "\n";
  return 0;
}

} // namespace wear::coupling

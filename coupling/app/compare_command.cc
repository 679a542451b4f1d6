// `wearsim compare <runA> <runB>`: wear volumes and the reduction of B against A (DEM wear
// over all revolutions, and the volume removed from the geometry with its amplification),
// wear per column, and per stage the peak ball-averaged von Mises stress (the measure that
// converges under refinement, fem/stress_measures.h) and the safety factor of both runs.
// Reduction = 1 - B / A, in percent (positive: B wears less).
#include "coupling/app/compare_command.h"

#include "coupling/output/hdf5_file.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace wear::coupling {

namespace {
struct RunHistory {
  std::string name;
  std::vector<double> cumulative, columns, stage, von_mises, safety, applied, amplification;
  std::size_t n_columns = 0;
};

RunHistory load(const std::string& dir) {
  const Hdf5Reader h5(dir + "/history.h5");
  RunHistory r;
  r.name = dir;
  r.cumulative = h5.doubles("/revolutions/wear_volume_cumulative_m3");
  r.columns = h5.doubles("/revolutions/column_wear_m3");
  const auto dims = h5.dims("/revolutions/column_wear_m3");
  r.n_columns = dims.size() == 2 ? dims[1] : 0;
  r.stage = h5.doubles("/stages/stage");
  r.von_mises = h5.doubles("/stages/max_von_mises_ball_Pa");
  r.safety = h5.doubles("/stages/safety_factor");
  r.applied = h5.doubles("/stages/cumulative_applied_m3");
  r.amplification = h5.doubles("/stages/amplification");
  if (r.cumulative.empty())
    throw std::runtime_error("run '" + dir + "' has no finished revolution yet");
  return r;
}

double column_total(const RunHistory& r, std::size_t c) {
  double s = 0;
  for (std::size_t k = c; k < r.columns.size(); k += r.n_columns)
    s += r.columns[k];
  return s;
}

std::string reduction(double a, double b) {
  if (a == 0)
    return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.1f %%", 100 * (1 - b / a));
  return buf;
}
} // namespace

int run_compare_command(const std::vector<std::string>& args, std::ostream& out) {
  if (args.size() != 2)
    throw std::invalid_argument("wearsim compare: expected two run folders: wearsim compare "
                                "<runA> <runB>");
  const RunHistory a = load(args[0]), b = load(args[1]);
  char line[256];
  std::snprintf(line, sizeof line, "%-34s %16s %16s %12s\n", "", "A", "B", "reduction");
  out << "A: " << a.name << "\nB: " << b.name << "\n" << line;
  const auto row = [&](const std::string& what, double va, double vb, double scale) {
    std::snprintf(line, sizeof line, "%-34s %16.4f %16.4f %12s\n", what.c_str(), va * scale,
                  vb * scale, reduction(va, vb).c_str());
    out << line;
  };
  std::snprintf(line, sizeof line, "%-34s %16zu %16zu\n", "revolutions", a.cumulative.size(),
                b.cumulative.size());
  out << line;
  if (a.cumulative.size() != b.cumulative.size())
    out << "note: the runs have different revolution counts; totals are not like for like\n";
  row("DEM wear, all revolutions [mm^3]", a.cumulative.back(), b.cumulative.back(), 1e9);
  row("per revolution [mm^3]", a.cumulative.back() / double(a.cumulative.size()),
      b.cumulative.back() / double(b.cumulative.size()), 1e9);
  if (!a.applied.empty() && !b.applied.empty())
    row("removed from the geometry [mm^3]", a.applied.back(), b.applied.back(), 1e9);
  for (std::size_t c = 0; c < std::min(a.n_columns, b.n_columns); ++c)
    row("column " + std::to_string(c + 1) + " wear [mm^3]", column_total(a, c), column_total(b, c),
        1e9);
  out << "\nstage  amplification A/B   ball-averaged von Mises A/B [MPa]  safety factor A/B\n";
  for (std::size_t k = 0; k < std::max(a.stage.size(), b.stage.size()); ++k) {
    const auto at = [&](const std::vector<double>& v) { return k < v.size() ? v[k] : 0.0; };
    std::snprintf(line, sizeof line, "%5zu  %8g / %-8g  %11.4f / %-11.4f  %8.1f / %-8.1f\n", k + 1,
                  at(a.amplification), at(b.amplification), at(a.von_mises) * 1e-6,
                  at(b.von_mises) * 1e-6, at(a.safety), at(b.safety));
    out << line;
  }
  out << "plot: /usr/bin/python3 coupling/output/plot_run.py --compare " << a.name << " " << b.name
      << "\n";
  return 0;
}

} // namespace wear::coupling

// What is left of a worn part's convex elements, measured again from a finished (or stopped)
// run's kept surfaces on the elements' unworn footprints.
//
// A run records each element's height and volume above the foot its labels span on every
// stage's surface (part_life.csv). The labels pass from each surface to the next by the
// nearest old face, so that foot moves a little with every stage, whatever the stage's size;
// a run with twice the stages loses more measured volume for the same wear. This command
// takes each element's outline from the surface the part was first meshed with (stage 0) and
// measures every kept stage's surface on it (meshes/part_life.h, footprint_standing):
//   V_e = sum over upward faces with plan centroid inside the outline of (z_f - z_foot,f) A_f,
// z_foot the mean value interpolant of the worn surface's heights along the outline. The
// stages, their equivalent revolutions and hours are the run's part_life.csv's; a stage whose
// surface file is a stub (a run continued from a kept checkpoint) is left out and named. Where
// stage 0 is such a stub, a tester's sample is meshed again from the run's parameters.prm as
// the run meshed it first (first_sample_mesh, deterministic for one gmsh).
#include "coupling/app/life_command.h"

#include "coupling/loop/wearing_part.h"
#include "coupling/output/grid_history.h"
#include "coupling/parameters/case_parameters.h"
#include "meshes/atomic_file.h"
#include "meshes/part_life.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace wear::coupling {

namespace {

namespace fs = std::filesystem;

struct LifeArguments {
  std::string run, part;
};

LifeArguments life_arguments(const std::vector<std::string>& args) {
  LifeArguments a;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--part") {
      if (i + 1 >= args.size())
        throw std::invalid_argument("wearsim life: --part needs the name of a part");
      a.part = args[++i];
    } else if (args[i].rfind("--", 0) == 0)
      throw std::invalid_argument("wearsim life: unknown option '" + args[i] + "'");
    else if (a.run.empty())
      a.run = args[i];
    else
      throw std::invalid_argument("wearsim life: one run folder, not '" + a.run + "' and '" +
                                  args[i] + "'");
  }
  if (a.run.empty())
    throw std::invalid_argument("usage: wearsim life <run> [--part <name>]");
  const fs::path parts = fs::path(a.run) / "parts";
  if (!fs::is_directory(parts))
    throw std::invalid_argument("wearsim life: '" + a.run + "' holds no parts/ folder: not a " +
                                "run of a wearing part");
  if (a.part.empty()) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(parts))
      if (e.is_directory())
        names.push_back(e.path().filename().string());
    if (names.size() != 1)
      throw std::invalid_argument("wearsim life: '" + a.run + "' has " +
                                  std::to_string(names.size()) + " parts; name one with --part");
    a.part = names.front();
  }
  if (!fs::is_directory(parts / a.part))
    throw std::invalid_argument("wearsim life: '" + a.run + "' has no part '" + a.part + "'");
  return a;
}

// A stage of the run's part_life.csv: its equivalent revolutions and hours as written, and
// the sum of its elements' volumes there.
struct LifeStage {
  std::string revolutions, hours;
  double labelled_volume = 0; ///< [m^3]
};

std::map<int, LifeStage> recorded_stages(const std::string& file) {
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error("wearsim life: no " + file + " (a run older than the part's life)");
  std::string line;
  std::getline(in, line);
  if (line.rfind("stage,equivalent_revolutions,equivalent_hours,what,", 0) != 0)
    throw std::runtime_error("wearsim life: " + file + " does not start with part_life.csv's " +
                             "header");
  std::map<int, LifeStage> stages;
  while (std::getline(in, line)) {
    std::vector<std::string> c;
    std::stringstream row(line);
    for (std::string x; std::getline(row, x, ',');)
      c.push_back(x);
    if (c.size() != 6)
      throw std::runtime_error("wearsim life: " + file + ": '" + line + "' has " +
                               std::to_string(c.size()) + " columns, not 6");
    auto& s = stages[std::stoi(c[0])];
    s.revolutions = c[1], s.hours = c[2];
    if (c[3] != "part")
      s.labelled_volume += std::stod(c[5]);
  }
  return stages;
}

std::string stage_file(const fs::path& part, int stage) {
  return grid_stage_path(part.string(), "surface", stage, ".h5");
}

// The surface the part was first meshed with: its stage 0, or for a tester's sample whose
// stage 0 is not kept, the sample meshed again from the run's parameters.
meshes::SurfaceMesh first_surface(const LifeArguments& a, const fs::path& part, std::ostream& out) {
  const std::string first = stage_file(part, 0);
  if (fs::is_regular_file(first) && holds_grid(first))
    return read_surface_stage(first);
  if (a.part != "sample")
    throw std::runtime_error("wearsim life: " + first + " does not hold the first surface, on " +
                             "which the elements' footprints lie");
  const CaseParameters p = read_case(a.run + "/parameters.prm");
  const fs::path dir = fs::temp_directory_path() / ("wearsim-life-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  meshes::GeneratedSample g;
  try {
    g = first_sample_mesh(p, (dir / "part.msh").string());
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
  out << "wearsim life: " << first << " is not kept; the sample meshed again from " << a.run
      << "/parameters.prm (" << g.surface.n_faces() << " faces)\n";
  return g.surface;
}

} // namespace

int run_life_command(const std::vector<std::string>& args, std::ostream& out) {
  const auto a = life_arguments(args);
  const fs::path part = fs::path(a.run) / "parts" / a.part;
  const auto stages = recorded_stages((part / "part_life.csv").string());
  const auto footprints = meshes::element_footprints(first_surface(a, part, out));
  if (footprints.empty())
    throw std::runtime_error("wearsim life: the first surface of part '" + a.part +
                             "' has no convex element (labels C<j><k>)");
  out << "wearsim life: part '" << a.part << "', " << footprints.size()
      << " elements on their footprints of stage 0\n"
      << "stage      hours  on footprints [mm^3]  above the labels' foot [mm^3]\n";
  std::ostringstream rows;
  std::vector<int> missing;
  for (const auto& [stage, s] : stages) {
    const std::string file = stage_file(part, stage);
    if (!fs::is_regular_file(file) || !holds_grid(file)) {
      missing.push_back(stage);
      continue;
    }
    const auto standing = meshes::footprint_standing(read_surface_stage(file), footprints);
    rows << element_life_rows(std::to_string(stage) + "," + s.revolutions + "," + s.hours,
                              standing);
    double total = 0;
    for (const auto& [label, e] : standing)
      total += e.volume;
    char line[160];
    std::snprintf(line, sizeof line, "%5d %10s %21.1f %30.1f\n", stage, s.hours.c_str(),
                  total * 1e9, s.labelled_volume * 1e9);
    out << line;
  }
  if (!missing.empty()) {
    out << "not measured (no surface kept in the folder):";
    for (const int k : missing)
      out << " " << k;
    out << "\n";
  }
  const std::string file = (part / "element_life.csv").string();
  meshes::write_atomically(file, [&](std::ostream& o) { o << element_life_header << rows.str(); });
  out << "written: " << file << "\n";
  return 0;
}

} // namespace wear::coupling

// `wearsim bench evolution`: the cost and accuracy of the worn surface's evolutions
// (fem::SurfaceEvolution) on one stage of wear, side by side on the same input.
//
// Input, either
//   - a worn stage file (--state, coupling/output/worn_stage_file.h): a worn sample and the
//     removed volume per face of one of its stages, scaled by --scale (the wear-out's stage
//     24, tests/data/wear-out/stage23.h5, is the surface on which the explicit recession
//     folds), or
//   - the unworn reference sample (--sample convex|plain, --mesh-size; its sides free, or held
//     as in the holder with --holder frame) with the pattern of
//     `wearsim bench fem`: depth x n_z^2 per wearing face (tops and flats most, flanks less;
//     --depth, default 20 um, a stage of the default case is about 1 um).
// Each evolution applies the same stage to its own fresh copy of the sample
// (WornSample::apply_wear) and is timed as a whole. Accuracy, per evolution:
//   volume error   |V_before - V_after - (asked - worn through)| / asked, the mesh's volume
//   unworn offset  the largest distance from a face that does not wear (held, clamped,
//                  or out of the flow) to the surface before the stage; 0 where it stays
//   worst triangle the smallest triangle quality of the surface handed on (meshes/mesh_quality.h)
//   min scaled Jacobian of the volume mesh handed on
//   surface faces  of the surface handed on (the implicit step's target edge sets it)
//   elements       the convex elements' volume after the stage on the workload's outlines
//                  (meshes::footprint_standing), and labels' by the foot their labels span
//                  (meshes::convex_element_standing); both before the stage in the header
// An evolution that takes implicit steps runs once per step depth of --step-depth (0: the
// stage in one step; the same stage in more steps says whether the steps compose).
// An evolution that takes implicit steps runs once per target edge of --target-edge and flat
// edge of --flat-edge (lists): the distances between their surfaces say what a coarser new
// surface costs in shape.
// and between each pair that completed, the two-sided sampled Hausdorff distance of their
// worn surfaces (meshes::farthest_point both ways), where it is reached, and the mean
// distance of the sampled points: how far the evolutions disagree.
// An evolution that gives up (the explicit recession where it still folds at its smallest
// increment) is reported with its message, not as a failure of the benchmark.
#include "coupling/app/bench_evolution.h"

#include "coupling/output/text_format.h"
#include "coupling/output/worn_stage_file.h"
#include "fem/fem_parameters.h"
#include "fem/worn_sample.h"
#include "meshes/atomic_file.h"
#include "meshes/mesh_quality.h"
#include "meshes/part_life.h"
#include "meshes/sample_generator.h"
#include "meshes/stopwatch.h"
#include "meshes/surface_locator.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <utility>

namespace wear::coupling {

namespace {

struct BenchEvolutionArguments {
  std::string state;                  ///< a worn stage file, or empty: the generated sample
  double scale = 1;                   ///< [-] on the state's removed volume
  meshes::SampleGeometry sample;      ///< the generated sample (convex unless --sample plain)
  bool held_sides = false;            ///< --holder frame: its sides held, as in the holder
  meshes::SampleGeometry state_sizes; ///< remesh sizes of the state (the wear-out case's)
  double depth = 20e-6;               ///< [m] the generated stage's depth on a flat top
  std::vector<std::string> evolutions{"explicit only", "explicit then implicit", "implicit"};
  std::string directory = "output/bench-evolution";
  meshes::ImplicitRecessionParameters implicit; ///< --grid-spacing
  std::vector<double> target_edges, flat_edges; ///< [m] --target-edge, --flat-edge
  std::vector<double> step_depths;              ///< [m] --step-depth (0: one implicit step)
};

double positive(const std::string& option, const std::string& value, double upper) {
  double x = 0;
  try {
    x = std::stod(value);
  } catch (const std::exception&) {
    throw std::invalid_argument("wearsim bench evolution: " + option + " '" + value +
                                "' is not a number");
  }
  if (!(x > 0 && x < upper))
    throw std::invalid_argument("wearsim bench evolution: " + option + " must lie in (0, " +
                                format("%g", upper) + ")");
  return x;
}

std::vector<std::string> comma_separated(const std::string& v) {
  std::vector<std::string> items;
  for (std::size_t b = 0; b <= v.size();) {
    const std::size_t e = std::min(v.find(',', b), v.size());
    items.push_back(v.substr(b, e - b));
    b = e + 1;
  }
  return items;
}

BenchEvolutionArguments bench_evolution_arguments(const std::vector<std::string>& args) {
  BenchEvolutionArguments a;
  a.state_sizes.mesh_size = 0.003; // cases/wear-out: the stage-24 file's sizes
  a.state_sizes.mesh_size_bottom = 0.005;
  a.state_sizes.curvature_refinement = false;
  a.sample.mesh_size = 0.002; // cases/quick's wear-face mesh
  const fem::FemParameters defaults;
  a.implicit = defaults.worn_sample.implicit;
  for (std::size_t k = 0; k < args.size(); k += 2) {
    if (k + 1 >= args.size())
      throw std::invalid_argument("wearsim bench evolution: option " + args[k] + " needs a value");
    const std::string &f = args[k], &v = args[k + 1];
    if (f == "--state")
      a.state = v;
    else if (f == "--scale")
      a.scale = positive(f, v, 100);
    else if (f == "--sample") {
      if (v != "convex" && v != "plain")
        throw std::invalid_argument("wearsim bench evolution: --sample is convex or plain");
      a.sample.convex = v == "convex";
    } else if (f == "--holder") {
      if (v != "frame" && v != "none")
        throw std::invalid_argument("wearsim bench evolution: --holder is frame or none");
      a.held_sides = v == "frame";
    } else if (f == "--mesh-size")
      a.sample.mesh_size = a.state_sizes.mesh_size = positive(f, v, 0.01);
    else if (f == "--depth")
      a.depth = positive(f, v, 0.005);
    else if (f == "--evolutions") {
      a.evolutions.clear();
      for (std::string name : comma_separated(v)) {
        std::replace(name.begin(), name.end(), '-', ' ');
        try {
          fem::surface_evolution(name);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument("wearsim bench evolution: --evolutions: " +
                                      std::string(e.what()));
        }
        a.evolutions.push_back(name);
      }
    } else if (f == "--grid-spacing")
      a.implicit.spacing = positive(f, v, 0.005);
    else if (f == "--flat-edge" || f == "--target-edge") {
      auto& list = f == "--flat-edge" ? a.flat_edges : a.target_edges;
      for (const std::string& x : comma_separated(v))
        list.push_back(f == "--flat-edge" && x == "0" ? 0.0 : positive(f, x, 0.01));
    } else if (f == "--step-depth") {
      for (const std::string& x : comma_separated(v))
        a.step_depths.push_back(x == "0" ? 0.0 : positive(f, x, 0.01));
    } else if (f == "--output")
      a.directory = v;
    else
      throw std::invalid_argument("wearsim bench evolution: unknown option '" + f + "'");
  }
  if (a.target_edges.empty())
    a.target_edges.push_back(a.implicit.target_edge);
  if (a.flat_edges.empty())
    a.flat_edges.push_back(a.implicit.flat_edge);
  if (a.step_depths.empty())
    a.step_depths.push_back(defaults.worn_sample.implicit_step_depth);
  for (const double edge : a.target_edges)
    for (const double flat : a.flat_edges) {
      fem::FemParameters checked; // the implicit step's parameters, checked as a case's are
      checked.worn_sample.implicit = a.implicit;
      checked.worn_sample.implicit.target_edge = edge;
      checked.worn_sample.implicit.flat_edge = flat;
      try {
        fem::validate(checked);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(
            "wearsim bench evolution: --grid-spacing, --target-edge, --flat-edge: " +
            std::string(e.what()));
      }
    }
  return a;
}

/// One worn sample and its stage, as every evolution starts from it.
struct Workload {
  fem::WornSampleState state;
  std::vector<double> removed;  ///< [m^3] per face of state.surface
  meshes::SampleGeometry sizes; ///< of the remeshes
  std::string description;
  /// the elements' outlines on the workload's surface (meshes::element_footprints): every
  /// evolution's elements are measured on them
  meshes::ElementFootprints footprints;
};

Workload state_workload(const BenchEvolutionArguments& a) {
  WornStage s = read_worn_stage(a.state);
  Workload w{std::move(s.state), std::move(s.removed_volume), a.state_sizes, {}, {}};
  for (double& v : w.removed)
    v *= a.scale;
  w.description = "worn stage '" + a.state + "' x " + format("%g", a.scale);
  return w;
}

Workload sample_workload(const BenchEvolutionArguments& a) {
  const std::string msh = a.directory + "/unworn.msh";
  auto generated = meshes::generate_sample(a.sample, msh);
  generated.surface.roles = meshes::sample_roles(a.held_sides);
  const fem::FemParameters defaults;
  fem::WornSample unworn(msh, generated.surface,
                         fem::worn_sample_parameters(defaults, a.sample, a.directory));
  Workload w{unworn.state(), {}, a.sample, {}, {}};
  const auto& s = w.state.surface;
  const auto area = meshes::face_areas(s);
  const auto normal = meshes::face_normals(s);
  w.removed.assign(s.n_faces(), 0.0);
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_wears(f))
      w.removed[f] = a.depth * normal[f].z * normal[f].z * area[f];
  w.description =
      std::string(a.sample.convex ? "convex" : "plain") + " sample" +
      (a.held_sides ? " (sides held)" : "") + ", " +
      format("%g mm mesh, %g um x n_z^2 a face", a.sample.mesh_size * 1e3, a.depth * 1e6);
  return w;
}

struct Outcome {
  std::string evolution, error;
  double seconds = 0;
  fem::WearStageReport report;
  std::optional<meshes::SurfaceMesh> surface; ///< handed on, when the stage completed
  double volume_error = 0, unworn_offset = 0, worst_triangle = 0;
  /// [m^3] the elements' volume on the workload's footprints, and on the labels handed on
  double element_volume = 0, labelled_element_volume = 0;
  meshes::Vec3 unworn_offset_at{0, 0, 0}; ///< [m] centroid of the unworn face farthest off
  int unworn_offset_label = 0;
};

/// The convex elements' volume on `s` [m^3]: on the workload's footprints, and above the
/// foot their labels span.
std::pair<double, double> element_volumes(const meshes::SurfaceMesh& s,
                                          const meshes::ElementFootprints& footprints) {
  std::pair<double, double> v{0, 0};
  for (const auto& [label, e] : meshes::footprint_standing(s, footprints))
    v.first += e.volume;
  for (const auto& [label, e] : meshes::convex_element_standing(s))
    v.second += e.volume;
  return v;
}

// `label` names the outcome (the evolution, and its target edge where several are run).
Outcome run_evolution(const Workload& w, const std::string& name, const std::string& label,
                      const meshes::ImplicitRecessionParameters& implicit, double step_depth,
                      const std::string& dir) {
  Outcome o;
  o.evolution = label;
  fem::FemParameters fp;
  fp.worn_sample.implicit = implicit;
  fp.worn_sample.implicit_step_depth = step_depth;
  fp.surface_evolution = name; // worn_sample_parameters() sets the evolution from its name
  std::string sub = label;
  std::replace(sub.begin(), sub.end(), ' ', '-');
  meshes::ensure_directory(dir + "/" + sub);
  fem::WornSample sample(w.state, fem::worn_sample_parameters(fp, w.sizes, dir + "/" + sub));
  meshes::FaceField<double> removed("removed volume", "m^3", meshes::Extensivity::extensive,
                                    sample.surface());
  removed.values() = w.removed;
  const meshes::Stopwatch clock;
  try {
    o.report = sample.apply_wear(removed);
  } catch (const std::exception& e) {
    o.seconds = clock.seconds();
    o.error = e.what();
    return o;
  }
  o.seconds = clock.seconds();
  const auto& r = o.report;
  o.volume_error = std::abs(r.volume_change - (r.removed_volume - r.worn_through_volume)) /
                   std::max(r.removed_volume, 1e-300);
  const auto& s = sample.surface();
  const auto unworn = meshes::farthest_unworn_face(s, w.state.surface);
  o.unworn_offset = unworn.distance;
  o.unworn_offset_at = unworn.centroid;
  o.unworn_offset_label = unworn.label;
  o.worst_triangle = meshes::min_triangle_quality(s);
  std::tie(o.element_volume, o.labelled_element_volume) = element_volumes(s, w.footprints);
  o.surface = s;
  return o;
}

void report(const Workload& w, const std::vector<Outcome>& outcomes, std::ostream& out) {
  double asked = 0;
  for (const double v : w.removed)
    asked += v;
  out << "workload: " << w.description << ": " << w.state.surface.n_faces() << " faces, "
      << w.state.tetrahedra.size() / 4 << " tetrahedra, " << format("%.2f", asked * 1e9)
      << " mm^3 asked\n";
  const auto [elements_before, labelled_before] = element_volumes(w.state.surface, w.footprints);
  out << format("elements before the stage: %.2f mm^3 on their footprints, %.2f mm^3 by their "
                "labels' foot\n",
                elements_before * 1e9, labelled_before * 1e9);
  out << format("%-24s %9s %5s %7s %8s %9s %11s %10s %9s %8s %8s %9s %9s\n", "evolution",
                "time [s]", "incr", "remesh", "implicit", "implicit", "volume", "unworn", "worst",
                "min", "surface", "elements", "labels'");
  out << format("%-24s %9s %5s %7s %8s %9s %11s %10s %9s %8s %8s %9s %9s\n", "", "", "", "(1st)",
                "steps", "[s]", "error", "off [mm]", "triangle", "Jacobian", "faces", "[mm^3]",
                "[mm^3]");
  for (const auto& o : outcomes) {
    if (!o.surface) {
      out << format("%-24s %9.1f  gave up: %s\n", o.evolution.c_str(), o.seconds, o.error.c_str());
      continue;
    }
    const auto& r = o.report;
    out << format("%-24s %9.1f %5d %3d (%d) %8d %9.1f %11.2e %10.4f %9.4f %8.4f %8zu %9.2f "
                  "%9.2f\n",
                  o.evolution.c_str(), o.seconds, r.increments, r.n_remeshes,
                  r.n_first_attempt_remeshes, r.n_implicit, r.implicit_seconds, o.volume_error,
                  o.unworn_offset * 1e3, o.worst_triangle, r.quality.min_scaled_jacobian,
                  o.surface->n_faces(), o.element_volume * 1e9, o.labelled_element_volume * 1e9);
  }
  for (const auto& o : outcomes) { // where a path handed over, and why
    for (const auto& why : o.report.explicit_remesh_failures)
      out << format("'%s': an explicit increment's remesh failed, the implicit step took the "
                    "rest: %s\n",
                    o.evolution.c_str(), why.c_str());
    for (const auto& why : o.report.implicit_failures)
      out << format("'%s': an implicit step failed, the explicit increments went on: %s\n",
                    o.evolution.c_str(), why.c_str());
  }
  for (const auto& o : outcomes)
    if (o.surface && o.unworn_offset > 0)
      out << format("'%s': the unworn face farthest off (%s) at (%.2f, %.2f, %.2f) mm\n",
                    o.evolution.c_str(), meshes::label::name(o.unworn_offset_label).c_str(),
                    o.unworn_offset_at.x * 1e3, o.unworn_offset_at.y * 1e3,
                    o.unworn_offset_at.z * 1e3);
  for (std::size_t i = 0; i < outcomes.size(); ++i)
    for (std::size_t j = i + 1; j < outcomes.size(); ++j)
      if (outcomes[i].surface && outcomes[j].surface) {
        const auto ij = meshes::farthest_point(*outcomes[i].surface, *outcomes[j].surface);
        const auto ji = meshes::farthest_point(*outcomes[j].surface, *outcomes[i].surface);
        const auto& far = ij.distance >= ji.distance ? ij : ji;
        out << format("surfaces of '%s' and '%s' apart by at most %.4f mm (%s, at (%.2f, %.2f, "
                      "%.2f) mm), by %.4f mm on average\n",
                      outcomes[i].evolution.c_str(), outcomes[j].evolution.c_str(),
                      far.distance * 1e3, meshes::label::name(far.label).c_str(), far.at.x * 1e3,
                      far.at.y * 1e3, far.at.z * 1e3, 0.5 * (ij.mean + ji.mean) * 1e3);
      }
}

} // namespace

int run_bench_evolution(const std::vector<std::string>& args, std::ostream& out) {
  const BenchEvolutionArguments a = bench_evolution_arguments(args);
  meshes::ensure_directory(a.directory);
  out << "machine: " << std::thread::hardware_concurrency() << " hardware threads\n";
  out << "implicit step: grid spacing " << format("%g", a.implicit.spacing * 1e3) << " mm\n";
  Workload w = a.state.empty() ? sample_workload(a) : state_workload(a);
  w.footprints = meshes::element_footprints(w.state.surface);
  std::vector<Outcome> outcomes;
  for (const auto& name : a.evolutions) {
    const bool implicit_steps =
        fem::surface_evolution(name) != fem::SurfaceEvolution::explicit_only;
    const std::size_t n_flat = a.flat_edges.size(), n_depth = a.step_depths.size();
    const std::size_t n_runs = implicit_steps ? a.target_edges.size() * n_flat * n_depth : 1;
    for (std::size_t k = 0; k < n_runs; ++k) {
      auto implicit = a.implicit;
      implicit.target_edge = a.target_edges[k / (n_flat * n_depth)];
      implicit.flat_edge = a.flat_edges[k / n_depth % n_flat];
      const double step_depth = a.step_depths[k % n_depth];
      std::string label = name;
      if (implicit_steps)
        label += format(" %g mm", implicit.target_edge * 1e3) +
                 (implicit.flat_edge > 0 ? format(" flat %g", implicit.flat_edge * 1e3) : "") +
                 (step_depth > 0 ? format(" step %g", step_depth * 1e3) : "");
      outcomes.push_back(run_evolution(w, name, label, implicit, step_depth, a.directory));
      out << "  " << label << ": " << format("%.1f s", outcomes.back().seconds)
          << (outcomes.back().surface ? "" : ", gave up") << std::endl;
    }
  }
  report(w, outcomes, out);
  return 0;
}

} // namespace wear::coupling

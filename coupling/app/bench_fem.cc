// `wearsim bench fem`: the FEM workload of one coupled stage on the reference convex sample.
//
// Sample: the reference convex geometry (meshes::SampleGeometry defaults) at the requested
// wear-face size. Load: a representative stage-averaged bed load on the wearing faces,
// 5 kPa normal pressure plus 2.5 kPa shear along the flow (+y), as forces per face
// (traction x area). Wear: a stage removing 20 um x n_z^2 per face (flow-like, tips and tops
// most), applied by recession and mesh motion; then the worn surface is remeshed. Every
// phase is timed on its own; the stress solve is timed as setup + assembly + AMG-CG, the
// stress measures apart (percentiles, and the ball average at --stress-radius, by default
// the default case's mean particle radius).
#include "coupling/app/bench_fem.h"

#include "coupling/output/grid_history.h"
#include "coupling/parameters/case_parameters.h"
#include "fem/elasticity.h"
#include "fem/fem_parameters.h"
#include "fem/volume_output.h"
#include "fem/worn_sample.h"
#include "meshes/atomic_file.h"
#include "meshes/sample_generator.h"
#include "meshes/stopwatch.h"

#include <deal.II/base/multithread_info.h>

#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace wear::coupling {

namespace {

double default_stress_radius() {
  const CaseParameters defaults;
  return stress_averaging_radius(defaults);
}

struct BenchFemArguments {
  meshes::SampleGeometry sample; ///< the reference convex sample, at the requested mesh size
  std::vector<unsigned int> degrees{1, 2};
  /// [m] of the ball-averaged stress: the default case's (mean particle radius at s = 4)
  double stress_radius = default_stress_radius();
  std::string directory = "output/bench-fem";
};

BenchFemArguments bench_fem_arguments(const std::vector<std::string>& args) {
  BenchFemArguments a;
  for (std::size_t k = 0; k < args.size(); k += 2) {
    if (k + 1 >= args.size())
      throw std::invalid_argument("wearsim bench fem: option " + args[k] + " needs a value");
    const std::string &f = args[k], &v = args[k + 1];
    if (f == "--mesh-size") {
      a.sample.mesh_size = std::stod(v);
      if (!(a.sample.mesh_size > 0 && a.sample.mesh_size < 0.01))
        throw std::invalid_argument("wearsim bench fem: --mesh-size is in metres, in (0, 0.01)");
    } else if (f == "--degrees") {
      a.degrees.clear();
      for (char c : v)
        if (c == '1' || c == '2')
          a.degrees.push_back(unsigned(c - '0'));
        else if (c != ',')
          throw std::invalid_argument("wearsim bench fem: --degrees takes 1, 2 or 1,2");
    } else if (f == "--stress-radius") {
      a.stress_radius = std::stod(v);
      if (!(a.stress_radius > 0 && a.stress_radius < 0.05))
        throw std::invalid_argument(
            "wearsim bench fem: --stress-radius is in metres, in (0, 0.05)");
    } else if (f == "--output")
      a.directory = v;
    else
      throw std::invalid_argument("wearsim bench fem: unknown option '" + f + "'");
  }
  return a;
}

// The stage's bed load [N] and removed volume [m^3] on every wearing face (module comment).
void bench_stage(const meshes::SurfaceMesh& surface, meshes::FaceField<meshes::Vec3>& load,
                 meshes::FaceField<double>& removed) {
  const auto area = meshes::face_areas(surface);
  const auto normal = meshes::face_normals(surface);
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    if (surface.face_wears(f)) {
      load[f] = (normal[f] * -5e3 + meshes::Vec3{0, 2.5e3, 0}) * area[f];
      removed[f] = 20e-6 * normal[f].z * normal[f].z * area[f];
    }
}

// One stress solve per degree; the stresses of the last one go to the volume fields.
void time_stress(const fem::WornSample& sample, const meshes::FaceField<meshes::Vec3>& load,
                 const std::vector<unsigned int>& degrees, double stress_radius,
                 GridHistory& history, std::ostream& out) {
  for (const auto degree : degrees) {
    fem::ElasticityParameters ep;
    ep.degree = degree;
    ep.averaging_radius = stress_radius;
    fem::ElasticitySolver solver(sample.triangulation(), sample.face_map(), ep);
    const meshes::Stopwatch clock;
    const auto r = solver.run(load);
    out << "stress P" << degree << ": " << r.n_dofs << " DoFs, " << r.iterations
        << " CG iterations, " << clock.seconds() << " s (setup " << r.setup_seconds << ", assemble "
        << r.assemble_seconds << ", solve " << r.solve_seconds << "), von Mises: largest at a "
        << "quadrature point " << r.max_von_mises_qp / 1e3 << " kPa, 99.9th percentile "
        << r.von_mises_p999 / 1e3 << " kPa, largest ball average (radius "
        << ep.averaging_radius * 1e3 << " mm) " << r.max_von_mises_ball / 1e3 << " kPa; measures "
        << r.measures_seconds << " s" << std::endl;
    if (degree == degrees.back())
      history.add_stage(0, 0, fem::volume_grid(sample.triangulation(), &solver));
  }
}

std::string describe(const fem::RemeshReport& r) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(2) << r.n_tetrahedra << " tetrahedra, " << r.seconds
    << " s, "
    << (r.surface_algorithm == 0
            ? std::string("surface kept, volume meshed anew")
            : "surface remeshed (gmsh algorithm " + std::to_string(r.surface_algorithm) + ", " +
                  std::to_string(r.n_patches) + " patches)")
    << ", volume " << std::scientific << std::setprecision(2)
    << r.volume_after / r.volume_before - 1 << " before the restoring offset, surface distance "
    << std::fixed << std::setprecision(3) << r.surface_distance * 1e3 << " mm";
  return o.str();
}

// The wear stage by recession and mesh motion (remeshing if cells go poor), then a remesh
// on request.
void time_wear_and_remesh(fem::WornSample& sample, const meshes::FaceField<double>& removed,
                          std::ostream& out) {
  const auto stage = sample.apply_wear(removed);
  out << "mesh motion: " << stage.increments << " increment(s), " << stage.motion_seconds
      << " s, removed " << stage.removed_volume * 1e9 << " mm^3, mesh volume change "
      << stage.volume_change * 1e9 << " mm^3, min scaled Jacobian " << std::setprecision(4)
      << stage.quality.min_scaled_jacobian << std::setprecision(2) << std::endl;
  if (stage.n_remeshes > 0)
    out << "remesh in the stage (poor cells after motion): " << describe(stage.last_remesh)
        << std::endl;
  const auto rr = sample.remesh();
  out << "remesh on request: " << describe(rr) << std::endl;
}

} // namespace

int run_bench_fem(const std::vector<std::string>& args, std::ostream& out) {
  const BenchFemArguments a = bench_fem_arguments(args);
  const auto& s = a.sample;
  const std::string& dir = a.directory;
  meshes::ensure_directory(dir);
  out << "machine: " << std::thread::hardware_concurrency() << " hardware threads, deal.II "
      << dealii::MultithreadInfo::n_threads() << " threads\n";
  out << "sample: reference convex, wear-face size " << s.mesh_size * 1e3 << " mm, bottom "
      << s.mesh_size_bottom * 1e3 << " mm" << std::endl;
  out << std::fixed << std::setprecision(2);

  meshes::Stopwatch clock;
  const std::string msh = dir + "/sample.msh";
  const auto generated = meshes::generate_sample(s, msh);
  out << "generate: " << generated.n_tetrahedra << " tetrahedra, " << clock.seconds() << " s"
      << std::endl;
  clock.restart();
  fem::WornSample sample(msh, generated.surface,
                         fem::worn_sample_parameters(fem::FemParameters{}, s, dir));
  out << "read + face map: " << clock.seconds() << " s" << std::endl;

  const auto& surface = sample.surface();
  meshes::FaceField<meshes::Vec3> load("force", "N", meshes::Extensivity::extensive, surface);
  meshes::FaceField<double> removed("removed volume", "m^3", meshes::Extensivity::extensive,
                                    surface);
  bench_stage(surface, load, removed);
  GridHistory history(dir);
  time_stress(sample, load, a.degrees, a.stress_radius, history, out);
  time_wear_and_remesh(sample, removed, out);
  history.add_stage(1, 1, fem::volume_grid(sample.triangulation()));
  out << "volume fields: " << history.xdmf_path() << "\n";
  return 0;
}

} // namespace wear::coupling

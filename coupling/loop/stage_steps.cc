// The FEM steps of a staged stage (stage_steps.h).
//
// Stress: F_f = I_f / T on every surface face f, I_f the window's traction impulse (the
// integral over f of the coarse-grained traction, or f's own impulse), T the window; the
// elastic solve clamps the part's clamped faces (fem/elasticity.h) and reports the von Mises
// stress ball-averaged at each face's centroid, which the stress-informed wear law reads: a
// cell's own value grows with refinement under the particles' contacts.
// Geometry: fem::WornSample::apply_wear (volume-exact recession, mesh motion, remeshing);
// the stage's extensive removed volume and intensive stress follow the faces, conservatively
// per label across a remesh (meshes::FaceTransfer).
#include "coupling/loop/stage_steps.h"

#include "coupling/output/worn_stage_file.h"

#include "fem/volume_output.h"
#include "meshes/face_transfer.h"
#include "meshes/stopwatch.h"

namespace wear::coupling {

StageStress solve_stage_stress(const fem::WornSample& sample, const dem::WallLoads& loads,
                               const fem::ElasticityParameters& ep, RunOutput& output,
                               StageRecord& r) {
  meshes::Stopwatch clock;
  const auto& surface = sample.surface();
  meshes::FaceField<meshes::Vec3> forces("force", "N", meshes::Extensivity::extensive, surface);
  const double T = loads.duration;
  for (std::size_t f = 0; f < surface.n_faces() && T > 0; ++f) {
    forces[f] = loads.traction_impulse[f] / T;
    // The contacts' own loads on the wear faces, whichever way the FEM's traction is laid.
    if (surface.face_wears(f)) {
      r.wear_face_force_z += loads.impulse[f].z / T;
      r.wear_face_normal_force += loads.normal_impulse[f] / T;
    }
  }
  r.mean_force_z = forces.sum().z;
  fem::ElasticitySolver solver(sample.triangulation(), sample.face_map(), ep);
  const auto result = solver.run(forces);
  r.max_von_mises_ball = result.max_von_mises_ball;
  r.von_mises_p99 = result.von_mises_p99;
  r.von_mises_p999 = result.von_mises_p999;
  r.max_von_mises_qp = result.max_von_mises_qp;
  r.stress_averaging_radius = ep.averaging_radius;
  r.safety_factor = result.safety_factor;
  r.max_displacement = result.max_displacement;
  StageStress stress{
      meshes::FaceField<double>("von Mises", "Pa", meshes::Extensivity::intensive, surface)};
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    stress.von_mises[f] = result.face_von_mises_ball[f];
  r.fem_solve_seconds = clock.seconds();
  clock.restart();
  const auto grid = fem::volume_grid(sample.triangulation(), &solver);
  r.volume_points = int(grid.points.size());
  r.volume_cells = int(grid.connectivity.size() / 4);
  output.add_volume(r.stage, r.time, grid);
  r.output_seconds += clock.seconds();
  return stress;
}

GeometryUpdate apply_stage_wear(fem::WornSample& sample, const WearIncrement& increment,
                                const StageStress& stress, StageRecord& r) {
  const meshes::SurfaceMesh before = sample.surface();
  // A stage whose wear the sample cannot take leaves its surface and wear in a file beside
  // the meshes, the workload that repeats the failure (`wearsim bench evolution --state`).
  const fem::WornSampleState start = sample.state();
  fem::WearStageReport applied;
  try {
    applied = sample.apply_wear(increment.removed);
  } catch (const std::exception& e) {
    const std::string path =
        sample.parameters().mesh_directory + "/failed-stage-" + std::to_string(r.stage) + ".h5";
    try {
      write_worn_stage(path, start, increment.removed.values());
    } catch (const std::exception& w) {
      throw std::runtime_error(std::string(e.what()) + " (its stage file not written: " + w.what() +
                               ")");
    }
    throw std::runtime_error(std::string(e.what()) + "; the stage's surface and wear are in '" +
                             path + "' (wearsim bench evolution --state " + path + ")");
  }
  GeometryUpdate update{increment.removed, stress.von_mises, applied};
  const auto& report = update.report;
  r.geometry_volume_change = report.volume_change;
  r.increments = report.increments;
  r.n_remeshes = report.n_remeshes;
  r.n_first_attempt_remeshes = report.n_first_attempt_remeshes;
  r.total_remeshes = sample.n_remeshes();
  r.spread_volume = report.spread_volume;
  r.worn_through_volume = report.worn_through_volume;
  r.n_worn_through = report.n_worn_through;
  r.min_scaled_jacobian = report.quality.min_scaled_jacobian;
  r.motion_seconds = report.motion_seconds;
  r.remesh_seconds = report.remesh_seconds;
  const auto& after = sample.surface();
  r.n_tetrahedra = int(sample.triangulation().n_active_cells());
  r.n_surface_faces = int(after.n_faces());
  if (report.n_remeshes > 0) {
    const meshes::FaceTransfer transfer(before, after);
    update.von_mises = transfer.apply(update.von_mises);
    update.applied = transfer.apply(update.applied);
  } else {
    update.von_mises.follow(after);
    update.applied.follow(after);
  }
  return update;
}

void record_increment(const WearIncrement& w, double cumulative_before, const CouplingParameters& p,
                      StageRecord& r) {
  r.amplification = w.amplification;
  r.dem_wear_volume = w.dem_wear_volume;
  r.max_depth = w.depth.max_depth;
  r.max_depth_fraction = w.depth.max_fraction;
  r.mean_stress_factor = w.mean_stress_factor;
  if (r.scheme == Scheme::reference) // its volumes come from the DEM's moved nodes
    return;
  r.cumulative_applied = cumulative_before;
  if (r.scheme == Scheme::staged) {
    r.applied_volume = w.removed.sum();
    r.cumulative_applied += r.applied_volume;
    check_depth_cap(w, p, r.stage);
  }
}

} // namespace wear::coupling

// The coupled DEM-FEM wear loop (model.md section 6), staged per revolution.
//
// One stage (scheme "staged"):
//   1. DEM: N revolutions on the current sample surface; per face the wear-law volume V_f
//      [m^3], the normal impulse and the impulse vector I_f [N s] are summed.
//   2. Wear: removed volume dV_f = A_amp * s(sigma_f) * V_f on the wear faces, with the
//      declared amplification A_amp and, for the stress-informed law, the factor
//      s = 1 + c (sigma_vM,f / sigma_ref)^m from the previous stage's stress (else 1). A
//      stage whose recession depth at a vertex, sum(dV_f) / sum(A_f) over the wear faces
//      around it, exceeds the allowed fraction of the longest edge there is refused before
//      anything changes, or, with adaptive amplification, runs at A_amp x cap / fraction
//      (not below the minimum amplification), which brings that vertex to the cap.
//   3. FEM: elastic stress of the current (pre-update) sample under the stage-averaged face
//      forces F_f = I_f / T_stage (sample frame, clamped bottom).
//   4. Geometry: volume-exact recession of the worn faces, mesh motion, remeshing when the
//      mesh degrades (fem::WornSample); the new surface goes to the DEM with the bed kept,
//      particles the new surface encloses pushed out.
//   5. Output and a checkpoint.
// "dem-only" stages skip 3 and 4; "reference" stages move surface nodes inside the DEM
// (dem::ReferenceDeformation) and stop the run at the first distortion.
//
// Reproducibility: after every stage the run passes through the same capture -> restore
// path as a resumed run (DEM state export/import, worn sample rebuilt from its arrays), so a
// run resumed from any checkpoint repeats the uninterrupted run bit for bit with the same
// thread count.
#include "coupling/coupled_run.h"

#include "fem/elasticity.h"
#include "fem/volume_output.h"
#include "meshes/atomic_file.h"
#include "meshes/face_transfer.h"
#include "meshes/sample_generator.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace wear::coupling {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

template <typename... Args>
std::string format(const char* f, Args... a) {
  char b[512];
  std::snprintf(b, sizeof b, f, a...);
  return b;
}

// The depth the geometry recedes by at each vertex, sum(dV_f) / sum(A_f) over the wear
// faces around it (the area-weighted node recession of meshes/recession), as a fraction of
// the longest edge at the vertex. A per-face depth dV_f / A_f would be noise on small faces.
struct DepthCheck {
  double max_depth = 0;    ///< [m]
  double max_fraction = 0; ///< [-]
  long vertex = -1;        ///< where the fraction is largest
  double depth_there = 0;  ///< [m]
  int label = 0;           ///< a wear label at that vertex
};

DepthCheck vertex_depths(const meshes::SurfaceMesh& m, const std::vector<double>& removed,
                         const std::vector<double>& area) {
  const std::size_t nv = m.n_vertices();
  std::vector<double> volume(nv, 0), around(nv, 0), edge(nv, 0);
  std::vector<int> label(nv, 0);
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    if (!meshes::label::wears(m.face_labels[f]))
      continue;
    const auto& t = m.triangles[f];
    for (int k = 0; k < 3; ++k) {
      volume[t[k]] += removed[f];
      around[t[k]] += area[f];
      label[t[k]] = m.face_labels[f];
      const double e = meshes::norm(m.vertices[t[k]] - m.vertices[t[(k + 1) % 3]]);
      edge[t[k]] = std::max(edge[t[k]], e);
      edge[t[(k + 1) % 3]] = std::max(edge[t[(k + 1) % 3]], e);
    }
  }
  DepthCheck c;
  for (std::size_t v = 0; v < nv; ++v) {
    if (around[v] <= 0)
      continue;
    const double depth = volume[v] / around[v];
    c.max_depth = std::max(c.max_depth, depth);
    if (depth / edge[v] > c.max_fraction) {
      c.max_fraction = depth / edge[v];
      c.vertex = long(v);
      c.depth_there = depth;
      c.label = label[v];
    }
  }
  return c;
}

constexpr double never = std::numeric_limits<double>::infinity();
} // namespace

CoupledRun::CoupledRun(const CaseParameters& p, std::ostream& log, const RunOptions& options)
    : p_(p), log_(log), options_(options) {
  validate(p_.coupling, p_.fem);
  for (const auto& item : parse_schedule(p_.coupling.schedule))
    for (int k = 0; k < item.n_stages; ++k) {
      plan_.push_back(int(item.scheme));
      staged_ |= item.scheme == Scheme::staged;
      reference_ |= item.scheme == Scheme::reference;
    }
  // The reference scheme is the node-moving method inside the DEM, amplified like the others.
  p_.deformation.enabled = reference_;
  p_.deformation.amplification = p_.coupling.amplification;
  parameters_text_ = resolved_parameters(p_);
}

fem::WornSampleParameters CoupledRun::worn_parameters() const {
  fem::WornSampleParameters w;
  w.remesh_min_scaled_jacobian = p_.fem.remesh_min_scaled_jacobian;
  w.worn_through_thickness = p_.fem.worn_through_thickness;
  w.remesh.sizes = p_.geometry.sample;
  w.remesh.feature_angle_deg = p_.fem.feature_angle_deg;
  w.remesh.chord_tolerance = p_.fem.chord_tolerance;
  w.remesh.min_tet_quality = p_.fem.remesh_min_tet_quality;
  w.mesh_directory = p_.output.directory + "/mesh";
  return w;
}

const meshes::SurfaceMesh& CoupledRun::sample_surface() const {
  return sample_ ? sample_->surface() : initial_surface_;
}

void CoupledRun::setup() {
  const std::string& dir = p_.output.directory;
  try {
    meshes::ensure_directory(dir);
    write_resolved_parameters(p_, dir + "/parameters.prm");
  } catch (const std::exception& e) {
    throw std::runtime_error("Output/Directory: cannot write into '" + dir + "' (" + e.what() +
                             ")");
  }
  meshes::SampleGeometry sg = p_.geometry.sample;
  sg.volume_mesh = staged_ && !options_.resume;
  const std::string msh = dir + "/mesh/sample.msh";
  if (sg.volume_mesh)
    meshes::ensure_directory(dir + "/mesh");
  const auto generated = meshes::generate_sample(sg, sg.volume_mesh ? msh : "");
  initial_surface_ = generated.surface;
  log_ << "sample: " << (sg.convex ? "convex" : "plain") << ", " << initial_surface_.n_faces()
       << " surface triangles";
  if (sg.volume_mesh)
    log_ << ", " << generated.n_tetrahedra << " tetrahedra";
  log_ << "; schedule '" << p_.coupling.schedule << "', " << p_.coupling.revolutions_per_stage
       << " revolution(s) per stage, wear amplification " << p_.coupling.amplification << std::endl;
  tester_ = std::make_unique<dem::WearTester>(p_.geometry, p_.dem, p_.wear_law, p_.deformation,
                                              initial_surface_);
  output_ = std::make_unique<RunOutput>(dir);
  if (options_.resume) {
    const Checkpoint c = read_checkpoint(checkpoint_path());
    if (c.parameters != parameters_text_)
      throw std::runtime_error("--resume: the case differs from the one checkpoint '" +
                               checkpoint_path() +
                               "' was written with; resume with the same case file (the run's "
                               "parameters.prm holds it)");
    restore(c);
    output_->reload(stages_);
    log_ << "resumed after stage " << stages_.size() << " of " << plan_.size() << " ("
         << tester_->n_revolutions_done() << " revolutions, t = " << tester_->system().time()
         << " s)" << std::endl;
    return;
  }
  if (staged_)
    sample_ = std::make_unique<fem::WornSample>(msh, initial_surface_, worn_parameters());
  const bool live = options_.progress && ::isatty(STDERR_FILENO);
  const auto fill = tester_->fill_and_settle([&](const dem::TesterProgress& pr) {
    if (live)
      std::fprintf(stderr, "\rsettling %5.1f %%  t = %.3f s  %.2e particle-steps/s   ",
                   100 * pr.fraction, pr.time, pr.particle_steps_per_second);
  });
  if (live)
    std::fprintf(stderr, "\n");
  char line[256];
  std::snprintf(line, sizeof line,
                "bed: %zu particles, height %.4f m, packing %.3f; time step %.3e s, %llu steps "
                "per revolution, %d threads\n",
                fill.n_particles, fill.bed_height, fill.packing_fraction,
                tester_->system().time_step(),
                static_cast<unsigned long long>(tester_->steps_per_revolution()),
                tester_->system().n_threads());
  log_ << line << std::flush;
  const std::size_t nf = sample_surface().n_faces();
  face_von_mises_.assign(nf, 0);
  dem_cumulative_.assign(nf, 0);
  const std::vector<double> zero(nf, 0);
  output_->add_surface(0, tester_->system().time(), sample_surface(),
                       {{"cumulative removed volume", 1, zero}, {"wear depth", 1, zero}});
  output_->write_tables({}, {}, tester_->evaluation().n_columns(),
                        tester_->evaluation().element_labels());
  checkpoint();
}

void CoupledRun::run() {
  setup();
  log_ << "stage scheme     revs   wear[mm^3]  applied[mm^3]  change[mm^3]  remesh  min-SJ   "
          "max-vM[MPa]  pushed  by[mm]  time[s]\n";
  int done_now = 0;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = stages_.size(); k < plan_.size(); ++k) {
    if (done_now > 0)
      stage_wall_ = seconds_since(start) / done_now;
    StageRecord r;
    r.stage = int(k) + 1;
    r.scheme = plan_[k];
    r.amplification = p_.coupling.amplification;
    run_dem(r);
    const auto removed = compute_wear(r);
    if (Scheme(r.scheme) == Scheme::staged) {
      solve_stress(r);
      update_geometry(removed, r);
    }
    output_results(r);
    print_stage(r);
    if (r.worn_through_volume > 0 && !worn_through_reported_) {
      log_ << format("stage %d: the sample is worn through: %d wear faces are within %g mm of "
                     "the clamped bottom (FEM/Worn-through thickness); the %.4g mm^3 asked of "
                     "them is not removed (stages.csv: worn_through_volume_m3)\n",
                     r.stage, r.n_worn_through, p_.fem.worn_through_thickness * 1e3,
                     r.worn_through_volume * 1e9);
      worn_through_reported_ = true;
    }
    if (!r.distortion.empty()) {
      log_ << "the reference method distorted the surface in stage " << r.stage << " ("
           << r.distortion << "); the run stops here, as the reference study's did\n";
      break;
    }
    checkpoint();
    ++done_now;
    if (options_.stop_after > 0 && done_now >= options_.stop_after && k + 1 < plan_.size()) {
      log_ << "stopped after stage " << r.stage << " as asked; continue with --resume\n";
      return;
    }
  }
  print_timing();
  double worn_through = 0;
  for (const auto& s : stages_)
    worn_through += s.worn_through_volume;
  if (worn_through > 0)
    log_ << format("worn through: %.4g mm^3 of the %.4g mm^3 asked was not removed\n",
                   worn_through * 1e9, stages_.back().cumulative_applied * 1e9);
  log_ << "results: " << output_->summary_path() << ", " << output_->stages_path() << ", "
       << output_->xdmf_path() << " (ParaView); plots: /usr/bin/python3 coupling/plot_run.py "
       << p_.output.directory << "\n";
}

void CoupledRun::run_dem(StageRecord& r) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t nf = tester_->sample_mesh().n_faces();
  stage_removed_.assign(nf, 0);
  stage_normal_impulse_.assign(nf, 0);
  stage_impulse_.assign(nf, {});
  const auto& g = p_.geometry;
  const meshes::Vec3 origin = meshes::tester_to_sample({0, 0, 0}, g.sample, g.placement);
  const bool live = options_.progress && ::isatty(STDERR_FILENO);
  r.first_revolution = tester_->n_revolutions_done() + 1;
  const int n_rev = p_.coupling.revolutions_per_stage;
  for (int q = 0; q < n_rev; ++q) {
    const auto& rec = tester_->run_revolution([&](const dem::TesterProgress& pr) {
      if (!live)
        return;
      // Time left: this stage's DEM from its rate so far, later stages at the mean wall time
      // of the stages finished in this invocation (or this stage's DEM estimate before one).
      const double dem_left =
          ((n_rev - q) - pr.fraction) * double(tester_->steps_per_revolution()) *
          double(tester_->system().particles.n_real) / std::max(1.0, pr.particle_steps_per_second);
      const double per_stage = stage_wall_ > 0
                                   ? stage_wall_
                                   : dem_left / std::max(1e-9, 1.0 - (q + pr.fraction) / n_rev);
      const double left = dem_left + per_stage * double(plan_.size() - std::size_t(r.stage));
      std::fprintf(stderr,
                   "\rstage %d/%zu %s: revolution %d (%d of %d) %5.1f %%  %.2e particle-steps/s  "
                   "time left %.0f min   ",
                   r.stage, plan_.size(), scheme_name(Scheme(r.scheme)).c_str(), pr.revolution,
                   q + 1, n_rev, 100 * pr.fraction, pr.particle_steps_per_second, left / 60);
    });
    const auto& wi = tester_->last_integrals();
    const auto& removed = tester_->last_removed_volume();
    for (std::size_t f = 0; f < nf; ++f) {
      stage_removed_[f] += removed[f];
      stage_normal_impulse_[f] += wi.normal_impulse[f];
      stage_impulse_[f] += meshes::tester_to_sample(wi.impulse[f], g.sample, g.placement) - origin;
    }
    if (Scheme(r.scheme) == Scheme::reference) { // the records are cumulative
      const auto& history = tester_->evaluation().history();
      const dem::RevolutionRecord* before =
          r.first_revolution > 1 ? &history[std::size_t(r.first_revolution - 2)] : nullptr;
      r.applied_volume = rec.applied_volume - (before ? before->applied_volume : 0);
      r.cumulative_applied = rec.applied_volume;
      r.geometry_volume_change =
          rec.enclosed_volume_loss - (before ? before->enclosed_volume_loss : 0);
      r.distortion = rec.distortion;
    }
  }
  if (live)
    std::fprintf(stderr, "\r%*s\r", 100, "");
  r.last_revolution = tester_->n_revolutions_done();
  r.time = tester_->system().time();
  r.dem_seconds = seconds_since(t0);
}

meshes::FaceField<double> CoupledRun::compute_wear(StageRecord& r) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto& surface = sample_surface();
  const std::size_t nf = surface.n_faces();
  if (stage_removed_.size() != nf)
    throw std::logic_error("coupled run: DEM and sample surfaces have different faces");
  const auto area = meshes::face_areas(surface);
  const auto& law = p_.coupling.stress_informed;
  meshes::FaceField<double> removed("removed volume", "m^3", meshes::Extensivity::extensive,
                                    surface);
  double factor_area = 0, wear_area = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    if (!meshes::label::wears(surface.face_labels[f]))
      continue;
    const double s = law.factor(face_von_mises_.empty() ? 0 : face_von_mises_[f]);
    removed[f] = r.amplification * s * stage_removed_[f];
    r.dem_wear_volume += stage_removed_[f];
    factor_area += s * area[f];
    wear_area += area[f];
  }
  DepthCheck depth = vertex_depths(surface, removed.values(), area);
  // The depth is linear in the amplification, so the stage that brings the deepest vertex to
  // the cap is this one scaled by cap / fraction (the factor just below it, so rounding in the
  // recomputed check cannot exceed the cap).
  const double cap = p_.coupling.max_depth_fraction;
  if (Scheme(r.scheme) == Scheme::staged && p_.coupling.adaptive_amplification &&
      depth.max_fraction > cap &&
      r.amplification * cap / depth.max_fraction >= p_.coupling.min_amplification) {
    const double scale = cap / depth.max_fraction * (1 - 1e-9);
    log_ << format("stage %d: amplification %g -> %.4g: at %g it would recede vertex %ld (%s) "
                   "by %.3g mm, %.3g of its longest edge (Maximum depth fraction %g)\n",
                   r.stage, r.amplification, r.amplification * scale, r.amplification, depth.vertex,
                   meshes::label::name(depth.label).c_str(), 1e3 * depth.depth_there,
                   depth.max_fraction, cap);
    r.amplification *= scale;
    for (std::size_t f = 0; f < nf; ++f)
      removed[f] *= scale;
    depth = vertex_depths(surface, removed.values(), area);
  }
  r.max_depth = depth.max_depth;
  r.max_depth_fraction = depth.max_fraction;
  r.mean_stress_factor = wear_area > 0 ? factor_area / wear_area : 1;
  stage_applied_ = removed;
  if (Scheme(r.scheme) == Scheme::staged) {
    r.applied_volume = removed.sum();
    r.cumulative_applied =
        (stages_.empty() ? 0 : stages_.back().cumulative_applied) + r.applied_volume;
    if (r.max_depth_fraction > cap)
      throw std::runtime_error(
          "stage " + std::to_string(r.stage) + " would recede the surface by " +
          format("%.4g", 1e3 * depth.depth_there) + " mm at vertex " +
          std::to_string(depth.vertex) + " (" + meshes::label::name(depth.label) + "), " +
          format("%.3g", r.max_depth_fraction) +
          " of its longest edge; Coupling/Maximum depth fraction allows " + format("%.3g", cap) +
          ". Lower Coupling/Amplification (now " + format("%g", r.amplification) +
          ") or Coupling/Revolutions per stage, raise Coupling/Maximum depth fraction (up to "
          "10: the wear stage then splits itself where the surface would fold), or set "
          "Coupling/Adaptive amplification (a stage would need " +
          format("%.3g", r.amplification * cap / r.max_depth_fraction) +
          "; Coupling/Minimum amplification is " + format("%g", p_.coupling.min_amplification) +
          "); a finer mesh raises the fraction");
  } else if (Scheme(r.scheme) == Scheme::dem_only && !sample_) {
    for (std::size_t f = 0; f < nf; ++f)
      dem_cumulative_[f] += removed[f];
  }
  r.wear_seconds = seconds_since(t0);
  return removed;
}

void CoupledRun::solve_stress(StageRecord& r) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto& surface = sample_->surface();
  const double stage_time = p_.coupling.revolutions_per_stage * tester_->revolution_time();
  meshes::FaceField<meshes::Vec3> forces("force", "N", meshes::Extensivity::extensive, surface);
  for (std::size_t f = 0; f < surface.n_faces(); ++f) {
    forces[f] = stage_impulse_[f] / stage_time;
    if (meshes::label::wears(surface.face_labels[f])) {
      r.wear_face_force_z += forces[f].z;
      r.wear_face_normal_force += stage_normal_impulse_[f] / stage_time;
    }
  }
  r.mean_force_z = forces.sum().z;
  fem::ElasticitySolver solver(sample_->triangulation(), sample_->face_map(), p_.fem.elasticity);
  const auto result = solver.run(forces);
  r.max_von_mises = result.max_von_mises;
  r.safety_factor = result.safety_factor;
  r.max_displacement = result.max_displacement;
  const auto& map = sample_->face_map();
  stage_von_mises_.assign(surface.n_faces(), 0);
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    stage_von_mises_[f] = solver.von_mises()[map[f].cell->active_cell_index()];
  r.fem_solve_seconds = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  const auto grid = fem::volume_grid(sample_->triangulation(), &solver);
  r.volume_points = int(grid.points.size());
  r.volume_cells = int(grid.connectivity.size() / 4);
  output_->add_volume(r.stage, r.time, grid);
  r.output_seconds += seconds_since(t1);
}

void CoupledRun::update_geometry(const meshes::FaceField<double>& removed, StageRecord& r) {
  const meshes::SurfaceMesh before = sample_->surface();
  const auto report = sample_->apply_wear(removed);
  r.geometry_volume_change = report.volume_change;
  r.increments = report.increments;
  r.n_remeshes = report.n_remeshes;
  r.total_remeshes = sample_->n_remeshes();
  r.spread_volume = report.spread_volume;
  r.worn_through_volume = report.worn_through_volume;
  r.n_worn_through = report.n_worn_through;
  r.min_scaled_jacobian = report.quality.min_scaled_jacobian;
  r.motion_seconds = report.motion_seconds;
  r.remesh_seconds = report.remesh_seconds;
  if (report.n_relaxation_halvings > 0)
    log_ << "stage " << r.stage << ": the surface relaxation was halved "
         << report.n_relaxation_halvings
         << " time(s) (alone it folded the surface or removed the whole increment)\n";
  if (report.n_held_restorations > 0)
    log_ << "stage " << r.stage << ": after " << report.n_held_restorations
         << " remesh(es) the volume-restoring offset would have folded the surface and was held "
            "still around the fold\n";
  if (report.volume_not_restored != 0)
    log_ << "stage " << r.stage
         << format(": %.3g mm^3 of chord volume not given back after remeshing (the restoring "
                   "offset folded or fell short)\n",
                   report.volume_not_restored * 1e9);
  for (const auto& refusal : report.remesh_refusals)
    log_ << "stage " << r.stage << ": a remesh needed more than one attempt; refused:" << refusal
         << '\n';
  const auto& after = sample_->surface();
  r.n_tetrahedra = int(sample_->triangulation().n_active_cells());
  r.n_surface_faces = int(after.n_faces());
  // This stage's stress, and what was removed, onto the faces of the new surface.
  meshes::FaceField<double> vm("von Mises", "Pa", meshes::Extensivity::intensive, before);
  vm.values() = stage_von_mises_;
  meshes::FaceField<double> applied = stage_applied_;
  if (report.n_remeshes > 0) {
    const meshes::FaceTransfer transfer(before, after);
    vm = transfer.apply(vm);
    applied = transfer.apply(applied);
  } else {
    vm.follow(after);
    applied.follow(after);
  }
  face_von_mises_ = vm.values();
  stage_applied_ = applied;
  dem_cumulative_.assign(after.n_faces(), 0); // used only by runs without a FEM sample
  const auto pushed = tester_->set_sample_surface(after, p_.coupling.push_tolerance);
  r.n_pushed = pushed.n_pushed;
  r.max_push = pushed.max_distance;
}

void CoupledRun::output_results(StageRecord& r) {
  const auto t0 = std::chrono::steady_clock::now();
  meshes::SurfaceMesh surface = sample_surface();
  if (Scheme(r.scheme) == Scheme::reference) { // the DEM's moved nodes, back in the sample frame
    const auto& g = p_.geometry;
    const auto& moved = tester_->sample_mesh();
    for (std::size_t v = 0; v < surface.n_vertices(); ++v)
      surface.vertices[v] = meshes::tester_to_sample(moved.vertices[v], g.sample, g.placement);
  }
  const auto area = meshes::face_areas(surface);
  std::vector<double> cumulative;
  if (Scheme(r.scheme) == Scheme::reference) { // the declared (amplified) volume
    cumulative = tester_->cumulative_removed_volume();
    for (auto& v : cumulative)
      v *= r.amplification;
  } else
    cumulative = sample_ ? sample_->removed_volume().values() : dem_cumulative_;
  std::vector<double> depth(surface.n_faces()), stage(stage_applied_.values());
  if (sample_)
    depth = sample_->wear_depth().values();
  else
    for (std::size_t f = 0; f < depth.size(); ++f)
      depth[f] = cumulative[f] / area[f];
  std::vector<meshes::VtuArray> fields{{"cumulative removed volume", 1, cumulative},
                                       {"wear depth", 1, depth},
                                       {"stage removed volume", 1, stage}};
  if (Scheme(r.scheme) == Scheme::staged)
    fields.push_back({"von Mises", 1, face_von_mises_});
  output_->add_surface(r.stage, r.time, surface, fields);
  if (!sample_)
    r.n_surface_faces = int(surface.n_faces());
  r.output_seconds += seconds_since(t0);
  stages_.push_back(r);
  output_->write_tables(tester_->evaluation().history(), stages_, tester_->evaluation().n_columns(),
                        tester_->evaluation().element_labels());
}

void CoupledRun::checkpoint() {
  if (reference_)
    return; // the node-moving method's state is not checkpointed; it runs in one go
  Checkpoint c;
  c.stages_done = int(stages_.size());
  c.parameters = parameters_text_;
  c.dem = tester_->system().export_state();
  c.revolutions_done = tester_->n_revolutions_done();
  c.revolutions = tester_->evaluation().history();
  c.has_sample = sample_ != nullptr;
  if (sample_)
    c.sample = sample_->state();
  c.face_von_mises = face_von_mises_;
  c.dem_cumulative = dem_cumulative_;
  c.stages = stages_;
  if (p_.coupling.checkpoints)
    write_checkpoint(checkpoint_path(), c);
  restore(c);
}

void CoupledRun::restore(const Checkpoint& c) {
  stages_ = c.stages;
  face_von_mises_ = c.face_von_mises;
  dem_cumulative_ = c.dem_cumulative;
  if (c.has_sample) {
    sample_ = std::make_unique<fem::WornSample>(c.sample, worn_parameters());
    tester_->set_sample_surface(sample_->surface(), never);
  }
  if (face_von_mises_.size() != sample_surface().n_faces() ||
      dem_cumulative_.size() != sample_surface().n_faces())
    throw std::runtime_error("checkpoint: per-face fields do not match the sample surface");
  tester_->restore(c.dem, c.revolutions_done, c.revolutions);
}

void CoupledRun::print_stage(const StageRecord& r) const {
  char line[256];
  std::snprintf(line, sizeof line,
                "%5d %-9s %3d-%-3d %11.4f %14.4f %13.4f %7d %7.3f %12.3f %7d %8.3f %8.1f%s\n",
                r.stage, scheme_name(Scheme(r.scheme)).c_str(), r.first_revolution,
                r.last_revolution, r.dem_wear_volume * 1e9, r.applied_volume * 1e9,
                r.geometry_volume_change * 1e9, r.n_remeshes, r.min_scaled_jacobian,
                r.max_von_mises * 1e-6, r.n_pushed, r.max_push * 1e3,
                r.dem_seconds + r.wear_seconds + r.fem_solve_seconds + r.motion_seconds +
                    r.remesh_seconds + r.output_seconds,
                r.distortion.empty() ? "" : "  DISTORTED");
  log_ << line << std::flush;
}

void CoupledRun::print_timing() const {
  double t[6] = {0, 0, 0, 0, 0, 0};
  for (const auto& r : stages_) {
    t[0] += r.dem_seconds, t[1] += r.wear_seconds, t[2] += r.fem_solve_seconds;
    t[3] += r.motion_seconds, t[4] += r.remesh_seconds, t[5] += r.output_seconds;
  }
  const char* names[6] = {"DEM", "wear", "FEM solve", "mesh motion", "remesh", "output"};
  double total = 0;
  for (double x : t)
    total += x;
  log_ << "time per phase over all stages:\n";
  char line[128];
  for (int k = 0; k < 6; ++k) {
    std::snprintf(line, sizeof line, "  %-12s %10.1f s  %5.1f %%\n", names[k], t[k],
                  total > 0 ? 100 * t[k] / total : 0.0);
    log_ << line;
  }
  std::snprintf(line, sizeof line, "  %-12s %10.1f s\n", "total", total);
  log_ << line;
}

int run_run_command(const std::vector<std::string>& args, std::ostream& log) {
  RunOptions options;
  std::string case_file;
  for (const auto& a : args) {
    if (a == "--resume")
      options.resume = true;
    else if (a.rfind("--", 0) == 0)
      throw std::invalid_argument("wearsim run: unknown option '" + a + "'");
    else if (case_file.empty())
      case_file = a;
    else
      throw std::invalid_argument("wearsim run: expected one case file, got '" + case_file +
                                  "' and '" + a + "'");
  }
  if (case_file.empty())
    throw std::invalid_argument("wearsim run: expected a case file: wearsim run [--resume] "
                                "<case.prm>");
  CoupledRun run(read_case(case_file), log, options);
  run.run();
  return 0;
}

} // namespace wear::coupling

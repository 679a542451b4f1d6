// The coupled DEM-FEM wear loop, staged per revolution (docs/coupling.md).
//
// One stage (scheme "staged"):
//   1. DEM: N revolutions on the current sample surface; the window's loads per face (impulse
//      I_f [N s], normal impulse, Archard load-distance, sliding work, contact-steps and the
//      wear law's volume V_f [m^3]) summed over them, in the sample frame.
//   2. Wear: the removed volume dV_f = A s(sigma_f) V_f on the wear faces (wear_increment.h:
//      amplification, stress-informed factor from the previous stage's stress, vertex depth
//      cap, adaptive amplification).
//   3. FEM: elastic stress of the current (pre-update) sample under the stage-averaged face
//      forces F_f = I_f / T_stage (sample frame, clamped bottom), I_f the integral over face
//      f of the coarse-grained traction (DEM/Wall traction; else f's own impulse).
//   4. Geometry: volume-exact recession of the worn faces, mesh motion, remeshing when the
//      mesh degrades (fem::WornSample); the new surface goes to the DEM with the bed kept,
//      particles the new surface encloses pushed out; the stage's stress and removed volume
//      carried onto the new faces (FaceTransfer after a remesh, else the same faces).
//   5. Output and a checkpoint.
// "dem-only" stages skip 3 and 4; "reference" stages move surface nodes inside the DEM
// (dem::ReferenceDeformation) and stop the run at the first distortion.
//
// Reproducibility: after every stage the run passes through the same capture -> restore
// path as a resumed run (DEM state export/import, worn sample rebuilt from its arrays), so a
// run resumed from any checkpoint repeats the uninterrupted run bit for bit with the same
// thread count.
//
// Over MPI ranks (RunOptions::ranks) every rank runs this same loop: the DEM over the ranks
// (its loads are sums over them, the same bits everywhere), steps 2 to 4 on every rank on its
// own copy of the sample (checked to give every rank the same surface bit for bit), output and
// messages on rank 0. Stops are agreed over the ranks, so every rank stops on the same step;
// a checkpoint gathers the ranks' DEM parts to rank 0, and a resume on another rank count
// takes them merged (docs/coupling.md, "Over MPI ranks").
#include "coupling/loop/coupled_run.h"

#include "coupling/output/progress_line.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace wear::coupling {

void RunTotals::add(const StageRecord& r) {
  cumulative_applied = r.cumulative_applied;
  worn_through += r.worn_through_volume;
  ++n_stages_run;
  stage_seconds = clock.seconds();
}

void RunTotals::add_dem_wear(const meshes::FaceField<double>& removed) {
  if (removed.revision() != dem_wear.revision() || removed.size() != dem_wear.size())
    throw std::logic_error("coupled run: a stage's removed volume is not on the faces of the "
                           "DEM-only cumulative wear");
  for (std::size_t f = 0; f < removed.size(); ++f)
    dem_wear[f] += removed[f];
}

double RunTotals::mean_stage_seconds() const {
  return n_stages_run > 0 ? stage_seconds / n_stages_run : 0;
}

int CoupledRun::run() {
  const StopSignals signals;
  std::optional<OpenStage> open = setup();
  print_header();
  totals_.n_stages_run = 0;
  totals_.clock.restart();
  for (std::size_t k = stages_.size(); k < plan_.size(); ++k) {
    StageRecord r = begin_stage(k, open);
    const std::optional<dem::WallLoads> loads = run_dem(r, std::exchange(open, {}), signals);
    if (!loads)
      return stopped_by(ranks_.agreed_signal(signals), r, true);
    const WearIncrement increment = compute_wear(*loads, r);
    meshes::FaceField<double> applied = increment.removed;
    if (r.scheme == Scheme::dem_only && !sample_)
      totals_.add_dem_wear(increment.removed);
    if (r.scheme == Scheme::staged) {
      const StageStress stress = solve_stress(*loads, r);
      GeometryUpdate update = update_geometry(increment, stress, r);
      applied = std::move(update.applied);
      previous_stress_ = std::move(update.von_mises);
    }
    record(r, applied);
    if (!r.distortion.empty()) {
      log_ << "the reference method distorted the surface in stage " << r.stage << " ("
           << r.distortion << "); the run stops here, as the reference study's did\n";
      break;
    }
    checkpoint();
    const int signal = ranks_.agreed_signal(signals);
    if (signal != 0 && k + 1 < plan_.size()) // came during the FEM part
      return stopped_by(signal, r, false);
    if (options_.stop_after > 0 && totals_.n_stages_run >= options_.stop_after &&
        k + 1 < plan_.size()) {
      log_ << "stopped after stage " << r.stage << " as asked; continue with --resume\n";
      return 0;
    }
  }
  print_end();
  return 0;
}

StageRecord CoupledRun::begin_stage(std::size_t k, const std::optional<OpenStage>& open) const {
  StageRecord r;
  r.stage = int(k) + 1;
  r.scheme = plan_[k];
  r.amplification = p_.coupling.amplification;
  r.first_revolution = tester_->n_revolutions_done() + 1 - (open ? open->revolutions_done : 0);
  return r;
}

// The stage's revolutions; their loads, turned from the tester's frame into the sample's
// (vectors rotated only), summed on the current sample surface. Between two steps the run
// may checkpoint itself (every Output/Checkpoint interval) or stop (a signal); an open stage
// from a checkpoint continues where it stood.
std::optional<dem::WallLoads> CoupledRun::run_dem(StageRecord& r, std::optional<OpenStage> open,
                                                  const StopSignals& signals) {
  const meshes::Stopwatch clock;
  const auto& surface = sample_surface();
  dem::WallLoads loads = open ? loads_of(*open, surface) : dem::WallLoads::zero(surface);
  const double seconds_before = open ? open->dem_seconds : 0;
  const auto to_sample = [this](const meshes::Vec3& v) { return frame_.vector_to_sample(v); };
  // The node-moving method's state is not checkpointed (checkpoint() explains).
  const bool can_checkpoint = p_.coupling.checkpoints && !has_reference_;
  const double interval = p_.output.checkpoint_interval;
  meshes::Stopwatch since_checkpoint;
  ProgressLine line(options_.progress);
  const int n_rev = p_.coupling.revolutions_per_stage;
  for (int q = open ? open->revolutions_done : 0; q < n_rev; ++q) {
    // Over ranks every rank stops and checkpoints on the same step: a signal to any rank
    // stops all, and rank 0's clock times the checkpoints.
    const auto stop = [&] {
      double v[2] = {double(signals.requested()), writer() && can_checkpoint && interval > 0 &&
                                                          since_checkpoint.seconds() >= interval
                                                      ? 1.0
                                                      : 0.0};
      if (options_.ranks)
        options_.ranks->max_over_ranks(v, 2);
      if (v[0] != 0)
        return true;
      if (v[1] != 0) {
        checkpoint_inside(loads, q, seconds_before + clock.seconds());
        since_checkpoint.restart();
      }
      return false;
    };
    const auto show = [&](const dem::TesterProgress& pr) { line.show(progress_text(r, pr, q)); };
    if (!tester_->advance_revolution(show, stop)) {
      line.clear();
      if (can_checkpoint)
        checkpoint_inside(loads, q, seconds_before + clock.seconds());
      return std::nullopt;
    }
    const auto& rec = tester_->evaluation().history().back();
    loads += tester_->last_loads().follow(surface, to_sample);
    if (r.scheme == Scheme::reference) { // the records are cumulative
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
  line.clear();
  r.last_revolution = tester_->n_revolutions_done();
  r.time = tester_->system().time();
  r.dem_seconds = seconds_before + clock.seconds();
  return loads;
}

// Time left: this stage's DEM from its rate so far, later stages at the mean wall time of
// the stages finished in this invocation (or this stage's DEM estimate before one).
std::string CoupledRun::progress_text(const StageRecord& r, const dem::TesterProgress& pr,
                                      int q) const {
  const int n_rev = p_.coupling.revolutions_per_stage;
  const double dem_left = ((n_rev - q) - pr.fraction) * double(tester_->steps_per_revolution()) *
                          double(tester_->n_particles()) /
                          std::max(1.0, pr.particle_steps_per_second);
  const double mean = totals_.mean_stage_seconds();
  const double per_stage =
      mean > 0 ? mean : dem_left / std::max(1e-9, 1.0 - (q + pr.fraction) / n_rev);
  const double left = dem_left + per_stage * double(plan_.size() - std::size_t(r.stage));
  return format("stage %d/%zu %s: revolution %d (%d of %d) %5.1f %%  %.2e particle-steps/s  "
                "time left %.0f min   ",
                r.stage, plan_.size(), scheme_name(r.scheme).c_str(), pr.revolution, q + 1, n_rev,
                100 * pr.fraction, pr.particle_steps_per_second, left / 60);
}

WearIncrement CoupledRun::compute_wear(const dem::WallLoads& loads, StageRecord& r) {
  const meshes::Stopwatch clock;
  const bool staged = r.scheme == Scheme::staged;
  const WearIncrement w =
      wear_increment(sample_surface(), loads.wear_volume, previous_stress_, p_.coupling, staged);
  if (w.lowered)
    log_ << format("stage %d: amplification %g -> %.4g: at %g it would recede vertex %ld (%s) "
                   "by %.3g mm, %.3g of its longest edge (Maximum depth fraction %g)\n",
                   r.stage, w.declared_amplification, w.amplification, w.declared_amplification,
                   w.declared_depth.vertex, meshes::label::name(w.declared_depth.label).c_str(),
                   1e3 * w.declared_depth.depth_there, w.declared_depth.max_fraction,
                   p_.coupling.max_depth_fraction);
  record_increment(w, totals_.cumulative_applied, p_.coupling, r);
  r.wear_seconds = clock.seconds();
  return w;
}

StageStress CoupledRun::solve_stress(const dem::WallLoads& loads, StageRecord& r) {
  fem::ElasticityParameters ep = p_.fem.elasticity;
  ep.averaging_radius = stress_averaging_radius(p_);
  ep.holder_support = p_.geometry.tester.holder;
  return solve_stage_stress(*sample_, loads, ep, *output_, r);
}

GeometryUpdate CoupledRun::update_geometry(const WearIncrement& increment,
                                           const StageStress& stress, StageRecord& r) {
  GeometryUpdate update = apply_stage_wear(*sample_, increment, stress, r);
  ranks_.require_same(sample_->surface(),
                      "the sample surfaces after the FEM part of stage " + std::to_string(r.stage));
  print_geometry_notes(r, update.report);
  const auto pushed = tester_->set_sample_surface(sample_->surface(), p_.coupling.push_tolerance);
  r.n_pushed = pushed.n_pushed;
  r.max_push = pushed.max_distance;
  return update;
}

// The surface the stage ends on, in the sample frame: for the reference scheme the DEM's
// moved nodes brought back from the tester frame.
meshes::SurfaceMesh CoupledRun::stage_surface(Scheme scheme) const {
  return scheme == Scheme::reference ? frame_.place_in_sample(tester_->sample_mesh())
                                     : sample_surface();
}

void CoupledRun::record(StageRecord r, const meshes::FaceField<double>& applied) {
  const meshes::Stopwatch clock;
  const meshes::SurfaceMesh surface = stage_surface(r.scheme);
  const auto area = meshes::face_areas(surface);
  std::vector<double> cumulative;
  if (r.scheme == Scheme::reference) { // the declared (amplified) volume
    cumulative = tester_->cumulative_removed_volume();
    for (auto& v : cumulative)
      v *= r.amplification;
  } else
    cumulative = sample_ ? sample_->removed_volume().values() : totals_.dem_wear.values();
  std::vector<double> depth(surface.n_faces());
  if (sample_)
    depth = sample_->wear_depth().values();
  else
    for (std::size_t f = 0; f < depth.size(); ++f)
      depth[f] = cumulative[f] / area[f];
  std::vector<meshes::VtuArray> fields{{"cumulative removed volume", 1, cumulative},
                                       {"wear depth", 1, depth},
                                       {"stage removed volume", 1, applied.values()}};
  if (r.scheme == Scheme::staged)
    fields.push_back({"von Mises", 1, previous_stress_.values()});
  output_->add_surface(r.stage, r.time, surface, fields);
  if (!sample_)
    r.n_surface_faces = int(surface.n_faces());
  r.output_seconds += clock.seconds();
  const bool first_worn_through = r.worn_through_volume > 0 && totals_.worn_through == 0;
  stages_.push_back(r);
  totals_.add(r);
  output_->write_tables(tester_->evaluation().history(), stages_, tester_->evaluation().n_columns(),
                        tester_->evaluation().element_labels());
  print_stage(r);
  if (first_worn_through)
    log_ << format("stage %d: the sample is worn through: %d wear faces are within %g mm of "
                   "the clamped bottom (FEM/Worn-through thickness); the %.4g mm^3 asked of "
                   "them is not removed (stages.csv: worn_through_volume_m3)\n",
                   r.stage, r.n_worn_through, p_.fem.worn_sample.worn_through_thickness * 1e3,
                   r.worn_through_volume * 1e9);
}

} // namespace wear::coupling

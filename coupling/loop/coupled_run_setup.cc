// The coupled run's set-up, checkpoints and messages (the loop itself: coupled_run.cc).
//
// Set-up: the output folder checked (a folder holding a run is refused unless --resume, or
// --overwrite moves that run aside and deletes it after the new run's first checkpoint), the
// resolved parameters written, the sample generated (with its volume mesh when a stage is
// staged), the DEM tester around it; then either a resume from checkpoint.h5 (or the one
// before it when it does not read; refused when the case differs) or the bed filled and
// settled, the initial surface written and a first checkpoint. A checkpoint is written and
// read straight back after every stage, so an uninterrupted run follows the same path as a
// resumed one. An in-stage checkpoint is only written: the DEM state it holds continues
// exactly (System::resume_state), so writing it changes nothing.
#include "coupling/loop/coupled_run.h"

#include "coupling/output/progress_line.h"
#include "dem/engine/rank_states.h"
#include "meshes/atomic_file.h"
#include "meshes/sample_generator.h"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace wear::coupling {

namespace {
constexpr double never = std::numeric_limits<double>::infinity();

meshes::FaceField<double> zero_stress(const meshes::SurfaceMesh& surface) {
  return {"von Mises", "Pa", meshes::Extensivity::intensive, surface};
}

// A folder holds a run once a run has written its tables or a checkpoint there.
bool holds_run(const std::string& dir) {
  for (const char* f : {"stages.csv", "summary.csv", "checkpoint.h5", "checkpoint.previous.h5"})
    if (std::filesystem::exists(dir + "/" + f))
      return true;
  return false;
}
} // namespace

CoupledRun::CoupledRun(const CaseParameters& p, std::ostream& log, const RunOptions& options)
    : p_(p), log_(options.ranks && options.ranks->rank() != 0 ? silent_ : log), options_(options),
      ranks_(options.ranks), frame_(p.geometry.sample, p.geometry.placement) {
  options_.progress = options_.progress && writer();
  validate(p_.coupling, p_.fem);
  if (!(p_.output.checkpoint_interval >= 0))
    throw std::invalid_argument("Output/Checkpoint interval: must be 0 (none) or positive [s]");
  if (options_.resume && options_.overwrite)
    throw std::invalid_argument("wearsim run: --resume continues the run in the output folder "
                                "and --overwrite replaces it; give one of them");
  for (const auto& item : parse_schedule(p_.coupling.schedule))
    for (int k = 0; k < item.n_stages; ++k) {
      plan_.push_back(item.scheme);
      has_staged_ |= item.scheme == Scheme::staged;
      has_reference_ |= item.scheme == Scheme::reference;
    }
  if (has_reference_ && options_.ranks && options_.ranks->n_ranks() > 1)
    throw std::invalid_argument("Coupling/Schedule: the reference scheme (nodes moved inside the "
                                "DEM) runs as one process, not over " +
                                std::to_string(options_.ranks->n_ranks()) + " ranks");
  // The reference scheme is the node-moving method inside the DEM, amplified like the others.
  p_.deformation.enabled = has_reference_;
  p_.deformation.amplification = p_.coupling.amplification;
  parameters_text_ = resolved_parameters(p_);
}

fem::WornSampleParameters CoupledRun::worn_parameters() const {
  return fem::worn_sample_parameters(p_.fem, p_.geometry.sample, mesh_directory());
}

std::string CoupledRun::mesh_directory() const {
  return writer() ? p_.output.directory + "/mesh" : ranks_.scratch();
}

const meshes::SurfaceMesh& CoupledRun::sample_surface() const {
  return sample_ ? sample_->surface() : initial_surface_;
}

std::optional<OpenStage> CoupledRun::setup() {
  std::string replaced;
  if (writer())
    replaced = prepare_output_folder();
  ranks_.wait_for_folder(); // rank 0 has the folder ready before any rank goes on
  initial_surface_ = generate_initial_surface();
  ranks_.require_same(initial_surface_, "the sample surfaces as generated");
  tester_ = std::make_unique<dem::WearTester>(p_.geometry, p_.dem, p_.wear_law, p_.deformation,
                                              initial_surface_);
  tester_->set_rank_link(options_.ranks);
  if (options_.ranks && options_.ranks->n_ranks() > 1)
    log_ << tester_->rank_layout()
         << "; rank 0 writes, every rank runs the FEM stage on its own copy of the sample"
         << std::endl;
  output_ = std::make_unique<RunOutput>(p_.output.directory, writer());
  if (options_.resume)
    return resume();
  if (has_staged_)
    sample_ = std::make_unique<fem::WornSample>(mesh_directory() + "/sample.msh", initial_surface_,
                                                worn_parameters());
  fill_and_settle();
  previous_stress_ = zero_stress(sample_surface());
  totals_.dem_wear = meshes::FaceField<double>("wear-law volume", "m^3",
                                               meshes::Extensivity::extensive, sample_surface());
  const std::vector<double> zero(sample_surface().n_faces(), 0);
  output_->add_surface(0, tester_->system().time(), sample_surface(),
                       {{"cumulative removed volume", 1, zero}, {"wear depth", 1, zero}});
  output_->write_tables({}, {}, tester_->evaluation().n_columns(),
                        tester_->evaluation().element_labels());
  checkpoint();
  if (!replaced.empty()) {
    std::filesystem::remove_all(replaced);
    log_ << "the replaced run in '" << replaced << "' is deleted (this run has its first "
         << "checkpoint)" << std::endl;
  }
  return std::nullopt;
}

std::string CoupledRun::prepare_output_folder() const {
  return prepare_run_folder(p_, options_, log_);
}

std::string prepare_run_folder(const CaseParameters& p, const RunOptions& options,
                               std::ostream& log) {
  const std::string& dir = p.output.directory;
  std::string aside;
  if (!options.resume && holds_run(dir)) {
    if (!options.overwrite)
      throw std::runtime_error(
          "Output/Directory: '" + dir +
          "' holds a run (stages.csv or a checkpoint); continue "
          "it with --resume, replace it with --overwrite, or set another Output/Directory");
    aside = dir + ".replaced";
    if (std::filesystem::exists(aside))
      throw std::runtime_error("--overwrite: '" + aside +
                               "' already holds a run an earlier "
                               "--overwrite moved aside and could not delete; look at it and "
                               "remove it first");
    std::error_code ec;
    std::filesystem::rename(dir, aside, ec);
    if (ec)
      throw std::runtime_error("--overwrite: cannot move the run in '" + dir + "' to '" + aside +
                               "' (" + ec.message() + ")");
    log << "the run in '" << dir << "' is moved to '" << aside
        << "'; it is deleted when this run has written its first checkpoint" << std::endl;
  }
  try {
    meshes::ensure_directory(dir);
    write_resolved_parameters(p, dir + "/parameters.prm");
  } catch (const std::exception& e) {
    throw std::runtime_error("Output/Directory: cannot write into '" + dir + "' (" + e.what() +
                             ")");
  }
  return aside;
}

// The volume mesh is generated only for a new run with staged stages; a resumed run takes
// its worn sample from the checkpoint.
meshes::SurfaceMesh CoupledRun::generate_initial_surface() const {
  meshes::SampleGeometry sg = p_.geometry.sample;
  sg.volume_mesh = has_staged_ && !options_.resume;
  const std::string msh = mesh_directory() + "/sample.msh";
  if (sg.volume_mesh)
    meshes::ensure_directory(mesh_directory());
  const auto generated = meshes::generate_sample(sg, sg.volume_mesh ? msh : "");
  log_ << "sample: " << (sg.convex ? "convex" : "plain") << ", " << generated.surface.n_faces()
       << " surface triangles";
  if (sg.volume_mesh)
    log_ << ", " << generated.n_tetrahedra << " tetrahedra";
  log_ << "; schedule '" << p_.coupling.schedule << "', " << p_.coupling.revolutions_per_stage
       << " revolution(s) per stage, wear amplification " << p_.coupling.amplification << std::endl;
  return generated.surface;
}

std::optional<OpenStage> CoupledRun::resume() {
  const DemPart part = ranks_.dem_part();
  const Checkpoint c = read_latest_checkpoint(checkpoint_path(), log_, part);
  require_same_case(c, parameters_text_, checkpoint_path());
  if (c.dem_ranks != part.n_ranks)
    log_ << "the checkpoint was written on " << c.dem_ranks << " rank(s), this run has "
         << part.n_ranks << ": the bed is decomposed again (it continues, not bit for bit as "
         << "on " << c.dem_ranks << ")" << std::endl;
  restore(c);
  output_->reload(stages_);
  log_ << "resumed after stage " << stages_.size() << " of " << plan_.size();
  if (c.open_stage)
    log_ << format(", inside stage %zu at revolution %d, %.1f %% of it", stages_.size() + 1,
                   tester_->n_revolutions_done() + 1,
                   100.0 * double(c.open_stage->revolution.steps_done) /
                       double(tester_->steps_per_revolution()));
  log_ << " (" << tester_->n_revolutions_done() << " revolutions, t = " << tester_->system().time()
       << " s)" << std::endl;
  return c.open_stage;
}

void CoupledRun::fill_and_settle() {
  ProgressLine line(options_.progress);
  const auto fill = tester_->fill_and_settle([&](const dem::TesterProgress& pr) {
    line.show(format("settling %5.1f %%  t = %.3f s  %.2e particle-steps/s   ", 100 * pr.fraction,
                     pr.time, pr.particle_steps_per_second));
  });
  line.keep();
  log_ << format("bed: %zu particles, height %.4f m, packing %.3f; time step %.3e s, %llu steps "
                 "per revolution, %d threads\n",
                 fill.n_particles, fill.bed_height, fill.packing_fraction,
                 tester_->system().time_step(),
                 static_cast<unsigned long long>(tester_->steps_per_revolution()),
                 tester_->system().n_threads())
       << std::flush;
}

Checkpoint CoupledRun::capture() const {
  Checkpoint c;
  c.stages_done = int(stages_.size());
  c.parameters = parameters_text_;
  c.dem = tester_->system().export_state();
  c.revolutions_done = tester_->n_revolutions_done();
  c.revolutions = tester_->evaluation().history();
  c.has_sample = sample_ != nullptr;
  if (sample_)
    c.sample = sample_->state();
  c.face_von_mises = previous_stress_.values();
  // Only a run without a FEM sample accumulates wear-law volume on a fixed surface.
  c.dem_cumulative =
      sample_ ? std::vector<double>(sample_surface().n_faces(), 0) : totals_.dem_wear.values();
  c.stages = stages_;
  return c;
}

void CoupledRun::checkpoint() {
  if (has_reference_)
    return; // the node-moving method's state is not checkpointed; it runs in one go
  const Checkpoint c = capture();
  if (p_.coupling.checkpoints)
    ranks_.write(checkpoint_path(), c);
  restore(c);
}

void CoupledRun::checkpoint_inside(const dem::WallLoads& loads, int revolutions_done,
                                   double dem_seconds) const {
  const auto revolution = tester_->open_revolution();
  if (!revolution)
    throw std::logic_error("CoupledRun: an in-stage checkpoint outside a revolution");
  Checkpoint c = capture();
  c.open_stage = open_stage(loads, revolutions_done, dem_seconds, *revolution);
  ranks_.write(checkpoint_path(), c);
}

void CoupledRun::restore(const Checkpoint& c) {
  stages_ = c.stages;
  if (c.has_sample) {
    sample_ = std::make_unique<fem::WornSample>(c.sample, worn_parameters());
    tester_->set_sample_surface(sample_->surface(), never);
  }
  const auto& surface = sample_surface();
  if (c.face_von_mises.size() != surface.n_faces() || c.dem_cumulative.size() != surface.n_faces())
    throw std::runtime_error("checkpoint: per-face fields do not match the sample surface");
  previous_stress_ = zero_stress(surface);
  previous_stress_.values() = c.face_von_mises;
  totals_.dem_wear =
      meshes::FaceField<double>("wear-law volume", "m^3", meshes::Extensivity::extensive, surface);
  totals_.dem_wear.values() = c.dem_cumulative;
  totals_.cumulative_applied = stages_.empty() ? 0 : stages_.back().cumulative_applied;
  totals_.worn_through = 0;
  for (const auto& s : stages_)
    totals_.worn_through += s.worn_through_volume;
  if (c.open_stage)
    tester_->restore(c.dem, c.revolutions_done, c.revolutions, c.open_stage->revolution);
  else
    tester_->restore(c.dem, c.revolutions_done, c.revolutions);
}

int CoupledRun::stopped_by(int signal, const StageRecord& r, bool inside) const {
  const bool saved = p_.coupling.checkpoints && !has_reference_;
  log_ << "stopped by " << StopSignals::name(signal)
       << format(inside ? " in stage %d of %zu (revolution %d, t = %.6g s); "
                        : " after stage %d of %zu (revolution %d done, t = %.6g s); ",
                 r.stage, plan_.size(), tester_->n_revolutions_done() + (inside ? 1 : 0),
                 tester_->system().time());
  if (saved)
    log_ << "checkpoint written to '" << checkpoint_path()
         << "'; continue with: wearsim run --resume <case.prm>" << std::endl;
  else
    log_ << "nothing was saved ("
         << (has_reference_ ? "the reference scheme is not checkpointed"
                            : "Coupling/Checkpoints is false")
         << "); the run must start again" << std::endl;
  return 128 + signal;
}

void CoupledRun::print_header() const {
  log_ << "stage scheme     revs   wear[mm^3]  applied[mm^3]  change[mm^3]  remesh  min-SJ   "
          "ball-vM[MPa]  pushed  by[mm]  time[s]\n";
}

void CoupledRun::print_stage(const StageRecord& r) const {
  log_ << format("%5d %-9s %3d-%-3d %11.4f %14.4f %13.4f %7d %7.3f %12.3f %7d %8.3f %8.1f%s\n",
                 r.stage, scheme_name(r.scheme).c_str(), r.first_revolution, r.last_revolution,
                 r.dem_wear_volume * 1e9, r.applied_volume * 1e9, r.geometry_volume_change * 1e9,
                 r.n_remeshes, r.min_scaled_jacobian, r.max_von_mises_ball * 1e-6, r.n_pushed,
                 r.max_push * 1e3,
                 r.dem_seconds + r.wear_seconds + r.fem_solve_seconds + r.motion_seconds +
                     r.remesh_seconds + r.output_seconds,
                 r.distortion.empty() ? "" : "  DISTORTED")
       << std::flush;
}

void CoupledRun::print_geometry_notes(const StageRecord& r,
                                      const fem::WearStageReport& report) const {
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
}

void CoupledRun::print_end() const {
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
  for (int k = 0; k < 6; ++k)
    log_ << format("  %-12s %10.1f s  %5.1f %%\n", names[k], t[k],
                   total > 0 ? 100 * t[k] / total : 0.0);
  log_ << format("  %-12s %10.1f s\n", "total", total);
  int n_remeshes = 0, n_first = 0;
  for (const auto& r : stages_)
    n_remeshes += r.n_remeshes, n_first += r.n_first_attempt_remeshes;
  if (n_remeshes > 0)
    log_ << format("remeshes: %d, %d of them (%.0f %%) at gmsh's first attempt\n", n_remeshes,
                   n_first, 100.0 * n_first / n_remeshes);
  if (totals_.worn_through > 0)
    log_ << format("worn through: %.4g mm^3 of the %.4g mm^3 asked was not removed\n",
                   totals_.worn_through * 1e9, totals_.cumulative_applied * 1e9);
  log_ << "results: " << output_->summary_path() << ", " << output_->stages_path() << ", "
       << output_->xdmf_path()
       << " (ParaView); plots: /usr/bin/python3 coupling/output/plot_run.py " << p_.output.directory
       << "\n";
}

} // namespace wear::coupling

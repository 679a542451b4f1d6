// A scene's run (scene_coupled_run.h): its DEM, and the staged wear loop on its wearing part.
//
// Set-up: the scene's walls are built (dem/scene/scene_walls.h), the wearing wall's CAD
// surfaces labelled by role (S<n> wearing, S<n>-free, S<n>-clamped); gmsh meshes the volume
// they enclose into tetrahedra (fem::remesh_sample, uniform size = the wall's Mesh size; the
// tester's sample (Source = sample) is the tester's own mesh, meshes::generate_sample moved to
// its placement, remeshed later at its own graded sizes, its labels and roles kept) and
// the DEM wall takes that mesh's boundary, so DEM faces and FEM boundary faces are the same
// triangles and every per-face field crosses without interpolation.
// One stage (scheme "staged"), in the part's own frame (a moving part's body frame):
//   1. DEM: Scene/Stage duration in windows of Output interval, a record each; the windows'
//      loads on the part (impulse, Archard, wear-law volume V_f per face) summed.
//   2. Wear: dV_f = A s(sigma_f) V_f on the wearing faces (wear_increment.h).
//   3. FEM: stress under F_f = I_f / T, the clamped surfaces held (stage_steps.h).
//   4. Geometry: recession, mesh motion or remeshing (fem::WornSample); the new surface to
//      the DEM wall, the particles kept (the part only recedes from them).
//   5. Output: the part's surface and volume with their fields (HDF5 + XDMF, VTU), stages.csv,
//      part_wear.csv (volume per surface, per stage and cumulative); a checkpoint.
// "dem-only" stages skip 3 and 4. Without stages the run is one DEM stage to End time.
// Checkpoints are taken between two windows, where the engine is between two steps: the
// engine's state with its continuation, the inlets' generators, the outlets' and flux planes'
// counts, the worn part and the open stage's summed loads; a resumed run repeats the
// uninterrupted one bit for bit with the same thread count. A scene that has not yet set up its
// engine (no particle so far) has nothing to lose and is not checkpointed.
// Assumption: the tester's worn-through check (a clamped bottom below the wear face) does not
// apply to a part; a part worn through folds its surface and the stage stops with the fold
// message.
#include "coupling/loop/scene_coupled_run.h"

#include "coupling/output/progress_line.h"
#include "fem/remesher.h"
#include "meshes/atomic_file.h"
#include "meshes/sample_frame.h"
#include "meshes/sample_generator.h"
#include "meshes/stopwatch.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace wear::coupling {

namespace {

std::size_t wearing_wall(const dem::SceneParameters& scene) {
  std::vector<std::size_t> wearing;
  std::string names;
  for (std::size_t k = 0; k < scene.walls.size(); ++k)
    if (scene.walls[k].wears) {
      wearing.push_back(k);
      names += (names.empty() ? "" : ", ") + scene.walls[k].name;
    }
  if (wearing.empty())
    throw std::invalid_argument("Scene/Stage duration: a wear loop needs a wearing part; set "
                                "Wears = true in the subsection of the wall that wears");
  if (wearing.size() > 1)
    throw std::invalid_argument("Scene/Stage duration: a wear loop takes one wearing part; "
                                "walls " +
                                names + " wear");
  return wearing.front();
}

/// The part's remeshing and mesh sizes: the wall's Mesh size everywhere (equal top and
/// bottom sizes make the sample's graded size field uniform, whatever its thickness). The
/// tester's sample keeps its own sizes and grading (Geometry/Sample), measured along its up
/// direction from its bottom's plane where Geometry/Placement puts it.
fem::WornSampleParameters part_parameters(const CaseParameters& p,
                                          const dem::SceneWallParameters& wall) {
  const std::string dir = p.output.directory + "/mesh";
  if (wall.source == "sample") {
    fem::WornSampleParameters w = fem::worn_sample_parameters(p.fem, p.geometry.sample, dir);
    const meshes::SampleFrame frame(p.geometry.sample, p.geometry.placement);
    w.remesh.up = frame.vector_to_tester({0, 0, 1});
    w.remesh.up_offset = meshes::dot(w.remesh.up, frame.point_to_tester({0, 0, 0}));
    return w;
  }
  meshes::SampleGeometry sizes;
  sizes.mesh_size = sizes.mesh_size_bottom = wall.mesh_size;
  sizes.thickness = wall.mesh_size;
  sizes.curvature_refinement = false;
  return fem::worn_sample_parameters(p.fem, sizes, dir);
}

const char* part_wear_header =
    "stage,scheme,time_s,label,stage_volume_m3,cumulative_removed_volume_m3\n";

} // namespace

SceneCoupledRun::SceneCoupledRun(const CaseParameters& p, std::ostream& log,
                                 const RunOptions& options)
    : p_(p), log_(log), options_(options), parameters_text_(resolved_parameters(p)) {
  dem::validate(p_.scene);
  if (p_.scene.stage_duration <= 0) { // one DEM stage to End time
    plan_ = {Scheme::dem_only};
    return;
  }
  validate(p_.coupling, p_.fem);
  part_wall_ = wearing_wall(p_.scene);
  const auto& wall = p_.scene.walls[*part_wall_];
  if (wall.source != "sample" && // the tester's sample is clamped at its bottom
      dem::surface_numbers(wall.clamped_surfaces, dem::scene_wall_path(wall)).empty())
    throw std::invalid_argument(dem::scene_wall_path(wall) +
                                "/Clamped surfaces: the wearing part needs at least one clamped "
                                "surface (held fixed in the FEM; without one it would float)");
  for (const auto& item : parse_schedule(p_.coupling.schedule)) {
    if (item.scheme == Scheme::reference)
      throw std::invalid_argument("Coupling/Schedule: the reference (node-moving) scheme runs "
                                  "on the built-in tester only; a scene's stages are staged or "
                                  "dem-only");
    plan_.insert(plan_.end(), std::size_t(item.n_stages), item.scheme);
  }
  law_ = dem::make_wear_law(p_.wear_law);
}

int SceneCoupledRun::run() {
  const StopSignals signals;
  std::optional<OpenSceneStage> open = setup();
  int n_run = 0;
  for (std::size_t k = stages_.size(); k < plan_.size(); ++k) {
    StageRecord r = begin_stage(k);
    const std::optional<dem::WallLoads> loads = run_dem(r, std::exchange(open, {}), signals);
    if (!loads) {
      log_ << "stopped by " << StopSignals::name(signals.requested()) << " inside stage " << r.stage
           << " at t = " << scene_->time() << " s";
      if (scene_->system().n_rebuilds() > 0 && p_.coupling.checkpoints)
        log_ << " after a checkpoint; continue with wearsim scene-run --resume " << p_.case_file
             << "\n";
      else // nothing was checkpointed: no particle yet, or checkpoints off
        log_ << " without a checkpoint (no particle yet, or Coupling/Checkpoints off); run it "
                "again with --overwrite\n";
      return 128 + signals.requested();
    }
    if (part_) {
      const WearIncrement increment = compute_wear(*loads, r);
      meshes::FaceField<double> applied = increment.removed;
      if (r.scheme == Scheme::staged) {
        const StageStress stress = solve_stress(*loads, r);
        GeometryUpdate update = update_geometry(increment, stress, r);
        applied = std::move(update.applied);
        previous_stress_ = std::move(update.von_mises);
      }
      record(r, applied);
    }
    checkpoint({zero_loads(), scene_->time() + p_.scene.stage_duration});
    if (options_.stop_after > 0 && ++n_run >= options_.stop_after && k + 1 < plan_.size()) {
      log_ << "stopped after stage " << r.stage << " as asked; continue with --resume\n";
      return 0;
    }
  }
  log_ << "written to " << p_.output.directory << "/ (scene_series.csv, scene_wear.csv, "
       << "particles_<k>.vtu, walls/"
       << (part_ ? ", stages.csv, part_wear.csv, surface.xdmf and volume.xdmf" : "")
       << (scene_->fields() ? ", fields.xdmf" : "") << ")\n";
  return 0;
}

std::vector<dem::SceneWall> SceneCoupledRun::scene_walls() const {
  std::vector<dem::SceneWall> walls = dem::build_scene_walls(p_.scene, p_.geometry);
  if (part_)
    walls[*part_wall_].surface.mesh = part_->surface();
  return walls;
}

std::optional<SceneCoupledRun::OpenSceneStage> SceneCoupledRun::setup() {
  const std::string replaced = prepare_run_folder(p_, options_, log_);
  if (options_.resume)
    return resume();
  const std::string& dir = p_.output.directory;
  std::vector<dem::SceneWall> walls = dem::build_scene_walls(p_.scene, p_.geometry);
  if (part_wall_) {
    auto& wall = walls[*part_wall_];
    const auto worn = part_parameters(p_, wall.parameters);
    meshes::ensure_directory(dir + "/mesh");
    const meshes::Stopwatch clock;
    const std::string msh = dir + "/mesh/part.msh";
    std::size_t n_tetrahedra = 0;
    meshes::SurfaceMesh surface;
    if (wall.parameters.source == "sample") { // the tester's own mesh, placed (as CoupledRun)
      meshes::SampleGeometry sg = p_.geometry.sample;
      sg.volume_mesh = true;
      const auto g = meshes::generate_sample(sg, msh, &p_.geometry.placement);
      surface = g.surface;
      n_tetrahedra = g.n_tetrahedra;
    } else {
      fem::RemeshReport report;
      surface = fem::remesh_sample(wall.surface.mesh, worn.remesh, msh, &report);
      n_tetrahedra = report.n_tetrahedra;
    }
    part_ = std::make_unique<fem::WornSample>(msh, surface, worn);
    wall.surface.mesh = surface;
    std::string labels;
    for (const auto& [label, area] : meshes::area_per_label(surface))
      labels += " " + meshes::label::name(label);
    log_ << format("part '%s': %zu tetrahedra, %zu surface faces, %.6g mm^3, surfaces%s (%.1f "
                   "s)\n",
                   wall.parameters.name.c_str(), n_tetrahedra, surface.n_faces(),
                   meshes::enclosed_volume(surface) * 1e9, labels.c_str(), clock.seconds());
    previous_stress_ =
        meshes::FaceField<double>("von Mises", "Pa", meshes::Extensivity::intensive, surface);
  }
  scene_ = std::make_unique<dem::SceneRun>(p_.scene, p_.dem, std::move(walls));
  scene_->setup([&](const std::string& text) { log_ << "scene: " << text << "\n" << std::flush; });
  log_ << "scene: " << scene_->walls().size() << " walls, " << scene_->inlets().size()
       << " inlets, " << scene_->outlets().size() << " outlets; batches and outlets every "
       << scene_->exchange_interval() << " s; " << plan_.size() << " stage(s) of "
       << (part_ ? p_.scene.stage_duration : p_.scene.end_time) << " s\n";
  series_ = std::make_unique<SceneSeries>(dir, *scene_);
  if (part_) {
    output_ = std::make_unique<RunOutput>(dir);
    const std::vector<double> zero(part_->surface().n_faces(), 0);
    output_->add_surface(0, scene_->time(), part_->surface(),
                         {{"cumulative removed volume", 1, zero}, {"wear depth", 1, zero}});
  }
  replaced_ = replaced;
  return std::nullopt;
}

std::optional<SceneCoupledRun::OpenSceneStage> SceneCoupledRun::resume() {
  const Checkpoint c = read_latest_checkpoint(checkpoint_path(), log_);
  require_same_case(c, parameters_text_, checkpoint_path());
  if (!c.scene || !c.open_stage)
    throw std::runtime_error("--resume: checkpoint '" + checkpoint_path() +
                             "' is not a scene run's (a `wearsim run` checkpoint?)");
  const auto& s = *c.scene;
  stages_ = c.stages;
  if (part_wall_) {
    if (!c.has_sample)
      throw std::runtime_error("--resume: checkpoint '" + checkpoint_path() +
                               "' holds no worn part");
    const auto& wall = p_.scene.walls[*part_wall_];
    part_ = std::make_unique<fem::WornSample>(c.sample, part_parameters(p_, wall));
    previous_stress_ = meshes::FaceField<double>("von Mises", "Pa", meshes::Extensivity::intensive,
                                                 part_->surface());
    for (std::size_t f = 0; f < c.face_von_mises.size(); ++f)
      previous_stress_[f] = c.face_von_mises[f];
    for (std::size_t k = 0; k < s.labels.size(); ++k)
      removed_per_label_[s.labels[k]] = s.removed_per_label[k];
  }
  scene_ = std::make_unique<dem::SceneRun>(p_.scene, p_.dem, scene_walls());
  dem::SceneRunState state{s.time,   true,          c.dem,           s.n_removed,
                           s.inlets, s.outlet_mass, s.outlet_counts, s.flux_planes};
  scene_->resume(state);
  series_ = std::make_unique<SceneSeries>(p_.output.directory, *scene_, s.n_records);
  if (part_) {
    output_ = std::make_unique<RunOutput>(p_.output.directory);
    output_->reload(stages_);
    // part_wear.csv as it stood after the checkpoint's stages.
    std::ifstream in(p_.output.directory + "/part_wear.csv");
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line))
      if (std::stoi(line.substr(0, line.find(','))) <= int(stages_.size()))
        part_wear_ += line + "\n";
  }
  OpenSceneStage open{zero_loads(), s.stage_end};
  if (part_)
    open.loads = loads_of(*c.open_stage, part_->surface());
  log_ << "resumed after stage " << stages_.size() << " of " << plan_.size() << " at t = " << s.time
       << " s (" << s.n_records << " records)" << std::endl;
  return open;
}

dem::WallLoads SceneCoupledRun::zero_loads() const {
  return dem::WallLoads::zero(part_ ? part_->surface() : meshes::SurfaceMesh{});
}

StageRecord SceneCoupledRun::begin_stage(std::size_t k) const {
  StageRecord r;
  r.stage = int(k) + 1;
  r.scheme = plan_[k];
  r.amplification = p_.coupling.amplification;
  return r;
}

std::optional<dem::WallLoads> SceneCoupledRun::run_dem(StageRecord& r,
                                                       std::optional<OpenSceneStage> open,
                                                       const StopSignals& signals) {
  const meshes::Stopwatch clock;
  OpenSceneStage stage =
      open ? std::move(*open)
           : OpenSceneStage{zero_loads(),
                            part_ ? scene_->time() + p_.scene.stage_duration : p_.scene.end_time};
  const double every = p_.scene.output_interval;
  const double interval = p_.output.checkpoint_interval;
  meshes::Stopwatch since_checkpoint;
  while (scene_->time() < stage.end - 1e-9 * every) {
    const dem::SceneWindow w = scene_->advance(std::min(stage.end, scene_->time() + every));
    if (part_ && w.integrated > 0)
      stage.loads += scene_->wall_loads(*part_wall_, *law_, w.integrated);
    series_->add(w, *scene_);
    if (part_)
      log_ << "stage " << r.stage << "/" << plan_.size() << " " << scheme_name(r.scheme) << ": ";
    log_ << window_summary(w) << "\n" << std::flush;
    const bool more = scene_->time() < stage.end - 1e-9 * every;
    const bool stop = signals.requested() != 0 && more;
    if ((stop || (interval > 0 && since_checkpoint.seconds() >= interval && more)) &&
        scene_->system().n_rebuilds() > 0) {
      checkpoint(stage);
      since_checkpoint.restart();
    }
    if (stop)
      return std::nullopt;
  }
  r.time = scene_->time();
  r.dem_seconds = clock.seconds();
  return std::move(stage.loads);
}

WearIncrement SceneCoupledRun::compute_wear(const dem::WallLoads& loads, StageRecord& r) const {
  const meshes::Stopwatch clock;
  const bool staged = r.scheme == Scheme::staged;
  const WearIncrement w =
      wear_increment(part_->surface(), loads.wear_volume, previous_stress_, p_.coupling, staged);
  record_increment(w, stages_.empty() ? 0.0 : stages_.back().cumulative_applied, p_.coupling, r);
  r.wear_seconds = clock.seconds();
  return w;
}

StageStress SceneCoupledRun::solve_stress(const dem::WallLoads& loads, StageRecord& r) {
  fem::ElasticityParameters ep = p_.fem.elasticity;
  ep.averaging_radius = stress_averaging_radius(p_);
  // A part is held at its clamped surfaces only: the tester's holder support (u . n = 0 on the
  // sides) is set in the sample's own frame, and the scene's FEM works in the scene's.
  ep.holder_support = false;
  return solve_stage_stress(*part_, loads, ep, *output_, r);
}

GeometryUpdate SceneCoupledRun::update_geometry(const WearIncrement& increment,
                                                const StageStress& stress, StageRecord& r) {
  GeometryUpdate update = apply_stage_wear(*part_, increment, stress, r);
  for (const auto& refusal : update.report.remesh_refusals)
    log_ << "stage " << r.stage << ": a remesh needed more than one attempt; refused:" << refusal
         << "\n";
  scene_->replace_wall_surface(*part_wall_, part_->surface());
  return update;
}

void SceneCoupledRun::record(StageRecord r, const meshes::FaceField<double>& applied) {
  const meshes::Stopwatch clock;
  const auto& surface = part_->surface();
  std::map<int, double> stage_per_label;
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    stage_per_label[surface.face_labels[f]] += applied[f];
  std::vector<meshes::VtuArray> fields{
      {"cumulative removed volume", 1, part_->removed_volume().values()},
      {"wear depth", 1, part_->wear_depth().values()},
      {"stage removed volume", 1, applied.values()}};
  if (r.scheme == Scheme::staged)
    fields.push_back({"von Mises", 1, previous_stress_.values()});
  output_->add_surface(r.stage, r.time, surface, fields);
  r.n_surface_faces = int(surface.n_faces());
  r.n_tetrahedra = int(part_->triangulation().n_active_cells());
  r.output_seconds += clock.seconds();
  stages_.push_back(r);
  output_->write_tables({}, stages_, 0, {});
  if (r.scheme == Scheme::staged) // a dem-only stage's volume changes nothing
    for (const auto& [label, v] : stage_per_label)
      removed_per_label_[label] += v;
  std::ostringstream rows;
  rows.precision(10);
  for (const auto& [label, v] : stage_per_label)
    if (meshes::label::wears(label))
      rows << r.stage << "," << scheme_name(r.scheme) << "," << r.time << ","
           << meshes::label::name(label) << "," << v << "," << removed_per_label_[label] << "\n";
  part_wear_ += rows.str();
  meshes::write_atomically(p_.output.directory + "/part_wear.csv",
                           [&](std::ostream& out) { out << part_wear_header << part_wear_; });
  log_ << format("stage %d %s done at t = %.4g s: wear-law volume %.4g mm^3, removed %.4g mm^3 "
                 "(cumulative %.4g), max von Mises (ball) %.3g MPa, %d remeshes, DEM %.0f s, "
                 "FEM %.1f s\n",
                 r.stage, scheme_name(r.scheme).c_str(), r.time, r.dem_wear_volume * 1e9,
                 r.applied_volume * 1e9, r.cumulative_applied * 1e9, r.max_von_mises_ball * 1e-6,
                 r.n_remeshes, r.dem_seconds,
                 r.fem_solve_seconds + r.motion_seconds + r.remesh_seconds)
       << std::flush;
}

void SceneCoupledRun::checkpoint(const OpenSceneStage& open) {
  if (!p_.coupling.checkpoints || scene_->system().n_rebuilds() == 0)
    return;
  const dem::SceneRunState state = scene_->state();
  Checkpoint c;
  c.stages_done = int(stages_.size());
  c.parameters = parameters_text_;
  c.dem = state.system;
  c.has_sample = part_ != nullptr;
  if (part_) {
    c.sample = part_->state();
    c.face_von_mises = previous_stress_.values();
  }
  c.stages = stages_;
  c.open_stage = open_stage(open.loads, 0, 0, {});
  SceneCheckpoint s;
  s.time = state.time;
  s.stage_end = open.end;
  s.n_records = series_->n_records();
  s.n_removed = state.n_removed;
  s.inlets = state.inlets;
  s.outlet_mass = state.outlet_mass;
  s.outlet_counts = state.outlet_counts;
  s.flux_planes = state.flux_planes;
  for (const auto& [label, v] : removed_per_label_) {
    s.labels.push_back(label);
    s.removed_per_label.push_back(v);
  }
  c.scene = s;
  write_checkpoint(checkpoint_path(), c);
  if (!replaced_.empty()) { // the run --overwrite replaced goes once this one can be resumed
    std::filesystem::remove_all(replaced_);
    log_ << "the replaced run in '" << replaced_ << "' is deleted (this run has its first "
         << "checkpoint)" << std::endl;
    replaced_.clear();
  }
}

} // namespace wear::coupling

// The staged wear loop on a scene's wearing part (scene_wear_run.h).
//
// Set-up: the scene's walls are built (dem/scene/scene_walls.h), the wearing wall's CAD
// surfaces labelled by role (S<n> wearing, S<n>-free, S<n>-clamped); gmsh meshes the volume
// they enclose into tetrahedra (fem::remesh_sample, uniform size = the wall's Mesh size) and
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
//      part_wear.csv (removed volume per surface, per stage and cumulative).
// "dem-only" stages skip 3 and 4: the flow settles into its steady state on the new part.
// Assumptions: the part's worn-through check of the tester's sample (a clamped bottom below
// the wear face) does not apply; a part worn through folds its surface and the stage stops
// with the fold message. A scene wear run has no checkpoint yet: a stopped run starts over.
#include "coupling/loop/scene_wear_run.h"

#include "coupling/output/progress_line.h"
#include "fem/remesher.h"
#include "meshes/atomic_file.h"
#include "meshes/stopwatch.h"

#include <algorithm>
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

} // namespace

SceneWearRun::SceneWearRun(const CaseParameters& p, std::ostream& log) : p_(p), log_(log) {
  dem::validate(p_.scene);
  validate(p_.coupling, p_.fem);
  part_wall_ = wearing_wall(p_.scene);
  const auto& wall = p_.scene.walls[part_wall_];
  if (dem::surface_numbers(wall.clamped_surfaces, dem::scene_wall_path(wall)).empty())
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

int SceneWearRun::run() {
  setup();
  previous_stress_ = meshes::FaceField<double>("von Mises", "Pa", meshes::Extensivity::intensive,
                                               part_->surface());
  for (std::size_t k = 0; k < plan_.size(); ++k) {
    StageRecord r = begin_stage(k);
    const dem::WallLoads loads = run_dem(r);
    const WearIncrement increment = compute_wear(loads, r);
    meshes::FaceField<double> applied = increment.removed;
    if (r.scheme == Scheme::staged) {
      const StageStress stress = solve_stress(loads, r);
      GeometryUpdate update = update_geometry(increment, stress, r);
      applied = std::move(update.applied);
      previous_stress_ = std::move(update.von_mises);
    }
    record(r, applied);
  }
  log_ << "written to " << p_.output.directory
       << "/ (stages.csv, part_wear.csv, history.xdmf with surface/ and volume/, the scene's "
          "records)\n";
  return 0;
}

void SceneWearRun::setup() {
  const std::string& dir = p_.output.directory;
  meshes::ensure_directory(dir + "/mesh");
  write_resolved_parameters(p_, dir + "/parameters.prm");
  std::vector<dem::SceneWall> walls = dem::build_scene_walls(p_.scene);
  auto& wall = walls[part_wall_];
  meshes::SampleGeometry sizes;
  sizes.mesh_size = sizes.mesh_size_bottom = wall.parameters.mesh_size;
  const auto box = meshes::bounding_box(wall.surface.mesh);
  sizes.thickness = std::max(box.extent().z, wall.parameters.mesh_size);
  sizes.curvature_refinement = false;
  const auto worn = fem::worn_sample_parameters(p_.fem, sizes, dir + "/mesh");
  fem::RemeshReport report;
  const meshes::Stopwatch clock;
  const meshes::SurfaceMesh surface =
      fem::remesh_sample(wall.surface.mesh, worn.remesh, dir + "/mesh/part.msh", &report);
  part_ = std::make_unique<fem::WornSample>(dir + "/mesh/part.msh", surface, worn);
  wall.surface.mesh = surface;
  std::string labels;
  for (const auto& [label, area] : report.area_after)
    labels += " " + meshes::label::name(label);
  log_ << format("part '%s': %zu tetrahedra, %zu surface faces, %.6g mm^3, surfaces%s (%.1f s)\n",
                 wall.parameters.name.c_str(), report.n_tetrahedra, surface.n_faces(),
                 report.volume_after * 1e9, labels.c_str(), clock.seconds());
  scene_ = std::make_unique<dem::SceneRun>(p_.scene, p_.dem, std::move(walls));
  scene_->setup([&](const std::string& text) { log_ << "scene: " << text << "\n" << std::flush; });
  series_ = std::make_unique<SceneSeries>(dir, *scene_);
  output_ = std::make_unique<RunOutput>(dir);
  const std::vector<double> zero(surface.n_faces(), 0);
  output_->add_surface(0, scene_->time(), surface,
                       {{"cumulative removed volume", 1, zero}, {"wear depth", 1, zero}});
}

StageRecord SceneWearRun::begin_stage(std::size_t k) const {
  StageRecord r;
  r.stage = int(k) + 1;
  r.scheme = plan_[k];
  r.amplification = p_.coupling.amplification;
  return r;
}

dem::WallLoads SceneWearRun::run_dem(StageRecord& r) {
  const meshes::Stopwatch clock;
  dem::WallLoads loads = dem::WallLoads::zero(part_->surface());
  const double end = scene_->time() + p_.scene.stage_duration;
  const double every = p_.scene.output_interval;
  while (scene_->time() < end - 1e-9 * every) {
    const dem::SceneWindow w = scene_->advance(std::min(end, scene_->time() + every));
    if (w.integrated > 0)
      loads += scene_->wall_loads(part_wall_, *law_, w.integrated);
    series_->add(++n_records_, w, *scene_);
    log_ << "stage " << r.stage << "/" << plan_.size() << " " << scheme_name(r.scheme) << ": "
         << window_summary(w) << "\n"
         << std::flush;
  }
  r.time = scene_->time();
  r.dem_seconds = clock.seconds();
  return loads;
}

WearIncrement SceneWearRun::compute_wear(const dem::WallLoads& loads, StageRecord& r) const {
  const meshes::Stopwatch clock;
  const bool staged = r.scheme == Scheme::staged;
  const WearIncrement w =
      wear_increment(part_->surface(), loads.wear_volume, previous_stress_, p_.coupling, staged);
  record_increment(w, stages_.empty() ? 0.0 : stages_.back().cumulative_applied, p_.coupling, r);
  r.wear_seconds = clock.seconds();
  return w;
}

StageStress SceneWearRun::solve_stress(const dem::WallLoads& loads, StageRecord& r) {
  fem::ElasticityParameters ep = p_.fem.elasticity;
  ep.averaging_radius = stress_averaging_radius(p_);
  ep.holder_support = false; // a part is held at its clamped surfaces only
  StageStress stress = solve_stage_stress(*part_, loads, ep, r);
  const meshes::Stopwatch clock;
  output_->add_volume(r.stage, r.time, stress.grid);
  r.output_seconds += clock.seconds();
  return stress;
}

GeometryUpdate SceneWearRun::update_geometry(const WearIncrement& increment,
                                             const StageStress& stress, StageRecord& r) {
  GeometryUpdate update = apply_stage_wear(*part_, increment, stress, r);
  for (const auto& refusal : update.report.remesh_refusals)
    log_ << "stage " << r.stage << ": a remesh needed more than one attempt; refused:" << refusal
         << "\n";
  scene_->replace_wall_surface(part_wall_, part_->surface());
  return update;
}

void SceneWearRun::record(StageRecord r, const meshes::FaceField<double>& applied) {
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
  std::ostringstream table;
  table.precision(10);
  table << "stage,scheme,time_s,label,stage_volume_m3,cumulative_removed_volume_m3\n";
  if (r.scheme == Scheme::staged) // a dem-only stage's volume changes nothing
    for (const auto& [label, v] : stage_per_label)
      removed_per_label_[label] += v;
  rows_ += [&] {
    std::ostringstream s;
    s.precision(10);
    for (const auto& [label, v] : stage_per_label)
      if (meshes::label::wears(label))
        s << r.stage << "," << scheme_name(r.scheme) << "," << r.time << ","
          << meshes::label::name(label) << "," << v << "," << removed_per_label_[label] << "\n";
    return s.str();
  }();
  meshes::write_atomically(p_.output.directory + "/part_wear.csv",
                           [&](std::ostream& out) { out << table.str() << rows_; });
  log_ << format("stage %d %s done at t = %.4g s: wear-law volume %.4g mm^3, removed %.4g mm^3 "
                 "(cumulative %.4g), max von Mises (ball) %.3g MPa, %d remeshes, DEM %.0f s, "
                 "FEM %.1f s\n",
                 r.stage, scheme_name(r.scheme).c_str(), r.time, r.dem_wear_volume * 1e9,
                 r.applied_volume * 1e9, r.cumulative_applied * 1e9, r.max_von_mises_ball * 1e-6,
                 r.n_remeshes, r.dem_seconds,
                 r.fem_solve_seconds + r.motion_seconds + r.remesh_seconds)
       << std::flush;
}

} // namespace wear::coupling

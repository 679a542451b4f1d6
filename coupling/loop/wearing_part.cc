// A scene's wearing part (wearing_part.h): its FEM sample and its side of a stage.
//
// Set-up: gmsh meshes the volume the part's labelled surfaces enclose into tetrahedra
// (fem::remesh_sample, uniform size = the wall's Mesh size); the tester's sample (Source =
// sample) is the tester's own mesh, meshes::generate_sample moved to its placement, remeshed
// later at its own graded sizes, its labels and roles kept.
// One stage, in the part's own frame (a moving part's body frame), under the loads the DEM
// summed on it over the stage's windows:
//   1. Wear: dV_f = A s(sigma_f) V_f on the wearing faces (wear_increment.h).
//   2. FEM (staged): stress under F_f = I_f / T, the clamped surfaces held (stage_steps.h).
//   3. Geometry (staged): recession, mesh motion or remeshing (fem::WornSample).
//   4. Output: the surface and volume with their fields (HDF5 + XDMF, VTU), stages.csv,
//      part_wear.csv (volume per surface, per stage and cumulative).
// A part is held at its clamped surfaces; the tester's sample (Source = sample) works in its own
// frame (its loads' vectors turned into it, its surface placed in the
// scene for the DEM wall), clamped at its bottom and, in a scene with the holder, its sides held
// normal to themselves (u . n = 0) as the holder holds them.
// A part whose wearing faces come within FEM/Worn-through thickness of its clamped surface is
// worn through there: the wear asked of those faces is recorded, not removed, and said once.
#include "coupling/loop/wearing_part.h"

#include "coupling/loop/stage_steps.h"
#include "coupling/loop/wear_increment.h"
#include "coupling/output/text_format.h"
#include "coupling/parameters/engine_version.h"
#include "dem/scene/wall_catalogue.h"
#include "fem/remesher.h"
#include "meshes/atomic_file.h"
#include "meshes/part_life.h"
#include "meshes/sample_frame.h"
#include "meshes/sample_generator.h"
#include "meshes/stopwatch.h"
#include "meshes/vtu_writer.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace wear::coupling {

namespace {

/// The part's remeshing and mesh sizes: the wall's Mesh size everywhere (equal top and
/// bottom sizes make the sample's graded size field uniform, whatever its thickness). The
/// tester's sample keeps its own sizes and grading (Geometry/Sample) in its own frame.
fem::WornSampleParameters part_parameters(const CaseParameters& p,
                                          const dem::SceneWallParameters& wall) {
  const std::string dir = part_directory(p, wall.name) + "/mesh";
  if (dem::wall_source_of(wall).source == dem::WallSource::sample)
    return fem::worn_sample_parameters(p.fem, p.geometry.sample, dir);
  meshes::SampleGeometry sizes;
  sizes.mesh_size = sizes.mesh_size_bottom = wall.mesh_size;
  sizes.thickness = wall.mesh_size;
  sizes.curvature_refinement = false;
  return fem::worn_sample_parameters(p.fem, sizes, dir);
}

/// The tester's sample's own frame (Geometry/Sample placed by Geometry/Placement), where its
/// FEM works; none for any other part (the wall's frame).
std::optional<meshes::SampleFrame> part_frame(const CaseParameters& p,
                                              const dem::SceneWallParameters& wall) {
  if (dem::wall_source_of(wall).source != dem::WallSource::sample)
    return std::nullopt;
  return meshes::SampleFrame(p.geometry.sample, p.geometry.placement);
}

/// The tester's sample rests in its holder when the scene has one (Source = holder): its sides
/// are held (u . n = 0 in the FEM).
bool held_sides(const CaseParameters& p, const dem::SceneWallParameters& wall) {
  return dem::wall_source_of(wall).source == dem::WallSource::sample &&
         std::any_of(p.scene.walls.begin(), p.scene.walls.end(), [](const auto& w) {
           return dem::wall_source_of(w).source == dem::WallSource::holder;
         });
}

const char* part_wear_header =
    "stage,scheme,time_s,label,stage_volume_m3,cumulative_removed_volume_m3\n";
// part_life.csv: per stage, each convex element standing (its height above its foot and its
// volume above it) and the part (its thinnest point above the clamped bottom, its volume).
const char* part_life_header =
    "stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3\n";

/// Revolutions at amplification 1 that the stages stand for: revolutions x amplification of
/// each stage that changes the geometry (a dem-only stage stands for none).
double equivalent_revolutions(const std::vector<StageRecord>& stages, int revolutions_per_stage) {
  double n = 0;
  for (const auto& s : stages)
    if (s.scheme != Scheme::dem_only)
      n += revolutions_per_stage * s.amplification;
  return n;
}

meshes::FaceField<double> von_mises_on(const meshes::SurfaceMesh& surface) {
  return meshes::FaceField<double>("von Mises", "Pa", meshes::Extensivity::intensive, surface);
}

} // namespace

const char* const element_life_header =
    "stage,equivalent_revolutions,equivalent_hours,what,height_m,volume_m3,measured_by\n";

std::string element_life_rows(const std::string& stage_columns,
                              const std::map<int, meshes::ElementStanding>& standing) {
  std::ostringstream rows;
  rows.precision(10);
  for (const auto& [label, e] : standing)
    rows << stage_columns << "," << meshes::label::name(label) << "," << e.height << "," << e.volume
         << "," << engine_version() << "\n";
  return rows.str();
}

meshes::GeneratedSample first_sample_mesh(const CaseParameters& p, const std::string& msh) {
  meshes::SampleGeometry sg = p.geometry.sample;
  sg.volume_mesh = true;
  return meshes::generate_sample(sg, msh);
}

std::string part_directory(const CaseParameters& p, const std::string& name) {
  return p.output.directory + "/parts/" + name;
}

WearingPart::WearingPart(const CaseParameters& p, std::size_t index, dem::SceneWall& wall,
                         std::ostream& log, bool writes)
    : wall_(index), name_(wall.parameters.name), directory_(part_directory(p, name_)),
      frame_(part_frame(p, wall.parameters)), writes_(writes) {
  const auto worn = part_parameters(p, wall.parameters);
  meshes::ensure_directory(directory_ + "/mesh");
  const meshes::Stopwatch clock;
  const std::string msh = directory_ + "/mesh/part.msh";
  std::size_t n_tetrahedra = 0;
  meshes::SurfaceMesh surface;
  if (frame_) { // the tester's sample, in its own frame
    const auto g = first_sample_mesh(p, msh);
    const auto& sg = p.geometry.sample;
    if (const auto warning = meshes::element_volume_warning(meshes::element_volume(g, sg), sg);
        !warning.empty())
      log << "warning: part '" << name_ << "': " << warning << "\n";
    surface = g.surface;
    surface.roles = meshes::sample_roles(held_sides(p, wall.parameters));
    n_tetrahedra = g.n_tetrahedra;
  } else {
    fem::RemeshReport report;
    surface = fem::remesh_sample(wall.surface.mesh, worn.remesh, msh, &report);
    n_tetrahedra = report.n_tetrahedra;
  }
  if (worn_out_criterion(p.coupling.worn_out_when) == WornOutCriterion::elements_gone &&
      meshes::convex_element_standing(surface).empty())
    throw std::invalid_argument("Coupling/Worn out when = elements gone: part '" + name_ +
                                "' has no convex elements to wear away");
  footprints_ = meshes::element_footprints(surface);
  sample_ = std::make_unique<fem::WornSample>(msh, surface, worn);
  wall.surface.mesh = wall_surface();
  std::string labels;
  for (const auto& [label, area] : meshes::area_per_label(surface))
    labels += " " + meshes::label::name(label);
  log << format("part '%s': %zu tetrahedra, %zu surface faces, %.6g mm^3, surfaces%s (%.1f s)\n",
                name_.c_str(), n_tetrahedra, surface.n_faces(),
                meshes::enclosed_volume(surface) * 1e9, labels.c_str(), clock.seconds());
  previous_stress_ = von_mises_on(surface);
  output_ = std::make_unique<RunOutput>(directory_, writes_);
  make_evaluation(p);
}

void WearingPart::make_evaluation(const CaseParameters& p) {
  if (p.scene.evaluation.wall == name_)
    evaluation_ = std::make_unique<dem::SceneEvaluation>(
        p.scene, p.geometry, p.dem.psd.mean_diameter(), wall_, surface());
}

meshes::SurfaceMesh WearingPart::wall_surface() const {
  return frame_ ? frame_->place_in_tester(surface()) : surface();
}

// The wall's surface may be a revision of the part's own faces (moved by the DEM's nodes in a
// reference stage): the loads follow the faces.
dem::WallLoads WearingPart::own_loads(const dem::WallLoads& wall_loads) const {
  if (!frame_)
    return wall_loads.follow(surface(), [](const meshes::Vec3& v) { return v; });
  const meshes::SampleFrame& frame = *frame_;
  return wall_loads.follow(surface(),
                           [&frame](const meshes::Vec3& v) { return frame.vector_to_sample(v); });
}

void WearingPart::observe(const dem::SceneRun& scene, const dem::SceneWindow& w,
                          const dem::WearLaw& law, const dem::WallLoads& window,
                          double wall_seconds) {
  if (evaluation_)
    evaluation_->observe(scene, w, law, window.wear_volume.values(), wall_seconds);
}

void WearingPart::write_tables() const {
  if (evaluation_)
    output_->write_tables(evaluation_->history(), stages_, evaluation_->n_columns(),
                          evaluation_->element_labels());
  else
    output_->write_tables({}, stages_, 0, {});
}

void WearingPart::record_initial(double time) {
  const std::vector<double> zero(surface().n_faces(), 0);
  output_->add_surface(0, time, surface(),
                       {{"cumulative removed volume", 1, zero}, {"wear depth", 1, zero}});
}

WearingPart::WearingPart(const CaseParameters& p, std::size_t index, const PartCheckpoint& c,
                         bool writes)
    : wall_(index), name_(p.scene.walls.at(index).name), directory_(part_directory(p, name_)),
      frame_(part_frame(p, p.scene.walls[index])), writes_(writes), stages_(c.stages),
      moved_volume_(c.moved_volume), footprints_(c.footprints) {
  if (frame_ && !c.sample_frame)
    throw std::runtime_error("--resume: the checkpoint holds the tester's sample '" + name_ +
                             "' in the scene's frame (an older engine's); run the case again "
                             "with --overwrite");
  meshes::ensure_directory(directory_ + "/mesh"); // a rank's scratch copy starts empty
  sample_ = std::make_unique<fem::WornSample>(c.sample, part_parameters(p, p.scene.walls[index]));
  previous_stress_ = von_mises_on(sample_->surface());
  previous_stress_.values() = c.face_von_mises;
  for (std::size_t k = 0; k < c.labels.size(); ++k)
    removed_per_label_[c.labels[k]] = c.removed_per_label[k];
  output_ = std::make_unique<RunOutput>(directory_, writes_);
  output_->reload(stages_);
  make_evaluation(p);
  if (evaluation_ != nullptr) {
    if (!c.evaluation)
      throw std::runtime_error("--resume: the checkpoint holds no evaluation of part '" + name_ +
                               "' (Scene/Evaluation/Wall); run the case again with --overwrite");
    evaluation_->resume(*c.evaluation);
  } else if (c.evaluation)
    throw std::runtime_error("--resume: the checkpoint holds an evaluation of part '" + name_ +
                             "' the case does not ask (Scene/Evaluation/Wall)");
  // part_wear.csv as it stood after the checkpoint's stages.
  std::ifstream in(directory_ + "/part_wear.csv");
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line))
    if (std::stoi(line.substr(0, line.find(','))) <= int(stages_.size()))
      wear_rows_ += line + "\n";
  // part_life.csv and element_life.csv likewise.
  for (auto [file, rows] :
       {std::pair{"/part_life.csv", &life_rows_}, std::pair{"/element_life.csv", &element_rows_}}) {
    std::ifstream in(directory_ + file);
    std::getline(in, line);
    while (std::getline(in, line))
      if (std::stoi(line.substr(0, line.find(','))) <= int(stages_.size()))
        *rows += line + "\n";
  }
}

void WearingPart::run_stage(
    StageRecord r, const dem::WallLoads& loads, const CaseParameters& p, std::ostream& log,
    const std::function<dem::PushReport(const meshes::SurfaceMesh&)>& to_wall,
    const dem::ReferenceDeformation* moved) {
  if ((r.scheme == Scheme::reference) != (moved != nullptr))
    throw std::logic_error("WearingPart::run_stage: the DEM's moved surface is a reference "
                           "stage's, and only its");
  const meshes::Stopwatch wear_clock;
  const WearIncrement increment =
      wear_increment(sample_->surface(), loads.wear_volume, previous_stress_, p.coupling,
                     r.scheme == Scheme::staged);
  if (increment.lowered) {
    const auto& d = increment.declared_depth;
    log << format("stage %d, part '%s': amplification %g -> %.4g: at %g it would recede vertex "
                  "%ld (%s) by %.3g mm, %.3g of its longest edge (Maximum depth fraction %g)\n",
                  r.stage, name_.c_str(), increment.declared_amplification, increment.amplification,
                  increment.declared_amplification, d.vertex, meshes::label::name(d.label).c_str(),
                  1e3 * d.depth_there, d.max_fraction, p.coupling.max_depth_fraction);
  }
  double impact = 0, total = 0; // [m^3] the window's wear-law volume, and its impact part
  for (std::size_t f = 0; f < loads.wear_volume.size(); ++f) {
    impact += loads.impact_volume[f];
    total += loads.wear_volume[f];
  }
  if (impact > 0)
    log << format("stage %d, part '%s': %.4g mm^3 of the window's wear-law volume %.4g mm^3 "
                  "(%.1f %%) by impact\n",
                  r.stage, name_.c_str(), impact * 1e9, total * 1e9, 100 * impact / total);
  if (writes_) { // the window's loads on the surface they fell on, before the stage moves it
    meshes::ensure_directory(directory_ + "/loads");
    meshes::write_vtu(sample_->surface(), directory_ + format("/loads/stage_%04d.vtu", r.stage),
                      {&loads.wear_volume, &loads.impact_volume, &loads.archard,
                       &loads.normal_impulse, &loads.contact_steps});
  }
  record_increment(increment, stages_.empty() ? 0.0 : stages_.back().cumulative_applied, p.coupling,
                   r);
  r.wear_seconds = wear_clock.seconds();
  StageChange change;
  switch (r.scheme) {
  case Scheme::dem_only:
    change = dem_only_stage(increment);
    break;
  case Scheme::staged:
    change = staged_stage(increment, loads, p, log, to_wall, r);
    break;
  case Scheme::reference:
    change = reference_stage(*moved, increment, r);
    break;
  }
  record_stage(std::move(r), change, p.coupling, log);
}

// A dem-only stage leaves the part as it is; its increment is recorded, not applied.
WearingPart::StageChange WearingPart::dem_only_stage(const WearIncrement& increment) const {
  return {sample_->surface(),
          increment.removed,
          sample_->removed_volume().values(),
          sample_->wear_depth().values(),
          false,
          "",
          false};
}

// A staged stage: the stress under the stage's loads, then the geometry update (recession,
// mesh motion, remeshing) and the new surface to the DEM wall.
WearingPart::StageChange
WearingPart::staged_stage(const WearIncrement& increment, const dem::WallLoads& loads,
                          const CaseParameters& p, std::ostream& log,
                          const std::function<dem::PushReport(const meshes::SurfaceMesh&)>& to_wall,
                          StageRecord& r) {
  fem::ElasticityParameters ep = p.fem.elasticity;
  ep.averaging_radius = stress_averaging_radius(p);
  const StageStress stress = solve_stage_stress(*sample_, loads, ep, *output_, r);
  GeometryUpdate update = apply_stage_wear(*sample_, increment, stress, r);
  log_geometry_notes(r, update.report, log);
  previous_stress_ = std::move(update.von_mises);
  const dem::PushReport pushed = to_wall(wall_surface());
  r.n_pushed = pushed.n_pushed;
  r.max_push = pushed.max_distance;
  return {sample_->surface(),
          std::move(update.applied),
          sample_->removed_volume().values(),
          sample_->wear_depth().values(),
          true,
          format(", max von Mises (ball) %.3g MPa, %d remeshes, FEM %.1f s, %d particles pushed "
                 "out",
                 r.max_von_mises_ball * 1e-6, r.n_remeshes,
                 r.fem_solve_seconds + r.motion_seconds + r.remesh_seconds, r.n_pushed),
          true};
}

// What the geometry update had to do beyond the plain recession, said once per stage.
void WearingPart::log_geometry_notes(const StageRecord& r, const fem::WearStageReport& report,
                                     std::ostream& log) const {
  const std::string where = "stage " + std::to_string(r.stage) + ", part '" + name_ + "': ";
  if (report.n_relaxation_halvings > 0)
    log << where << "the surface relaxation was halved " << report.n_relaxation_halvings
        << " time(s) (alone it folded the surface or removed the whole increment)\n";
  if (report.n_held_restorations > 0)
    log << where << "after " << report.n_held_restorations
        << " remesh(es) the volume-restoring offset would have folded the surface and was held "
           "still around the fold\n";
  // Round-off of a restoring offset with almost nothing to give back (-5e-11 mm^3 of a
  // 762 mm^3 stage) is no note; a billionth of the stage is.
  if (std::abs(report.volume_not_restored) > 1e-9 * report.removed_volume)
    log << where
        << format("%.3g mm^3 of chord volume not given back after remeshing (the restoring "
                  "offset folded or fell short)\n",
                  report.volume_not_restored * 1e9);
  for (const auto& failure : report.explicit_remesh_failures)
    log << where << "the recession's moved surface could not be remeshed (" << failure
        << "); the implicit recession took the rest of the stage\n";
  for (const auto& failure : report.implicit_failures)
    log << where << "the implicit recession failed (" << failure
        << "); the explicit recession went on\n";
  if (report.n_implicit > 0)
    log << where << report.n_implicit << " implicit recession(s), "
        << format("%.1f s, grid loss %.3g mm^3", report.implicit_seconds,
                  report.implicit_grid_loss * 1e9);
  if (report.n_fragments > 0)
    log << format("; %zu fragment(s) cut off and dropped, %.3g mm^3", report.n_fragments,
                  report.fragment_volume * 1e9);
  if (report.n_teeth_joined > 0)
    log << format("; %zu face(s) of no width joined to the label beside them",
                  report.n_teeth_joined);
  if (report.n_folds_mended + report.n_folds_left > 0)
    log << format("; %zu folded edge(s) mended, %zu left", report.n_folds_mended,
                  report.n_folds_left);
  if (!report.vanished_labels.empty()) {
    log << (report.n_implicit > 0 ? "; " : where) << "worn away:";
    for (const int label : report.vanished_labels)
      log << " " << meshes::label::name(label);
  }
  if (report.n_implicit > 0 || !report.vanished_labels.empty())
    log << "\n";
  for (const auto& refusal : report.remesh_refusals)
    log << where << "a remesh needed more than one attempt; refused:" << refusal << "\n";
}

// A reference stage: the DEM moved the nodes (cumulative figures over the run): the volume the
// nodes took up on the wearing faces, the enclosed volume the surface lost, the surface they
// moved, in the part's frame. The part's FEM sample stays as it was.
WearingPart::StageChange WearingPart::reference_stage(const dem::ReferenceDeformation& moved,
                                                      const WearIncrement& increment,
                                                      StageRecord& r) {
  double before = 0, lost_before = 0;
  for (const auto& s : stages_) {
    before = s.cumulative_applied;
    lost_before += s.geometry_volume_change;
  }
  r.cumulative_applied = moved.applied_volume();
  r.applied_volume = r.cumulative_applied - before;
  r.geometry_volume_change = moved.enclosed_volume_loss() - lost_before;
  r.distortion = moved.distortion_text();
  const auto& removed = increment.removed;
  moved_volume_.resize(removed.size(), 0.0);
  for (std::size_t f = 0; f < removed.size(); ++f)
    moved_volume_[f] += removed[f];
  meshes::SurfaceMesh surface = frame_ ? frame_->place_in_sample(moved.mesh()) : moved.mesh();
  const auto area = meshes::face_areas(surface);
  std::vector<double> depth(area.size());
  for (std::size_t f = 0; f < depth.size(); ++f)
    depth[f] = moved_volume_[f] / area[f];
  return {std::move(surface),
          removed,
          moved_volume_,
          std::move(depth),
          true,
          format(" by the DEM's node moves, the surface's enclosed volume %.4g mm^3 less",
                 r.geometry_volume_change * 1e9),
          false};
}

// Whatever the scheme: the surface with its fields, the stage's record, the tables, the volume
// per label and the stage's line.
void WearingPart::record_stage(StageRecord r, const StageChange& change,
                               const CouplingParameters& c, std::ostream& log) {
  const meshes::Stopwatch clock;
  const auto& surface = change.surface;
  std::map<int, double> stage_per_label;
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    stage_per_label[surface.face_labels[f]] += change.applied[f];
  std::vector<meshes::VtuArray> fields{{"cumulative removed volume", 1, change.cumulative},
                                       {"wear depth", 1, change.depth},
                                       {"stage removed volume", 1, change.applied.values()}};
  if (change.stress_solved)
    fields.push_back({"von Mises", 1, previous_stress_.values()});
  output_->add_surface(r.stage, r.time, surface, fields);
  r.n_surface_faces = int(surface.n_faces());
  r.n_tetrahedra = int(sample_->triangulation().n_active_cells());
  r.output_seconds += clock.seconds();
  if (evaluation_) { // the periods of this stage (a stage is a whole number of them)
    if (change.changes_geometry)
      evaluation_->set_surface(surface);
    r.first_revolution = stages_.empty() ? 1 : stages_.back().last_revolution + 1;
    r.last_revolution = int(evaluation_->history().size());
  }
  const bool first_worn_through =
      r.worn_through_volume > 0 &&
      std::none_of(stages_.begin(), stages_.end(),
                   [](const StageRecord& s) { return s.worn_through_volume > 0; });
  stages_.push_back(r);
  write_tables();
  if (change.changes_geometry) // a dem-only stage's volume changes nothing
    for (const auto& [label, v] : stage_per_label)
      removed_per_label_[label] += v;
  std::ostringstream rows;
  rows.precision(10);
  for (const auto& [label, v] : stage_per_label)
    if (surface.roles.wears(label))
      rows << r.stage << "," << scheme_name(r.scheme) << "," << r.time << ","
           << meshes::label::name(label) << "," << v << "," << removed_per_label_[label] << "\n";
  wear_rows_ += rows.str();
  if (writes_)
    meshes::write_atomically(directory_ + "/part_wear.csv",
                             [&](std::ostream& out) { out << part_wear_header << wear_rows_; });
  record_life(r.stage, surface, c);
  log << format("stage %d %s, part '%s': wear-law volume %.4g mm^3, removed %.4g mm^3 "
                "(cumulative %.4g)",
                r.stage, scheme_name(r.scheme).c_str(), name_.c_str(), r.dem_wear_volume * 1e9,
                r.applied_volume * 1e9, r.cumulative_applied * 1e9)
      << change.note << "\n"
      << std::flush;
  if (first_worn_through)
    log << format("stage %d, part '%s': worn through: %d wear faces are within %g mm of the "
                  "clamped bottom (FEM/Worn-through thickness); the %.4g mm^3 asked of them is "
                  "not removed (stages.csv: worn_through_volume_m3)\n",
                  r.stage, name_.c_str(), r.n_worn_through,
                  sample_->parameters().worn_through_thickness * 1e3, r.worn_through_volume * 1e9);
}

void WearingPart::record_life(int stage, const meshes::SurfaceMesh& surface,
                              const CouplingParameters& c) {
  const auto life = meshes::part_life(surface, sample_->parameters().implicit.vanish_height);
  const double revolutions = equivalent_revolutions(stages_, c.revolutions_per_stage);
  std::ostringstream rows;
  rows.precision(10);
  const auto row = [&](const std::string& what, double height, double volume) {
    rows << stage << "," << revolutions << "," << revolutions * c.hours_per_revolution << ","
         << what << "," << height << "," << volume << "\n";
  };
  for (const auto& [label, e] : life.elements)
    row(meshes::label::name(label), e.height, e.volume);
  row("part", life.thinnest, life.volume);
  life_rows_ += rows.str();
  if (writes_)
    meshes::write_atomically(directory_ + "/part_life.csv",
                             [&](std::ostream& out) { out << part_life_header << life_rows_; });
  if (footprints_.empty())
    return;
  std::ostringstream stage_columns;
  stage_columns.precision(10);
  stage_columns << stage << "," << revolutions << "," << revolutions * c.hours_per_revolution;
  element_rows_ +=
      element_life_rows(stage_columns.str(), meshes::footprint_standing(surface, footprints_));
  if (writes_)
    meshes::write_atomically(directory_ + "/element_life.csv", [&](std::ostream& out) {
      out << element_life_header << element_rows_;
    });
}

std::string WearingPart::worn_out(const CouplingParameters& c) const {
  const auto& s = surface();
  const double vanish = sample_->parameters().implicit.vanish_height;
  switch (worn_out_criterion(c.worn_out_when)) {
  case WornOutCriterion::never:
    return {};
  case WornOutCriterion::elements_gone: {
    if (meshes::part_life(s, vanish).n_standing > 0)
      return {};
    return format("no convex element stands higher than %g mm above its foot", vanish * 1e3);
  }
  case WornOutCriterion::thickness: {
    const auto life = meshes::part_life(s, vanish);
    if (life.thinnest > c.worn_out_thickness)
      return {};
    return format("its thinnest point, %.4g mm above the clamped bottom, reached Worn-out "
                  "thickness %g mm",
                  life.thinnest * 1e3, c.worn_out_thickness * 1e3);
  }
  case WornOutCriterion::worn_through: {
    const bool hole = meshes::euler_characteristic(s) < 2;
    const bool set_aside = std::any_of(stages_.begin(), stages_.end(), [](const StageRecord& r) {
      return r.worn_through_volume > 0;
    });
    if (!hole && !set_aside)
      return {};
    return hole ? std::string("worn through: its surface has a hole")
                : std::string("worn through: wear faces reached the clamped bottom "
                              "(FEM/Worn-through thickness)");
  }
  }
  return {};
}

double WearingPart::equivalent_hours(const CouplingParameters& c) const {
  return equivalent_revolutions(stages_, c.revolutions_per_stage) * c.hours_per_revolution;
}

std::string WearingPart::summary_text() const {
  double t[6] = {0, 0, 0, 0, 0, 0};
  int n_remeshes = 0, n_first = 0;
  double worn_through = 0;
  for (const auto& r : stages_) {
    t[0] += r.dem_seconds, t[1] += r.wear_seconds, t[2] += r.fem_solve_seconds;
    t[3] += r.motion_seconds, t[4] += r.remesh_seconds, t[5] += r.output_seconds;
    n_remeshes += r.n_remeshes, n_first += r.n_first_attempt_remeshes;
    worn_through += r.worn_through_volume;
  }
  const char* names[6] = {"DEM", "wear", "FEM solve", "mesh motion", "remesh", "output"};
  double total = 0;
  for (double x : t)
    total += x;
  std::string text = "part '" + name_ + "', time per phase over its stages:\n";
  for (int k = 0; k < 6; ++k)
    text += format("  %-12s %10.1f s  %5.1f %%\n", names[k], t[k],
                   total > 0 ? 100 * t[k] / total : 0.0);
  text += format("  %-12s %10.1f s\n", "total", total);
  if (n_remeshes > 0)
    text += format("  remeshes: %d, %d of them (%.0f %%) at gmsh's first attempt\n", n_remeshes,
                   n_first, 100.0 * n_first / n_remeshes);
  if (worn_through > 0)
    text +=
        format("  worn through: %.4g mm^3 of the %.4g mm^3 asked was not removed\n",
               worn_through * 1e9, stages_.empty() ? 0.0 : stages_.back().cumulative_applied * 1e9);
  return text;
}

PartCheckpoint WearingPart::state(const dem::WallLoads& open) const {
  PartCheckpoint c;
  c.sample = sample_->state();
  c.face_von_mises = previous_stress_.values();
  c.stages = stages_;
  for (const auto& [label, v] : removed_per_label_) {
    c.labels.push_back(label);
    c.removed_per_label.push_back(v);
  }
  c.open = open_stage(open);
  if (evaluation_)
    c.evaluation = evaluation_->state();
  c.sample_frame = frame_.has_value();
  c.moved_volume = moved_volume_;
  c.footprints = footprints_;
  return c;
}

} // namespace wear::coupling

// A scene's run (scene_coupled_run.h): its DEM, and the staged wear loop on its wearing parts.
//
// Set-up: the scene's walls are built (dem/scene/scene_walls.h), each wearing wall's CAD
// surfaces labelled by role (S<n> wearing, S<n>-free, S<n>-clamped) and meshed into its
// part's tetrahedra (wearing_part.h); the DEM wall takes that mesh's boundary, so DEM faces
// and FEM boundary faces are the same triangles and every per-face field crosses without
// interpolation.
// One stage:
//   1. DEM: Scene/Stage duration in windows of Output interval, a record each; the windows'
//      loads on each part (impulse, Archard, wear-law volume V_f per face, in the part's own
//      frame) summed.
//   2. Each part: wear, stress and geometry under its own loads, its records (wearing_part.h).
//   3. Each part's new surface to its DEM wall, the particles kept (a part only recedes from
//      them; those a remesh's chords would overlap pushed out, Coupling/Push tolerance); a
//      checkpoint.
// "dem-only" stages change no surface. "reference" stages (the node-moving method) move each
// part's nodes inside the DEM (dem::SceneRun::move_wall_nodes) instead of steps 2 and 3's FEM;
// the part records the moved surface, and the run stops after the stage whose surface
// distorted. Without stages the run is one DEM stage to End time.
// The part Scene/Evaluation names is sampled after every window and evaluated per period
// (wearing_part.h).
// Checkpoints are taken between two windows, where the engine is between two steps: the
// engine's state with its continuation, the inlets' generators, the outlets' and flux planes'
// counts, each worn part and its open stage's summed loads; a resumed run repeats the
// uninterrupted one bit for bit with the same thread count. A scene that has not yet set up its
// engine (no particle so far) has nothing to lose and is not checkpointed.
// Over ranks: every rank builds the walls and meshes the parts; the DEM is decomposed (rank
// layout logged), its windows and loads are the whole scene's on every rank, each part's
// stage runs on every rank and the worn surfaces are checked the same on all; a stop or a
// checkpoint is agreed over the ranks; a checkpoint gathers the ranks' DEM parts to rank 0
// with the slabs' cuts, and a resume on another rank count takes the merged bed. After a
// window whose bed has flowed away from its cuts (Scene/Rank rebalance), the scene is cut anew.
#include "coupling/loop/scene_coupled_run.h"

#include "coupling/output/text_format.h"
#include "dem/engine/rank_states.h"
#include "dem/scene/wall_catalogue.h"
#include "meshes/stopwatch.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace wear::coupling {

namespace {

std::vector<std::size_t> wearing_walls(const dem::SceneParameters& scene) {
  std::vector<std::size_t> wearing;
  for (std::size_t k = 0; k < scene.walls.size(); ++k)
    if (scene.walls[k].wears)
      wearing.push_back(k);
  if (wearing.empty())
    throw std::invalid_argument("Scene/Stage duration: a wear loop needs a wearing part; set "
                                "Wears = true in the subsection of a wall that wears");
  return wearing;
}

// The scene filled and settled as a new run fills it (also the bed of a run resumed without
// one), its progress and over ranks its layout logged.
void fill_bed(dem::SceneRun& scene, const RunOptions& options, std::ostream& log) {
  scene.setup([&](const std::string& text) { log << "scene: " << text << "\n" << std::flush; });
  if (options.ranks && options.ranks->n_ranks() > 1)
    log << "scene: " << scene.rank_layout() << "; rank 0 writes" << std::endl;
}

} // namespace

SceneCoupledRun::SceneCoupledRun(const CaseParameters& p, std::ostream& log,
                                 const RunOptions& options)
    : p_(p), log_(options.ranks && options.ranks->rank() != 0 ? silent_ : log), options_(options),
      ranks_(options.ranks), part_case_(p), parameters_text_(resolved_parameters(p)) {
  dem::validate(p_.scene);
  if (p_.scene.stage_duration <= 0) { // one DEM stage to End time
    plan_ = {Scheme::dem_only};
    return;
  }
  validate(p_.coupling, p_.fem);
  part_walls_ = wearing_walls(p_.scene);
  for (const std::size_t k : part_walls_) {
    const auto& wall = p_.scene.walls[k];
    if (dem::wall_source_of(wall).source != dem::WallSource::sample && // clamped at its bottom
        dem::surface_numbers(wall.clamped_surfaces, dem::scene_wall_path(wall)).empty())
      throw std::invalid_argument(dem::scene_wall_path(wall) +
                                  "/Clamped surfaces: the wearing part needs at least one "
                                  "clamped surface (held fixed in the FEM; without one it would "
                                  "float)");
  }
  for (const auto& item : parse_schedule(p_.coupling.schedule)) {
    plan_.insert(plan_.end(), std::size_t(item.n_stages), item.scheme);
    moves_nodes_ |= item.scheme == Scheme::reference;
  }
  if (moves_nodes_) // known from the case: refused before the scene fills
    for (const std::size_t k : part_walls_)
      if (dem::wall_motion_of(p_.scene.walls[k]).rigid)
        throw std::invalid_argument(dem::scene_wall_path(p_.scene.walls[k]) +
                                    "/Motion: the node-moving method moves the nodes of a wall "
                                    "that keeps its place (fixed, or a surface motion), not of "
                                    "one that moves as a whole");
  law_ = dem::make_wear_law(p_.wear_law);
}

int SceneCoupledRun::run() {
  const StopSignals signals;
  std::optional<OpenSceneStage> open = setup();
  if (const std::string steady = steady_stop(); !steady.empty()) { // resumed after the stop
    log_ << steady << "; nothing is left to run\n";
    return 0;
  }
  if (const std::string worn = worn_out_stop(); !worn.empty()) {
    log_ << worn << "; nothing is left to run\n";
    return 0;
  }
  int n_run = 0;
  for (std::size_t k = std::size_t(n_stages_done_); k < plan_.size(); ++k) {
    StageRecord r = begin_stage(k);
    const auto loads = run_dem(r, std::exchange(open, {}), signals);
    if (!loads) {
      const int signal = ranks_.agreed_signal(signals);
      log_ << "stopped by " << StopSignals::name(signal) << " in stage " << r.stage << " of "
           << plan_.size() << " at t = " << scene_->time() << " s";
      if (scene_->system().n_rebuilds() > 0 && p_.coupling.checkpoints)
        log_ << " after a checkpoint; continue with wearsim " << options_.command << " --resume "
             << p_.case_file << "\n";
      else // nothing was checkpointed: no particle yet, or checkpoints off
        log_ << " without a checkpoint (no particle yet, or Coupling/Checkpoints off); run it "
                "again with --overwrite\n";
      return 128 + signal;
    }
    run_parts(r, *loads);
    n_stages_done_ = r.stage;
    if (const std::string distorted = distortion(); !distorted.empty()) {
      log_ << "the reference method distorted " << distorted << " in stage " << r.stage
           << "; the run stops here, as the reference study's did\n";
      break;
    }
    checkpoint(next_stage());
    if (const std::string steady = steady_stop(); !steady.empty()) {
      log_ << steady << "\n";
      break;
    }
    if (const std::string worn = worn_out_stop(); !worn.empty()) {
      log_ << worn << "\n";
      break;
    }
    if (options_.stop_after > 0 && ++n_run >= options_.stop_after && k + 1 < plan_.size()) {
      log_ << "stopped after stage " << r.stage << " as asked; continue with --resume\n";
      return 0;
    }
  }
  for (const auto& part : parts_)
    log_ << part.summary_text();
  log_ << "written to " << p_.output.directory << "/ (scene_series.csv, scene_wear.csv, "
       << "particles_<k>.vtu, walls/"
       << (parts_.empty()
               ? ""
               : ", parts/<part>/ with stages.csv, part_wear.csv, part_life.csv, history.xdmf")
       << (scene_->fields() ? ", fields.xdmf" : "") << ")\n";
  return 0;
}

std::optional<SceneCoupledRun::OpenSceneStage> SceneCoupledRun::setup() {
  const std::string replaced = ranks_.writer() ? prepare_run_folder(p_, options_, log_) : "";
  ranks_.wait_for_folder(); // rank 0 has the folder ready before any rank goes on
  if (!ranks_.writer())
    part_case_.output.directory = ranks_.scratch();
  if (options_.resume)
    return resume();
  std::vector<dem::SceneWall> walls = dem::build_scene_walls(p_.scene, p_.geometry);
  for (const std::size_t k : part_walls_) {
    parts_.emplace_back(part_case_, k, walls[k], log_, ranks_.writer());
    ranks_.require_same(parts_.back().surface(), "part '" + parts_.back().name() + "' meshed");
  }
  scene_ = std::make_unique<dem::SceneRun>(p_.scene, p_.dem, std::move(walls),
                                           dem::impact_measure(p_.wear_law));
  scene_->set_rank_link(options_.ranks);
  fill_bed(*scene_, options_, log_);
  if (moves_nodes_) {
    move_part_nodes();
    log_ << "scene: the wearing parts' nodes move inside the DEM every "
         << p_.deformation.update_interval << " steps (reference scheme)\n";
  }
  for (auto& part : parts_)
    part.record_initial(scene_->time());
  log_ << "scene: " << scene_->walls().size() << " walls (" << parts_.size() << " wearing), "
       << scene_->inlets().size() << " inlets, " << scene_->outlets().size()
       << " outlets; batches and outlets every " << scene_->exchange_interval() << " s; "
       << plan_.size() << " stage(s) of "
       << (parts_.empty() ? p_.scene.end_time : p_.scene.stage_duration) << " s\n";
  if (ranks_.writer())
    series_ = std::make_unique<SceneSeries>(p_.output.directory, *scene_);
  replaced_ = replaced;
  // The settled bed, before any stage: a run stopped in its first stage does not fill again.
  checkpoint(next_stage());
  return std::nullopt;
}

std::optional<SceneCoupledRun::OpenSceneStage> SceneCoupledRun::resume() {
  const DemPart part = ranks_.dem_part();
  const Checkpoint c = read_latest_checkpoint(checkpoint_path(), log_, part);
  require_same_case(c, parameters_text_, checkpoint_path());
  const auto& s = c.scene;
  if (s.parts.size() != part_walls_.size())
    throw std::runtime_error("--resume: checkpoint '" + checkpoint_path() + "' holds " +
                             std::to_string(s.parts.size()) + " wearing parts, the case " +
                             std::to_string(part_walls_.size()));
  n_stages_done_ = c.stages_done;
  std::vector<dem::SceneWall> walls = dem::build_scene_walls(p_.scene, p_.geometry);
  OpenSceneStage open{{}, s.stage_end};
  for (std::size_t i = 0; i < part_walls_.size(); ++i) {
    parts_.emplace_back(part_case_, part_walls_[i], s.parts[i], ranks_.writer());
    walls[part_walls_[i]].surface.mesh = parts_.back().wall_surface();
    open.loads.push_back(loads_of(s.parts[i].open, parts_.back().surface()));
  }
  const bool inside = std::any_of(s.parts.begin(), s.parts.end(),
                                  [](const PartCheckpoint& k) { return k.open.duration > 0; });
  scene_ = std::make_unique<dem::SceneRun>(p_.scene, p_.dem, std::move(walls),
                                           dem::impact_measure(p_.wear_law));
  scene_->set_rank_link(options_.ranks);
  n_records_ = s.n_records;
  first_table_record_ = s.first_table_record;
  if (!c.has_bed)
    return refill(checkpoint_path(), inside);
  const dem::SceneRunState state = scene_run_state(s, c.dem);
  if (moves_nodes_) // from the unmoved surfaces, moved as the state says
    move_part_nodes();
  scene_->resume(state);
  if (ranks_.writer())
    series_ = std::make_unique<SceneSeries>(p_.output.directory, *scene_, s.n_records,
                                            first_table_record_);
  if (c.dem_ranks != part.n_ranks)
    log_ << "the checkpoint was written on " << c.dem_ranks << " rank(s), this run has "
         << part.n_ranks << ": the scene is decomposed again (it continues, not bit for bit as "
         << "on " << c.dem_ranks << ")" << std::endl;
  if (part.n_ranks > 1)
    log_ << "scene: " << scene_->rank_layout() << "; rank 0 writes" << std::endl;
  log_ << "resumed after stage " << n_stages_done_ << " of " << plan_.size()
       << (inside ? ", inside stage " + std::to_string(n_stages_done_ + 1) : std::string())
       << " at t = " << s.time << " s (" << s.n_records << " records)" << std::endl;
  return open;
}

SceneCoupledRun::OpenSceneStage SceneCoupledRun::refill(const std::string& path, bool inside) {
  const std::string next = std::to_string(n_stages_done_ + 1);
  if (inside)
    throw std::runtime_error("--resume: checkpoint '" + path + "' holds no particle bed and " +
                             "was written inside stage " + next + "; a checkpoint is kept " +
                             "without its bed only at a stage's end");
  if (moves_nodes_)
    throw std::runtime_error("--resume: checkpoint '" + path + "' holds no particle bed; the " +
                             "reference scheme's parts move inside the DEM and need it");
  // The bed as the run's start made it: the fill settled on the worn surfaces, then the DEM
  // for as long as the schedule's leading dem-only stages, which bring a new bed to its flow.
  const auto first_worn =
      std::find_if(plan_.begin(), plan_.end(), [](Scheme s) { return s != Scheme::dem_only; });
  OpenSceneStage open = next_stage();
  open.warm_up = double(first_worn - plan_.begin()) * p_.scene.stage_duration;
  log_ << "resumed after stage " << n_stages_done_ << " of " << plan_.size() << " from '" << path
       << "', a checkpoint without its particle bed: the bed is filled anew on the worn "
       << "surfaces and runs " << format("%.4g", open.warm_up) << " s (the schedule's leading "
       << "dem-only stages) before stage " << next << " begins; its clock starts again, so the "
       << "stages' times from here on are the new bed's" << std::endl;
  fill_bed(*scene_, options_, log_);
  if (ranks_.writer()) {
    // A run carried to another machine brings its checkpoint, not its scene tables.
    const bool kept = std::filesystem::exists(p_.output.directory + "/scene_series.csv");
    if (!kept)
      log_ << "scene: '" << p_.output.directory << "' holds no scene_series.csv: the scene's "
           << "tables start again at record " << n_records_ + 1 << std::endl;
    series_ = std::make_unique<SceneSeries>(
        p_.output.directory, *scene_, n_records_, first_table_record_,
        kept ? SceneSeries::EarlierRows::read : SceneSeries::EarlierRows::absent);
    // Its checkpoints say where the tables start, so that a later --resume reads them.
    first_table_record_ = series_->first_record();
  }
  return open;
}

bool SceneCoupledRun::warm_up(double duration, const StopSignals& signals) {
  const double every = p_.scene.output_interval;
  const double end = scene_->time() + duration;
  while (scene_->time() < end - 1e-9 * every) {
    const dem::SceneWindow w = scene_->advance(std::min(end, scene_->time() + every));
    log_ << "warm-up of the new bed: " << window_summary(w) << "\n" << std::flush;
    if (ranks_.agreed_signal(signals) != 0)
      return false;
  }
  return true;
}

void SceneCoupledRun::record(const dem::SceneWindow& w) {
  ++n_records_;
  const bool snapshot = dem::snapshot_due(p_.scene, n_records_) && w.n_particles > 0;
  if (!ranks_.link()) {
    series_->add(w, *scene_, scene_->system().particles, &scene_->system().clumps(), snapshot);
    return;
  }
  const dem::Particles all = snapshot ? scene_->particles_on_first_rank() : dem::Particles{};
  const dem::Clumps bodies =
      snapshot ? dem::gather_clumps(scene_->system().clumps(), all, ranks_.link()) : dem::Clumps{};
  if (series_)
    series_->add(w, *scene_, all, &bodies, snapshot);
}

SceneCoupledRun::OpenSceneStage SceneCoupledRun::next_stage() const {
  return {zero_loads(),
          parts_.empty() ? p_.scene.end_time : scene_->time() + p_.scene.stage_duration};
}

std::vector<dem::WallLoads> SceneCoupledRun::zero_loads() const {
  std::vector<dem::WallLoads> loads;
  for (const auto& part : parts_)
    loads.push_back(dem::WallLoads::zero(part.surface()));
  return loads;
}

StageRecord SceneCoupledRun::begin_stage(std::size_t k) const {
  StageRecord r;
  r.stage = int(k) + 1;
  r.scheme = plan_[k];
  r.amplification = p_.coupling.amplification;
  return r;
}

std::optional<std::vector<dem::WallLoads>>
SceneCoupledRun::run_dem(StageRecord& r, std::optional<OpenSceneStage> open,
                         const StopSignals& signals) {
  OpenSceneStage stage = open ? std::move(*open) : next_stage();
  if (stage.warm_up > 0) {
    if (!warm_up(stage.warm_up, signals))
      return std::nullopt;
    stage = next_stage(); // the stage begins where the warm-up ends
  }
  const meshes::Stopwatch clock; // the stage's own DEM time, without a warm-up
  const double every = p_.scene.output_interval;
  const double interval = p_.output.checkpoint_interval;
  meshes::Stopwatch since_checkpoint;
  while (scene_->time() < stage.end - 1e-9 * every) {
    const meshes::Stopwatch window_clock;
    const dem::SceneWindow w = scene_->advance(std::min(stage.end, scene_->time() + every));
    const double window_seconds = window_clock.seconds();
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const dem::WallLoads window =
          w.integrated > 0 ? parts_[i].own_loads(scene_->wall_loads(parts_[i].wall(), *law_, w))
                           : dem::WallLoads::zero(parts_[i].surface());
      if (w.integrated > 0)
        stage.loads[i] += window;
      parts_[i].observe(*scene_, w, *law_, window, window_seconds);
    }
    record(w);
    if (!parts_.empty())
      log_ << "stage " << r.stage << "/" << plan_.size() << " " << scheme_name(r.scheme) << ": ";
    log_ << window_summary(w) << "\n" << std::flush;
    if (ranks_.link() && p_.scene.rank_rebalance > 0) {
      const double imbalance = scene_->rank_imbalance();
      if (imbalance > p_.scene.rank_rebalance) {
        scene_ = scene_->rebalanced();
        log_ << format("scene: rebalanced at t = %.4f s (the fullest rank held %.2f times the "
                       "mean): ",
                       scene_->time(), imbalance)
             << scene_->rank_layout() << std::endl;
      }
    }
    const bool more = scene_->time() < stage.end - 1e-9 * every;
    // Every rank decides alike: a signal to any rank stops all, rank 0's clock times.
    const bool stop = ranks_.agreed_signal(signals) != 0 && more;
    const bool due =
        ranks_.any(ranks_.writer() && interval > 0 && since_checkpoint.seconds() >= interval);
    if ((stop || (due && more)) && scene_->system().n_rebuilds() > 0) {
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

void SceneCoupledRun::run_parts(const StageRecord& r, const std::vector<dem::WallLoads>& loads) {
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const dem::WallNodeMoves* moves = scene_->node_moves(parts_[i].wall());
    parts_[i].run_stage(
        r, loads[i], part_case_, log_,
        [&](const meshes::SurfaceMesh& surface) {
          ranks_.require_same(parts_[i].surface(), "part '" + parts_[i].name() +
                                                       "' after the FEM part of stage " +
                                                       std::to_string(r.stage));
          return scene_->replace_wall_surface(parts_[i].wall(), surface,
                                              p_.coupling.push_tolerance);
        },
        moves ? &moves->deformation() : nullptr);
  }
  if (!parts_.empty())
    log_ << format("stage %d %s done at t = %.4g s, DEM %.0f s\n", r.stage,
                   scheme_name(r.scheme).c_str(), r.time, r.dem_seconds)
         << std::flush;
}

void SceneCoupledRun::move_part_nodes() {
  for (const auto& part : parts_)
    scene_->move_wall_nodes(part.wall(), p_.wear_law, p_.deformation.update_interval,
                            p_.coupling.amplification);
}

std::string SceneCoupledRun::distortion() const {
  for (const auto& part : parts_)
    if (!part.stages().empty() && !part.stages().back().distortion.empty())
      return "part '" + part.name() + "' (" + part.stages().back().distortion + ")";
  return {};
}

std::string SceneCoupledRun::steady_stop() const {
  const int after = p_.scene.evaluation.periods_after_steady;
  for (const auto& part : parts_) {
    const dem::SceneEvaluation* e = part.evaluation();
    if (after == 0 || !e || e->history().empty())
      continue;
    const int steady = e->history().back().steady_revolution;
    const int n_periods = int(e->history().size());
    if (steady > 0 && n_periods - steady >= after)
      return "stopped " + std::to_string(n_periods - steady) + " period(s) after the first " +
             "steady one (period " + std::to_string(steady) + " of part '" + part.name() +
             "'), Scene/Evaluation/Periods after steady";
  }
  return {};
}

std::string SceneCoupledRun::worn_out_stop() const {
  for (const auto& part : parts_)
    if (const std::string why = part.worn_out(p_.coupling); !why.empty()) {
      const double hours = part.equivalent_hours(p_.coupling);
      return "part '" + part.name() + "' worn out at " +
             (p_.coupling.hours_per_revolution > 0
                  ? format("%.0f h", hours)
                  : std::string("an unstated number of hours (Coupling/Hours per revolution)")) +
             " after stage " + std::to_string(n_stages_done_) + ": " + why +
             " (Coupling/Worn out when = " + p_.coupling.worn_out_when + ")";
    }
  return {};
}

void SceneCoupledRun::checkpoint(const OpenSceneStage& open) {
  if (!p_.coupling.checkpoints || scene_->system().n_rebuilds() == 0)
    return;
  const dem::SceneRunState state = scene_->state();
  Checkpoint c;
  c.stages_done = n_stages_done_;
  c.parameters = parameters_text_;
  c.dem = state.system;
  c.scene = scene_checkpoint(state, open.end, n_records_, first_table_record_);
  for (std::size_t i = 0; i < parts_.size(); ++i)
    c.scene.parts.push_back(parts_[i].state(open.loads[i]));
  ranks_.write(checkpoint_path(), c);
  if (!replaced_.empty()) { // the run --overwrite replaced goes once this one can be resumed
    std::filesystem::remove_all(replaced_);
    log_ << "the replaced run in '" << replaced_ << "' is deleted (this run has its first "
         << "checkpoint)" << std::endl;
    replaced_.clear();
  }
}

} // namespace wear::coupling

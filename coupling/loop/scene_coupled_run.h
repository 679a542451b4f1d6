#pragma once
// `wearsim scene-run`: a scene's run (docs/coupling.md). Without a wearing part (or without
// Scene/Stage duration) one DEM stage to Scene/End time; with one, the staged wear loop on the
// user's own equipment. run() reads as the algorithm: per stage, loads = run_dem -> increment
// = compute_wear(loads) -> stress = solve_stress(loads) -> update = update_geometry(increment,
// stress) -> record -> checkpoint. The part is the scene's wearing wall: its CAD surfaces
// labelled by role (wearing, free, clamped), meshed into tetrahedra by gmsh, worn, moved and
// remeshed by fem::WornSample exactly as the tester's sample; the worn surface goes back to
// the DEM wall with the particles kept. Between two windows the run checkpoints itself (after
// every stage, every Output/Checkpoint interval, and on SIGINT/SIGTERM/SIGUSR1, then it
// stops), and `--resume` continues bit for bit (same thread count).
#include "coupling/loop/coupled_run.h"
#include "coupling/loop/stage_steps.h"
#include "coupling/loop/stop_signals.h"
#include "coupling/output/checkpoint.h"
#include "coupling/output/run_output.h"
#include "coupling/output/scene_series.h"
#include "coupling/parameters/case_parameters.h"
#include "dem/scene/scene_run.h"
#include "dem/wear/wear_law.h"
#include "fem/worn_sample.h"

#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <vector>

namespace wear::coupling {

class SceneCoupledRun {
public:
  /// Checks the case: with stages, one wearing wall with a clamped surface and a schedule of
  /// staged and dem-only stages. Nothing runs yet.
  SceneCoupledRun(const CaseParameters& p, std::ostream& log, const RunOptions& options = {});
  /// Every stage (or what is left of them when resuming). Returns 0 when they ran (or the
  /// stages asked by RunOptions::stop_after), 128 + the signal when a signal stopped the run
  /// (after a checkpoint).
  int run();

  const std::vector<StageRecord>& stages() const { return stages_; }
  /// The wearing part (nullptr in a run without stages).
  const fem::WornSample* part() const { return part_.get(); }
  const dem::SceneRun& scene() const { return *scene_; }
  /// [m^3] removed volume asked of the geometry per part label, summed over the staged
  /// stages (part_wear.csv also lists a dem-only stage's amplified wear-law volume, which
  /// changes nothing).
  const std::map<int, double>& removed_per_label() const { return removed_per_label_; }
  std::string checkpoint_path() const { return p_.output.directory + "/checkpoint.h5"; }

private:
  /// A stage left open by a checkpoint: its loads so far and where it ends.
  struct OpenSceneStage {
    dem::WallLoads loads;
    double end = 0; ///< [s]
  };
  /// The part meshed (with stages), the scene set up (its fill settled), the output started;
  /// or, resuming, everything as the checkpoint left it (then returns the open stage).
  std::optional<OpenSceneStage> setup();
  std::optional<OpenSceneStage> resume();
  /// The scene's walls, the part's surface (when there is one) in its place.
  std::vector<dem::SceneWall> scene_walls() const;
  StageRecord begin_stage(std::size_t k) const;
  /// The stage's DEM windows, a record each, their loads on the part summed; none when a
  /// signal stopped the run between two windows (after a checkpoint).
  std::optional<dem::WallLoads> run_dem(StageRecord& r, std::optional<OpenSceneStage> open,
                                        const StopSignals& signals);
  WearIncrement compute_wear(const dem::WallLoads& loads, StageRecord& r) const;
  StageStress solve_stress(const dem::WallLoads& loads, StageRecord& r);
  GeometryUpdate update_geometry(const WearIncrement& increment, const StageStress& stress,
                                 StageRecord& r);
  void record(StageRecord r, const meshes::FaceField<double>& applied);
  /// Writes checkpoint.h5 (the one before kept); `open`: the stage in progress.
  void checkpoint(const OpenSceneStage& open);
  /// The loads a stage starts from: zero on the part's faces (none without a part).
  dem::WallLoads zero_loads() const;

  CaseParameters p_;
  std::ostream& log_;
  RunOptions options_;
  std::string parameters_text_;
  std::vector<Scheme> plan_;
  std::optional<std::size_t> part_wall_; ///< the wearing wall's index in the scene, with stages
  std::unique_ptr<dem::WearLaw> law_;
  std::unique_ptr<fem::WornSample> part_;
  std::unique_ptr<dem::SceneRun> scene_;
  std::unique_ptr<SceneSeries> series_;
  std::unique_ptr<RunOutput> output_;
  std::vector<StageRecord> stages_;
  /// [Pa] the last staged stage's von Mises stress on the part's faces (zeros before the
  /// first): the stress-informed wear law's input to the next stage
  meshes::FaceField<double> previous_stress_;
  std::map<int, double> removed_per_label_;
  std::string part_wear_; ///< part_wear.csv's rows so far
  std::string replaced_;  ///< a run --overwrite moved aside, deleted at the first checkpoint
};

} // namespace wear::coupling

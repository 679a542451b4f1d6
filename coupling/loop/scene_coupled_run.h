#pragma once
// `wearsim scene-run`: a scene's run (docs/coupling.md). Without a wearing part (or without
// Scene/Stage duration) one DEM stage to Scene/End time; with wearing parts, the staged wear
// loop on the user's own equipment. run() reads as the algorithm: per stage, loads = run_dem
// (the DEM's windows, their loads on every part summed) -> each part's stage (wear, stress,
// geometry, its records; coupling/loop/wearing_part.h) -> the worn surfaces to the DEM walls
// with the particles kept -> checkpoint. Between two windows the run checkpoints itself (after
// every stage, every Output/Checkpoint interval, and on SIGINT/SIGTERM/SIGUSR1, then it
// stops), and `--resume` continues bit for bit (same thread count).
// Over MPI ranks (RunOptions::ranks) every rank runs this same loop: the scene's DEM
// decomposed into slabs (dem::SceneRun::set_rank_link), each wearing part worn on every rank's
// own copy (checked the same bit for bit), output and messages on rank 0.
#include "coupling/loop/run_folder.h"
#include "coupling/loop/run_ranks.h"
#include "coupling/loop/stage_record.h"
#include "coupling/loop/stop_signals.h"
#include "coupling/loop/wearing_part.h"
#include "coupling/output/checkpoint.h"
#include "coupling/output/scene_series.h"
#include "coupling/parameters/case_parameters.h"
#include "dem/scene/scene_run.h"
#include "dem/wear/wear_law.h"

#include <memory>
#include <optional>
#include <ostream>
#include <vector>

namespace wear::coupling {

class SceneCoupledRun {
public:
  /// Checks the case: with stages, one or more wearing walls, each with a clamped surface, and
  /// a schedule of staged and dem-only stages, or of reference stages alone. Nothing runs yet.
  SceneCoupledRun(const CaseParameters& p, std::ostream& log, const RunOptions& options = {});
  /// Every stage (or what is left of them when resuming). Returns 0 when they ran (or the
  /// stages asked by RunOptions::stop_after), 128 + the signal when a signal stopped the run
  /// (after a checkpoint).
  int run();

  /// The wearing parts, in the order of Scene/Walls (none in a run without stages).
  const std::vector<WearingPart>& parts() const { return parts_; }
  const dem::SceneRun& scene() const { return *scene_; }
  std::string checkpoint_path() const { return p_.output.directory + "/checkpoint.h5"; }

private:
  /// A stage left open by a checkpoint: its loads on each part so far and where it ends.
  struct OpenSceneStage {
    std::vector<dem::WallLoads> loads; ///< per part, in its frame
    double end = 0;                    ///< [s]
    /// [s] the DEM runs this long on a bed filled anew before the stage begins (a resume from
    /// a checkpoint without its bed); its windows count for no stage
    double warm_up = 0;
  };
  /// The parts meshed, the scene set up (its fill settled), the output started; or,
  /// resuming, everything as the checkpoint left it (then returns the open stage).
  std::optional<OpenSceneStage> setup();
  std::optional<OpenSceneStage> resume();
  /// The resume from a checkpoint without its particle bed (`path`, written at a stage's end,
  /// not `inside` one): the fill on the worn surfaces, and the stage to come with its warm-up.
  OpenSceneStage refill(const std::string& path, bool inside);
  /// The DEM of a bed filled anew run for `duration` [s], each window logged and counted for
  /// nothing; false when a signal stopped it (the checkpoint without the bed stays in place).
  bool warm_up(double duration, const StopSignals& signals);
  StageRecord begin_stage(std::size_t k) const;
  /// The stage's DEM windows, a record each, their loads on each part summed; none when a
  /// signal stopped the run between two windows (after a checkpoint).
  std::optional<std::vector<dem::WallLoads>>
  run_dem(StageRecord& r, std::optional<OpenSceneStage> open, const StopSignals& signals);
  /// Each part's stage under its loads; a part whose surface changed goes to its DEM wall.
  void run_parts(const StageRecord& r, const std::vector<dem::WallLoads>& loads);
  /// The reference scheme: every part's nodes move inside the DEM (SceneRun::move_wall_nodes).
  void move_part_nodes();
  /// The first part the reference scheme distorted, with where ("part 'sample' (inverted face
  /// at ...)"), empty if none.
  std::string distortion() const;
  /// Says why the run stops after this stage when the evaluated part is steady for
  /// Scene/Evaluation/Periods after steady periods; empty otherwise.
  /// The line that ends the run once a part is worn out (Coupling/Worn out when), or empty.
  std::string worn_out_stop() const;
  std::string steady_stop() const;
  /// Writes checkpoint.h5 (the one before kept); `open`: the stage in progress.
  void checkpoint(const OpenSceneStage& open);
  /// The stage that begins now: no loads yet, ending a stage duration on (without wearing
  /// parts: the run's one stage, ending at End time).
  OpenSceneStage next_stage() const;
  /// The loads a stage starts from: zero on each part's faces.
  std::vector<dem::WallLoads> zero_loads() const;
  /// The window's record on rank 0 (over ranks the particles of a snapshot gathered there).
  void record(const dem::SceneWindow& w);

  CaseParameters p_;
  std::ostream silent_{nullptr}; ///< the log of the ranks after the first
  std::ostream& log_;
  RunOptions options_;
  RunRanks ranks_;
  /// The case as the wearing parts see it: over ranks, on the ranks after the first, with
  /// Output/Directory their scratch folder (they mesh and wear there and write nothing else)
  CaseParameters part_case_;
  std::string parameters_text_;
  std::vector<Scheme> plan_;
  bool moves_nodes_ = false; ///< the reference scheme: the parts' nodes move inside the DEM
  std::vector<std::size_t> part_walls_; ///< the wearing walls' indices in the scene, with stages
  std::unique_ptr<dem::WearLaw> law_;
  std::vector<WearingPart> parts_;
  std::unique_ptr<dem::SceneRun> scene_;
  std::unique_ptr<SceneSeries> series_;
  int n_stages_done_ = 0;
  int n_records_ = 0; ///< windows recorded (rank 0 writes them)
  /// the record the scene tables' first row holds (after a continuation without them, the
  /// one after its checkpoint's)
  int first_table_record_ = 1;
  std::string replaced_; ///< a run --overwrite moved aside, deleted at the first checkpoint
};

} // namespace wear::coupling

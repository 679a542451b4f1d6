#pragma once
// `wearsim run`: the coupled DEM-FEM wear loop, one stage at a time (docs/coupling.md).
// run() reads as the algorithm; each step takes the values it needs and returns what it
// made: loads = run_dem -> increment = compute_wear(loads) -> stress = solve_stress(loads)
// -> update = update_geometry(increment, stress) -> record -> checkpoint. Inside run_dem the
// run can stop between two steps (a signal) and checkpoint itself (a signal, or every
// Output/Checkpoint interval), and a resume continues there bit for bit.
#include "coupling/loop/run_ranks.h"
#include "coupling/loop/stage_record.h"
#include "coupling/loop/stage_steps.h"
#include "coupling/loop/stop_signals.h"
#include "coupling/loop/wear_increment.h"
#include "coupling/output/checkpoint.h"
#include "coupling/output/run_output.h"
#include "coupling/parameters/case_parameters.h"
#include "dem/tester/wear_tester.h"
#include "dem/wear/wall_loads.h"
#include "fem/worn_sample.h"
#include "meshes/sample_frame.h"
#include "meshes/stopwatch.h"

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

struct RunOptions {
  bool resume = false;    ///< continue from <output>/checkpoint.h5
  bool progress = true;   ///< live line on a terminal (stderr)
  int stop_after = 0;     ///< stop after this many stages of this invocation (0: run all)
  bool overwrite = false; ///< replace a run in the output folder (kept until the first checkpoint)
  /// The DEM over these ranks (under mpirun; every rank runs the same CoupledRun, rank 0
  /// writes and prints); null: one process.
  dem::RankLink* ranks = nullptr;
};

/// Readies Output/Directory for a run and writes its resolved parameters: a folder holding a
/// run (stages.csv, summary.csv or a checkpoint) is refused unless resuming, or moved aside to
/// `<folder>.replaced` with --overwrite (returned, to be deleted after the new run's first
/// checkpoint; empty if none). Throws naming Output/Directory and the options.
std::string prepare_run_folder(const CaseParameters& p, const RunOptions& options,
                               std::ostream& log);

/// What a run accumulates over its stages; rebuilt from the stage records on resume.
struct RunTotals {
  double cumulative_applied = 0; ///< [m^3] asked of the geometry so far
  double worn_through = 0;       ///< [m^3] asked of worn-through faces and not removed
  /// [m^3] per face, the wear-law volume of a run without a FEM sample (dem-only stages on
  /// a fixed surface), amplified as declared: the cumulative field such runs output.
  meshes::FaceField<double> dem_wear;
  int n_stages_run = 0;     ///< by this invocation
  meshes::Stopwatch clock;  ///< wall time since this invocation's first stage
  double stage_seconds = 0; ///< [s] on that clock when the last stage was recorded

  /// Adds a finished stage's volumes and counts it.
  void add(const StageRecord& r);
  /// Adds a stage's removed volume per face to dem_wear (same faces).
  void add_dem_wear(const meshes::FaceField<double>& removed);
  /// [s] mean wall time of this invocation's stages, 0 before the first.
  double mean_stage_seconds() const;
};

class CoupledRun {
public:
  /// Checks the case and the output folder; nothing runs yet.
  CoupledRun(const CaseParameters& p, std::ostream& log, const RunOptions& options = {});
  CoupledRun(const CoupledRun&) = delete;
  CoupledRun& operator=(const CoupledRun&) = delete;

  /// The whole schedule (or what is left of it when resuming). Returns the exit status: 0
  /// when the schedule (or the stages asked by stop_after) ran, 128 + the signal when a
  /// signal stopped it (after a checkpoint, so that --resume continues).
  int run();

  const std::vector<StageRecord>& stages() const { return stages_; }
  const dem::WearTester& tester() const { return *tester_; }
  const fem::WornSample* sample() const { return sample_.get(); }
  std::string checkpoint_path() const { return p_.output.directory + "/checkpoint.h5"; }

private:
  // setup, in coupled_run_setup.cc; a resume inside a stage returns the open stage
  std::optional<OpenStage> setup();
  /// Returns where a run it replaces (--overwrite) was moved, empty if none.
  std::string prepare_output_folder() const;
  meshes::SurfaceMesh generate_initial_surface() const;
  std::optional<OpenStage> resume();
  void fill_and_settle();
  fem::WornSampleParameters worn_parameters() const;

  // one stage
  StageRecord begin_stage(std::size_t k, const std::optional<OpenStage>& open) const;
  /// The stage's loads; none when a signal stopped the run inside it (then checkpointed).
  std::optional<dem::WallLoads> run_dem(StageRecord& r, std::optional<OpenStage> open,
                                        const StopSignals& signals);
  WearIncrement compute_wear(const dem::WallLoads& loads, StageRecord& r);
  StageStress solve_stress(const dem::WallLoads& loads, StageRecord& r);
  GeometryUpdate update_geometry(const WearIncrement& increment, const StageStress& stress,
                                 StageRecord& r);
  void record(StageRecord r, const meshes::FaceField<double>& applied);
  void checkpoint();
  /// An in-stage checkpoint: the state as it is, the stage's loads so far, nothing restored.
  void checkpoint_inside(const dem::WallLoads& loads, int revolutions_done,
                         double dem_seconds) const;
  Checkpoint capture() const;
  void restore(const Checkpoint& c);
  /// Says where a signal stopped the run (inside stage r, or after it) and how to go on;
  /// returns the exit status.
  int stopped_by(int signal, const StageRecord& r, bool inside) const;

  // over ranks
  bool writer() const { return ranks_.writer(); }
  /// Where this rank's FEM writes its meshes: Output/Directory/mesh on rank 0, a scratch
  /// folder on the others (each rank runs the same FEM stage on its own copy of the sample).
  std::string mesh_directory() const;

  // what the run tells the user
  void print_header() const;
  void print_stage(const StageRecord& r) const;
  void print_geometry_notes(const StageRecord& r, const fem::WearStageReport& report) const;
  void print_end() const;
  std::string progress_text(const StageRecord& r, const dem::TesterProgress& pr,
                            int revolution_in_stage) const;

  const meshes::SurfaceMesh& sample_surface() const; ///< current, sample frame
  meshes::SurfaceMesh stage_surface(Scheme scheme) const;

  CaseParameters p_;
  std::ostream silent_{nullptr}; ///< the log of the ranks after the first
  std::ostream& log_;
  RunOptions options_;
  RunRanks ranks_;
  std::string parameters_text_;
  std::vector<Scheme> plan_; ///< the scheme of each stage
  bool has_staged_ = false, has_reference_ = false;
  meshes::SampleFrame frame_;
  meshes::SurfaceMesh initial_surface_; ///< sample frame, as generated
  std::unique_ptr<dem::WearTester> tester_;
  std::unique_ptr<fem::WornSample> sample_;
  std::unique_ptr<RunOutput> output_;
  std::vector<StageRecord> stages_;
  /// [Pa] the last staged stage's von Mises stress on the current surface's faces (zeros
  /// before the first): the stress-informed wear law's input to the next stage.
  meshes::FaceField<double> previous_stress_;
  RunTotals totals_;
};

} // namespace wear::coupling

#pragma once
// `wearsim scene-run` with a wearing part: the staged wear loop on the user's own equipment
// (docs/coupling.md). run() reads as the algorithm: per stage, loads = run_dem -> increment =
// compute_wear(loads) -> stress = solve_stress(loads) -> update = update_geometry(increment,
// stress) -> record. The part is the scene's wearing wall: its CAD surfaces labelled by role
// (wearing, free, clamped), meshed into tetrahedra by gmsh, worn, moved and remeshed by
// fem::WornSample exactly as the tester's sample; the worn surface goes back to the DEM wall
// with the particles kept.
#include "coupling/loop/stage_steps.h"
#include "coupling/output/run_output.h"
#include "coupling/output/scene_series.h"
#include "coupling/parameters/case_parameters.h"
#include "dem/scene/scene_run.h"
#include "dem/tester/wear_law.h"
#include "fem/worn_sample.h"

#include <map>
#include <memory>
#include <ostream>
#include <vector>

namespace wear::coupling {

class SceneWearRun {
public:
  /// Checks the case: one wearing wall with a clamped surface, a schedule of staged and
  /// dem-only stages. Nothing runs yet.
  SceneWearRun(const CaseParameters& p, std::ostream& log);
  /// Every stage of Coupling/Schedule, each Scene/Stage duration of DEM time. Returns 0.
  int run();

  const std::vector<StageRecord>& stages() const { return stages_; }
  const fem::WornSample& part() const { return *part_; }
  const dem::SceneRun& scene() const { return *scene_; }
  /// [m^3] removed volume asked of the geometry per part label, summed over the staged
  /// stages (part_wear.csv also lists a dem-only stage's amplified wear-law volume, which
  /// changes nothing).
  const std::map<int, double>& removed_per_label() const { return removed_per_label_; }

private:
  /// The part meshed, the scene set up (its fill settled), the output folder started.
  void setup();
  StageRecord begin_stage(std::size_t k) const;
  /// The stage's DEM windows, a record each; their loads on the part summed.
  dem::WallLoads run_dem(StageRecord& r);
  WearIncrement compute_wear(const dem::WallLoads& loads, StageRecord& r) const;
  StageStress solve_stress(const dem::WallLoads& loads, StageRecord& r);
  GeometryUpdate update_geometry(const WearIncrement& increment, const StageStress& stress,
                                 StageRecord& r);
  void record(StageRecord r, const meshes::FaceField<double>& applied);

  CaseParameters p_;
  std::ostream& log_;
  std::vector<Scheme> plan_;
  std::size_t part_wall_ = 0; ///< the wearing wall's index in the scene
  std::unique_ptr<dem::WearLaw> law_;
  std::unique_ptr<fem::WornSample> part_;
  std::unique_ptr<dem::SceneRun> scene_;
  std::unique_ptr<SceneSeries> series_;
  std::unique_ptr<RunOutput> output_;
  int n_records_ = 0;
  std::vector<StageRecord> stages_;
  /// [Pa] the last staged stage's von Mises stress on the part's faces (zeros before the
  /// first): the stress-informed wear law's input to the next stage
  meshes::FaceField<double> previous_stress_;
  std::map<int, double> removed_per_label_;
  std::string rows_; ///< part_wear.csv's rows so far
};

} // namespace wear::coupling

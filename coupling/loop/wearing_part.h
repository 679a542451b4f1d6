#pragma once
// One wearing part of a scene (coupling/loop/scene_coupled_run.h): a wall with Wears = true,
// its CAD surfaces labelled by role (wearing, free, clamped), meshed into tetrahedra and worn,
// moved and remeshed by fem::WornSample. A scene holds any number of them; each has its own
// sample, stress, stage records and output folder (Output/Directory/parts/<wall name>:
// stages.csv, part_wear.csv, history.xdmf with the surface and volume per stage, mesh/), and
// writes and reads its own part of the run's checkpoint. The part Scene/Evaluation names (the
// tester's sample) is also evaluated period by period as the tester's revolutions
// (dem/scene/scene_evaluation.h): summary.csv and history.h5's revolutions in its folder.
#include "coupling/loop/stage_record.h"
#include "coupling/loop/wear_increment.h"
#include "coupling/output/run_output.h"
#include "coupling/output/scene_checkpoint.h"
#include "coupling/parameters/case_parameters.h"
#include "dem/scene/scene_evaluation.h"
#include "dem/scene/scene_walls.h"
#include "dem/wear/reference_deformation.h"
#include "dem/wear/wall_loads.h"
#include "fem/worn_sample.h"
#include "meshes/part_life.h"
#include "meshes/sample_frame.h"
#include "meshes/sample_generator.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// element_life.csv's header: per stage each convex element measured on its unworn footprint
/// (meshes::footprint_standing) and the engine that measured it (the run's own, or that of
/// `wearsim life`, which measures a run's kept surfaces again).
extern const char* const element_life_header;
/// element_life.csv's rows of one stage: `stage_columns` (its stage, equivalent revolutions
/// and hours) and each element's height and volume, measured by this engine.
std::string element_life_rows(const std::string& stage_columns,
                              const std::map<int, meshes::ElementStanding>& standing);

/// The tester's sample (Geometry/Sample) meshed as a run's part first is, with its volume
/// mesh into `msh`.
meshes::GeneratedSample first_sample_mesh(const CaseParameters& p, const std::string& msh);

class WearingPart {
public:
  /// Meshes scene wall `wall` (index `index` among the scene's walls) into tetrahedra and
  /// gives the wall that mesh's boundary, so that DEM faces and FEM boundary faces are the
  /// same triangles. Logs what it made.
  /// `writes`: the part writes its tables and series (over ranks rank 0 only; every rank
  /// meshes and wears its own copy, in the folders `p` names).
  WearingPart(const CaseParameters& p, std::size_t index, dem::SceneWall& wall, std::ostream& log,
              bool writes = true);
  /// Writes the unworn surface as stage 0 at scene time `time` [s] (once the scene is set up).
  void record_initial(double time);
  /// The part as checkpoint part `c` left it (its output folder as it stood then).
  WearingPart(const CaseParameters& p, std::size_t index, const PartCheckpoint& c,
              bool writes = true);

  std::size_t wall() const { return wall_; } ///< index among the scene's walls
  const std::string& name() const { return name_; }
  const fem::WornSample& sample() const { return *sample_; }
  /// The part's surface in its own frame, where its FEM works: the wall's (a moving wall's
  /// body frame), or the tester's sample's own (Geometry/Sample).
  const meshes::SurfaceMesh& surface() const { return sample_->surface(); }
  /// The surface in the DEM wall's frame (the sample placed by Geometry/Placement).
  meshes::SurfaceMesh wall_surface() const;
  /// A window's loads on the wall (its frame, SceneRun::wall_loads) in the part's own frame.
  dem::WallLoads own_loads(const dem::WallLoads& wall_loads) const;
  const std::vector<StageRecord>& stages() const { return stages_; }
  /// [m^3] removed volume asked of the geometry per label, summed over the staged stages
  /// (part_wear.csv also lists a dem-only stage's amplified wear-law volume, which changes
  /// nothing).
  const std::map<int, double>& removed_per_label() const { return removed_per_label_; }
  /// Where the part writes: Output/Directory/parts/<name>.
  const std::string& directory() const { return directory_; }
  /// The evaluation Scene/Evaluation asks of this part (the tester's sample), or null.
  const dem::SceneEvaluation* evaluation() const { return evaluation_.get(); }

  /// After window w of the scene, its loads on the part (`window`) and its
  /// wall time [s]: the evaluation's sample and, at a period's end, its record (every rank
  /// calls it together). Nothing without an evaluation.
  void observe(const dem::SceneRun& scene, const dem::SceneWindow& w, const dem::WearLaw& law,
               const dem::WallLoads& window, double wall_seconds);

  /// Stage r (its number, scheme, amplification, time and DEM figures set) under the loads
  /// the DEM summed on the part (part frame): the wear increment; for a staged stage the
  /// stress under those loads, the geometry update and the new surface handed to `to_wall`
  /// (in the wall's frame; it says which particles it pushed out); for a reference stage the
  /// surface the DEM moved (`moved`, the wall's node moves; null otherwise). Records the
  /// stage and writes its output.
  void run_stage(StageRecord r, const dem::WallLoads& loads, const CaseParameters& p,
                 std::ostream& log,
                 const std::function<dem::PushReport(const meshes::SurfaceMesh&)>& to_wall,
                 const dem::ReferenceDeformation* moved = nullptr);
  /// Why the part is worn out by Coupling/Worn out when (figures of its current surface,
  /// meshes/part_life.h), or empty while it is not (or the criterion is never).
  std::string worn_out(const CouplingParameters& c) const;
  /// [h] laboratory hours its stages stand for (Coupling/Hours per revolution; 0 unstated).
  double equivalent_hours(const CouplingParameters& c) const;
  /// What the part's stages cost per phase, its remeshes and its worn-through volume, for the
  /// end of a run.
  std::string summary_text() const;
  /// The part's checkpoint part; `open`: the open stage's loads summed so far.
  PartCheckpoint state(const dem::WallLoads& open) const;

private:
  std::size_t wall_;
  std::string name_, directory_;
  std::optional<meshes::SampleFrame> frame_; ///< the tester's sample's own frame, or none
  std::unique_ptr<fem::WornSample> sample_;
  std::unique_ptr<RunOutput> output_;
  std::unique_ptr<dem::SceneEvaluation> evaluation_; ///< the tester's evaluation, or none
  bool writes_ = true;
  std::vector<StageRecord> stages_;
  /// [Pa] the last staged stage's von Mises stress on the part's faces (zeros before the
  /// first): the stress-informed wear law's input to the next stage
  meshes::FaceField<double> previous_stress_;
  std::map<int, double> removed_per_label_;
  /// [m^3] per face, the volume the reference stages moved the DEM's nodes by (declared,
  /// amplified), on the faces of surface(); empty before a reference stage
  std::vector<double> moved_volume_;
  std::string wear_rows_; ///< part_wear.csv's rows so far
  std::string life_rows_; ///< part_life.csv's rows so far
  /// [m] the convex elements' outlines on the first mesh, on which element_life.csv measures
  /// them (empty: no elements, or resumed from an engine older than them)
  meshes::ElementFootprints footprints_;
  std::string element_rows_; ///< element_life.csv's rows so far

  /// The evaluation Scene/Evaluation asks of this part (the tester's sample), on its surface
  /// in its own frame.
  void make_evaluation(const CaseParameters& p);
  /// What a stage did to the part after its wear increment, whatever its scheme.
  struct StageChange {
    meshes::SurfaceMesh surface;       ///< the surface the stage ends on (part frame)
    meshes::FaceField<double> applied; ///< [m^3] the stage's volume per face of `surface`
    std::vector<double> cumulative;    ///< [m^3] per face, removed since the start
    std::vector<double> depth;         ///< [m] per face, wear depth since the start
    bool changes_geometry = false;     ///< the surface moved (staged, reference)
    std::string note;                  ///< the scheme's part of the stage's line
    bool stress_solved = false;        ///< previous_stress_ is this stage's
  };
  // One per scheme (Coupling/Schedule): what the stage does after the increment.
  StageChange dem_only_stage(const WearIncrement& increment) const;
  StageChange
  staged_stage(const WearIncrement& increment, const dem::WallLoads& loads, const CaseParameters& p,
               std::ostream& log,
               const std::function<dem::PushReport(const meshes::SurfaceMesh&)>& to_wall,
               StageRecord& r);
  /// Says what the geometry update of stage r did beyond the recession (relaxation halved,
  /// restoring offset held or short, remesh attempts refused).
  void log_geometry_notes(const StageRecord& r, const fem::WearStageReport& report,
                          std::ostream& log) const;
  /// The record's figures from the DEM's node moves `moved`, the stage's volume added to
  /// moved_volume_; the moved surface in the part's frame.
  StageChange reference_stage(const dem::ReferenceDeformation& moved,
                              const WearIncrement& increment, StageRecord& r);
  /// The stage's output, record, tables, volume per label, life and line.
  void record_stage(StageRecord r, const StageChange& change, const CouplingParameters& c,
                    std::ostream& log);
  /// part_life.csv's rows of stage `stage` (recorded) on `surface`.
  void record_life(int stage, const meshes::SurfaceMesh& surface, const CouplingParameters& c);
  /// The part's tables: stages.csv, history.h5 and, evaluated, summary.csv.
  void write_tables() const;
};

/// Output/Directory/parts/<name>: a wearing part's folder.
std::string part_directory(const CaseParameters& p, const std::string& name);

} // namespace wear::coupling

#pragma once
// A scene run's own part of a checkpoint (`wearsim scene-run`,
// coupling/loop/scene_coupled_run.h), between two of its windows: where the scene stands
// beside the engine's state, and each wearing part's own state (coupling/loop/wearing_part.h).
#include "coupling/output/checkpoint_arrays.h"
#include "dem/scene/flux_plane.h"
#include "dem/scene/inlet.h"
#include "dem/scene/scene_evaluation.h"
#include "dem/scene/scene_run.h"
#include "dem/wear/reference_deformation.h"
#include "meshes/part_life.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace wear::coupling {

/// A wearing part between two windows: its worn sample, the last staged stage's stress, its
/// stage records, its removed volume per label and the open stage's summed loads on it.
struct PartCheckpoint {
  fem::WornSampleState sample;
  std::vector<double> face_von_mises; ///< [Pa] per face of the part's surface (last stage)
  std::vector<StageRecord> stages;
  std::vector<int> labels;               ///< the part's labels with removed volume so far
  std::vector<double> removed_per_label; ///< [m^3] per label above (staged stages)
  OpenStage open;                        ///< the open stage's loads (part frame)
  /// The part's evaluation (Scene/Evaluation), or none
  std::optional<dem::SceneEvaluationState> evaluation;
  /// The part is the tester's sample, kept in its own frame (the sample's state and loads)
  bool sample_frame = false;
  /// [m^3] per face, the volume the reference stages moved the DEM's nodes by (declared);
  /// empty before a reference stage
  std::vector<double> moved_volume;
  /// [m] its convex elements' outlines on the first mesh (element_life.csv); empty for a part
  /// without elements or from an engine older than them
  meshes::ElementFootprints footprints;
};

struct SceneCheckpoint {
  double time = 0;      ///< [s] scene time
  double stage_end = 0; ///< [s] where the open stage (or the run) ends
  int n_records = 0;    ///< windows recorded so far
  /// the record the scene tables' first row holds: 1, or the record after the checkpoint a
  /// run continued from without its tables (it started them again there)
  int first_table_record = 1;
  std::uint64_t n_removed = 0; ///< particles the outlets took
  std::vector<dem::InletState> inlets;
  std::vector<double> outlet_mass;          ///< [kg] per outlet
  std::vector<std::uint64_t> outlet_counts; ///< per outlet
  std::vector<dem::FluxPlaneState> flux_planes;
  std::vector<PartCheckpoint> parts; ///< in the order of the scene's wearing walls
  /// Over ranks: the slabs' cuts [m or rad] (n_ranks + 1) the DEM parts were written on;
  /// empty from one process
  std::vector<double> rank_bounds;
  /// The node moves of the reference scheme, per wall whose nodes move (none otherwise)
  std::vector<dem::ReferenceDeformationState> node_moves;
};

/// The scene's own part of a checkpoint from the scene run's state `s` at the open stage's
/// end `stage_end` [s] after `n_records` records, its tables' first row record
/// `first_table_record` (no wearing part: the caller adds them).
SceneCheckpoint scene_checkpoint(const dem::SceneRunState& s, double stage_end, int n_records,
                                 int first_table_record = 1);
/// The scene run's state that checkpoint part `s` with the engine state `system` holds.
dem::SceneRunState scene_run_state(const SceneCheckpoint& s, const dem::SystemState& system);

/// Writes s under /scene: /scene/progress, outlets, inlet_<k>, flux_plane_<k>, part_<k>.
void write_scene(Hdf5File& h5, const SceneCheckpoint& s);
/// Throws naming what is missing or inconsistent.
SceneCheckpoint read_scene(const Hdf5Reader& h5);

} // namespace wear::coupling

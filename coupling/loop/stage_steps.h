#pragma once
// The FEM steps of a staged stage of a wearing part (wearing_part.h, scene_coupled_run.h): the
// stress of the part under the stage-averaged
// face loads, and the geometry update that applies the stage's removed volume. Each takes
// the values it needs, fills the stage's record and returns what it made.
#include "coupling/loop/stage_record.h"
#include "coupling/loop/wear_increment.h"
#include "coupling/output/run_output.h"
#include "dem/wear/wall_loads.h"
#include "fem/elasticity.h"
#include "fem/worn_sample.h"
#include "meshes/face_field.h"
#include "meshes/vtu_writer.h"

namespace wear::coupling {

/// The FEM's answer to a stage's loads, on the surface before the geometry update.
struct StageStress {
  /// [Pa] ball-averaged at each surface face's centroid (intensive; fem/stress_measures.h)
  meshes::FaceField<double> von_mises;
};

/// A staged stage's fields carried onto the surface after the geometry update.
struct GeometryUpdate {
  meshes::FaceField<double> applied;   ///< [m^3] the stage's removed volume (extensive)
  meshes::FaceField<double> von_mises; ///< [Pa] the stage's stress (intensive)
  fem::WearStageReport report;         ///< what the update did
};

/// Elastic stress of `sample` under the forces F_f = I_f / T of the loads' traction impulse
/// (zero when the window is empty), with `ep`; the volume with its displacement and stress
/// goes to `output` as stage r.stage at r.time. Fills the record's stress, force and
/// displacement figures (mean_force_z, wear_face_*: in the sample's frame) and times.
StageStress solve_stage_stress(const fem::WornSample& sample, const dem::WallLoads& loads,
                               const fem::ElasticityParameters& ep, RunOutput& output,
                               StageRecord& r);

/// Applies the increment to `sample` (recession, mesh motion, remeshing) and carries the
/// stage's removed volume and stress onto the new surface (FaceTransfer after a remesh).
/// Fills the record's geometry figures.
GeometryUpdate apply_stage_wear(fem::WornSample& sample, const WearIncrement& increment,
                                const StageStress& stress, StageRecord& r);

/// The increment's figures in the record (amplification, volumes, depth); but for a reference
/// stage the cumulative volume from `cumulative_before` [m^3]; for a staged stage also the
/// applied volume and the depth cap check (throws naming the parameters).
void record_increment(const WearIncrement& w, double cumulative_before, const CouplingParameters& p,
                      StageRecord& r);

} // namespace wear::coupling

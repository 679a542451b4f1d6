#pragma once
// One increment of a wear stage on the sample's surface (WornSample::apply_wear): the share
// of the remaining wear it takes, the relaxation of the surface before it, its volume-exact
// recession, and what the stage does next with the moved surface: take it, or retry with
// less relaxation, smaller increments, or the wear spread around a fold.
#include "fem/worn_sample.h"
#include "meshes/mesh_quality.h"
#include "meshes/recession.h"
#include "meshes/surface_mesh.h"

#include <string>
#include <vector>

namespace wear::fem {

/// How a stage is divided into increments, as it goes.
struct StageSplit {
  int n_left = 1;     ///< increments of the current size still to take
  int halvings = 0;   ///< the current size is 1 / 2^halvings of the stage
  int spreadings = 0; ///< spreading steps taken at the current size
  /// Fraction of the relaxations applied. The umbrella offsets of a graded mesh (a remesh
  /// refines where the surface curves) can be large next to small triangles, and moving every
  /// vertex at once can turn one of them over whatever the increment; then the relaxation, not
  /// the recession, folds the surface, and it is halved for the rest of the stage.
  double relax = 1;
};

/// One increment proposed on the current surface.
struct StageIncrement {
  std::vector<double> part;               ///< [m^3] per face: the remaining wear / n_left
  double part_sum = 0;                    ///< [m^3]
  std::vector<char> worn_vertex;          ///< vertices of the faces with part > 0
  std::vector<meshes::Vec3> displacement; ///< [m] relaxation (+ recession once receded)
  meshes::SurfaceMesh relaxed;            ///< the surface after the relaxation
  double relaxation_loss = 0;             ///< [m^3] enclosed volume the relaxation removes
  meshes::Recession recession;            ///< of the relaxed surface (once receded)
  meshes::SurfaceMesh moved;              ///< after relaxation and recession (once receded)
};

/// Height of the clamped bottom in the sample frame (its highest vertex; the bottom is flat),
/// or -infinity for a surface without one. [m]
double bottom_height(const meshes::SurfaceMesh& s);

/// Faces worn down to the clamped bottom have no material left: a wearing face with a vertex
/// below `floor_z` [m] gives what is left of its wear (`remaining`, zeroed) to
/// r.worn_through_volume, and r.n_worn_through counts these faces.
void set_aside_worn_through(const meshes::SurfaceMesh& s, double floor_z,
                            std::vector<double>& remaining, WearStageReport& r);

/// The increment's share of the remaining wear (remaining / n_left) and the surface relaxed
/// before its recession: tangential in the worn region, unworn surface and crease, each
/// scaled by `relax`, spikes cut unless that removes more than a quarter of the increment.
StageIncrement relaxed_increment(const meshes::SurfaceMesh& s, const std::vector<double>& remaining,
                                 int n_left, double relax);

/// True when the relaxation alone removes the whole increment: the recession would have
/// nothing left to scale (and the increment would remove more than asked).
bool relaxation_removes_increment(const StageIncrement& inc, double relax);

/// Recedes the relaxed surface by what the relaxation left of the increment's volume, so the
/// enclosed volume drops by exactly part_sum: fills recession and moved, adds to displacement.
void recede(StageIncrement& inc);

enum class NextStep {
  take,             ///< the moved surface is fit to hand on
  relax_less,       ///< the relaxation alone folds the surface
  halve,            ///< smaller increments: short of the volume, or past the worn-through layer
  spread,           ///< spread the remaining wear around the fold
  halve_after_fold, ///< smaller increments where spreading did not help; spread again there
  missed_volume,    ///< short of the volume even at the smallest increment: give up
  folds,            ///< folds even at the smallest increment: give up
};

struct Verdict {
  NextStep step = NextStep::take;
  meshes::SurfaceQuality quality; ///< of the moved surface (not set for missed_volume)
};

/// What the stage does with a receded increment on surface `s`; `floor_z` as for
/// set_aside_worn_through.
Verdict judge_increment(const meshes::SurfaceMesh& s, const StageIncrement& inc, double floor_z,
                        const StageSplit& split, const WornSampleParameters& p);

/// The error of a stage whose recession stays short of the asked volume even at the smallest
/// increment (`n_taken` increments taken before).
std::string missed_volume_message(const meshes::Recession& rec, int halvings, int n_taken);

/// The error of a stage whose surface folds even at the smallest increment; `dump` names the
/// files the surfaces before and after were written to.
std::string fold_message(const meshes::SurfaceMesh& s, const meshes::SurfaceQuality& quality,
                         int halvings, int n_taken, const std::string& dump);

} // namespace wear::fem

#pragma once
// The wear tester's evaluation as an observer of a scene (Scene/Evaluation): the scene's sample
// (a wall with Source = sample) evaluated per period as the built-in tester evaluates it per
// revolution (dem/evaluation/tester_evaluation.h): wear per column and convex element, normal
// force, bottom-layer speed and spin, speed over the sample, bed height, the coefficients of
// variation that judge steady state and the wear fits. A period's samples are the scene's
// windows (its records), so the tester written as a scene (dem/tester/tester_scene.h) samples
// as the built-in tester does: Samples per revolution a revolution.
#include "dem/evaluation/tester_evaluation.h"
#include "dem/scene/scene_run.h"
#include "dem/wear/wear_law.h"
#include "meshes/geometry_parameters.h"

#include <vector>

namespace wear::dem {

/// What an evaluation carries between two windows, bit for bit (a checkpoint's part).
struct SceneEvaluationState {
  std::vector<RevolutionRecord> history; ///< one record per finished period
  RevolutionSamples samples;             ///< the open period's samples
  int n_windows = 0;                     ///< windows of the open period so far
  /// [m^3], [N s] per face of the wall since the open period began: the wear law's volume
  /// and the normal impulse, as the samples take them (cumulative over the period)
  std::vector<double> removed, normal_impulse;
  /// [m^3] per face since the open period began, as the window loads lay it on the faces
  /// (DEM/Wear field): the period's wear, as the built-in tester's revolution closes
  std::vector<double> wear_volume;
  double contact_total = 0;  ///< [m^3] the wear law's volume from the per-contact totals
  double wall_seconds = 0;   ///< [s] wall time of the open period's windows
  double particle_steps = 0; ///< [-] particle-steps of the open period's windows
};

class SceneEvaluation {
public:
  /// Evaluates wall `wall` of the scene, the tester's sample, whose surface `sample` is given
  /// in the sample's own frame (face order as the DEM wall's), with the tester geometry `g`
  /// (its sample and placement) and the bottom layer's diameter `layer_diameter` [m] (the
  /// size distribution's mean).
  SceneEvaluation(const SceneParameters& scene, const meshes::GeometryParameters& g,
                  double layer_diameter, std::size_t wall, const meshes::SurfaceMesh& sample);

  /// After window w: its integrals on the wall (w.wearing), `wear_volume` [m^3] the window's
  /// loads' wear volume on the wall's faces, `wall_seconds` [s] the window's wall time. Takes
  /// a sample of the particles over the sample (over ranks gathered on every rank: every rank
  /// calls it together) and closes a record at the period's last window.
  void observe(const SceneRun& scene, const SceneWindow& w, const WearLaw& law,
               const std::vector<double>& wear_volume, double wall_seconds);
  /// The wall's new surface (the sample's frame; between two periods): columns and labels
  /// derived anew, the records kept.
  void set_surface(const meshes::SurfaceMesh& sample);

  const std::vector<RevolutionRecord>& history() const { return evaluation_.history(); }
  int n_columns() const { return evaluation_.n_columns(); }
  const std::vector<int>& element_labels() const { return evaluation_.element_labels(); }

  SceneEvaluationState state() const;
  /// Continues from a state() of the same evaluation (same wall surface).
  void resume(const SceneEvaluationState& s);

private:
  std::size_t wall_;
  int n_samples_; ///< windows per period
  TesterEvaluation evaluation_;
  SceneEvaluationState open_; ///< the open period's sums (its samples live in evaluation_)
  /// The sums of a period not yet begun, on `n_faces` faces.
  void open_period(std::size_t n_faces);
};

} // namespace wear::dem

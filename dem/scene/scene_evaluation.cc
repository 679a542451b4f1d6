// The tester's evaluation of a scene's sample, period by period (scene_evaluation.h).
//
// A period of n = Period / Output interval windows is one record, as a revolution of
// Samples per revolution samples is in the built-in tester. At the end of each window the
// evaluation samples the particles over the sample with the wear-law volume V_f and the
// normal impulse I_f per face summed since the period began (the wear laws are a coefficient
// times one window integral, so the sum of the windows' volumes is the volume of the summed
// integrals); the period's record takes the wear volume as the windows' loads lay it on the
// faces (DEM/Wear field), summed, and the per-contact total. Records and samples are the
// tester's (dem/evaluation/tester_evaluation.h): columns, elements and the bed are read in the
// sample's own frame (Geometry/Sample, Geometry/Placement), in which the caller gives the
// sample's surface. When the reference scheme moves the sample's nodes, a record carries the
// moves' figures as the tester's revolutions do (swept, applied and enclosed volume, smallest
// angle, the first distortion; cumulative).
#include "dem/scene/scene_evaluation.h"

#include "dem/engine/rank_link.h"

#include <cmath>
#include <stdexcept>

namespace wear::dem {

SceneEvaluation::SceneEvaluation(const SceneParameters& scene, const meshes::GeometryParameters& g,
                                 double layer_diameter, std::size_t wall,
                                 const meshes::SurfaceMesh& sample)
    : wall_(wall), n_samples_(int(std::lround(scene.evaluation.period / scene.output_interval))),
      evaluation_(sample, g.sample, g.placement, layer_diameter, scene.evaluation.steady_threshold,
                  scene.evaluation.steady_periods) {
  open_period(sample.n_faces());
}

void SceneEvaluation::observe(const SceneRun& scene, const SceneWindow& w, const WearLaw& law,
                              const std::vector<double>& wear_volume, double wall_seconds) {
  const std::size_t nf = open_.removed.size();
  if (wear_volume.size() != nf)
    throw std::logic_error("SceneEvaluation: the window's wear volume is not on the evaluated "
                           "wall's faces");
  if (open_.n_windows == 0)
    evaluation_.begin_revolution(w.t_begin);
  if (const auto at = w.wearing.find(wall_); at != w.wearing.end()) {
    const auto removed = law.removed_volume(at->second);
    for (std::size_t f = 0; f < nf; ++f) {
      open_.removed[f] += removed[f];
      open_.normal_impulse[f] += at->second.normal_impulse[f];
    }
    open_.contact_total += law.total_removed_volume(at->second);
  }
  for (std::size_t f = 0; f < nf; ++f)
    open_.wear_volume[f] += wear_volume[f];
  open_.wall_seconds += wall_seconds;
  open_.particle_steps +=
      std::round((w.t_end - w.t_begin) / scene.system().time_step()) * double(w.n_particles);
  ++open_.n_windows;

  const meshes::SurfaceMesh& placed = scene.walls().at(wall_).surface.mesh;
  const System& system = scene.system();
  BedGrains grains = evaluation_.grains(system.particles, &system.clumps(), placed);
  if (RankLink* link = system.rank_link(); link && link->n_ranks() > 1) {
    std::vector<double> all; // every rank's grains, in rank order
    link->gather_in_rank_order(grains.packed(), all);
    grains = BedGrains{};
    grains.append_packed(all);
  }
  evaluation_.sample(grains, w.t_end, open_.removed, open_.normal_impulse);

  if (open_.n_windows < n_samples_)
    return;
  RevolutionRecord& r = evaluation_.end_revolution(w.t_end, open_.wear_volume, open_.contact_total);
  r.wall_seconds = open_.wall_seconds;
  r.particle_steps_per_second =
      open_.wall_seconds > 0 ? open_.particle_steps / open_.wall_seconds : 0;
  if (const WallNodeMoves* moves = scene.node_moves(wall_)) { // cumulative, as the tester's
    const ReferenceDeformation& d = moves->deformation();
    r.swept_volume = d.swept_volume();
    r.applied_volume = d.applied_volume();
    r.enclosed_volume_loss = d.enclosed_volume_loss();
    r.min_angle_deg = d.quality().min_angle_deg;
    r.distortion = d.distortion_text();
  }
  open_period(nf);
}

void SceneEvaluation::open_period(std::size_t n_faces) {
  open_ = SceneEvaluationState{};
  open_.removed.assign(n_faces, 0);
  open_.normal_impulse.assign(n_faces, 0);
  open_.wear_volume.assign(n_faces, 0);
}

void SceneEvaluation::set_surface(const meshes::SurfaceMesh& sample) {
  if (open_.n_windows != 0)
    throw std::logic_error("SceneEvaluation: a new surface inside a period");
  evaluation_.set_surface(sample);
  open_period(sample.n_faces());
}

SceneEvaluationState SceneEvaluation::state() const {
  SceneEvaluationState s = open_;
  s.history = evaluation_.history();
  s.samples = evaluation_.open_samples();
  return s;
}

void SceneEvaluation::resume(const SceneEvaluationState& s) {
  const std::size_t nf = open_.removed.size();
  if (s.removed.size() != nf || s.normal_impulse.size() != nf || s.wear_volume.size() != nf)
    throw std::invalid_argument("checkpoint: the evaluation's sums are not on the evaluated "
                                "wall's " +
                                std::to_string(nf) + " faces");
  if (s.n_windows < 0 || s.n_windows >= n_samples_)
    throw std::invalid_argument("checkpoint: the evaluation's open period holds " +
                                std::to_string(s.n_windows) + " windows, a period " +
                                std::to_string(n_samples_));
  open_ = s;
  open_.history.clear();
  open_.samples = {};
  evaluation_.history() = s.history;
  if (s.n_windows > 0)
    evaluation_.resume_samples(s.samples);
}

} // namespace wear::dem

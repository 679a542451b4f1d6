// A scene over MPI ranks (SceneRun::set_rank_link; docs/dem.md, "A scene over ranks").
//
// The engine decomposes a bed into one slab per rank along one coordinate (SlabCuts: x, y, z,
// or the angle about z). A scene names the coordinate (Scene/Rank slabs along; auto: its
// period's, or x) and where the cuts go (Scene/Rank slabs):
//   uniform   n equal slabs of the range: the domain along the axis, the periodic sector, or
//             the full circle (-pi, pi] for angular slabs without a sector;
//   balanced  cuts at the quantiles of the particles' coordinate when the engine first sets
//             up (SlabDecomposition::balanced_slabs over a histogram of 1024 bins of the
//             range): each rank starts with as many particles. Every rank holds the same bed
//             then (the fill, or the first inlet batch, drawn alike on every rank), so the
//             histogram, hence the cuts, are the same everywhere without a message.
// The cuts travel with the run's checkpoints: a resume on as many ranks takes them back and
// continues bit for bit; on another count the merged bed is cut anew. When the bed flows
// away from its cuts (a bin draining, a heap moving along a chute), the run is rebalanced
// (rebalanced()): the ranks' parts merged into the whole bed and cut balanced anew, as a resume
// on another rank count would. Its trigger is the particle count, the largest rank's over the
// mean (rank_imbalance), not a measured time: the same inputs then rebalance on the same step
// of every repetition, and a run stays bit for bit reproducible.
// Angular slabs are measured against the interaction reach as arcs at the smallest distance
// from the z axis that a particle has at set-up (an annulus' inner wall keeps them outside it).
//
// Everything the scene reports is the whole scene's on every rank: window integrals summed
// over the ranks in rank order, counts of outlets and flux planes summed per exchange, a batch
// drawn from every rank's particles near the inlet.
#include "dem/scene/scene_run.h"

#include "dem/engine/rank_states.h"

#include "meshes/constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

namespace {
constexpr std::size_t histogram_bins = 1024;

int slab_axis(const std::string& along) {
  return along == "y" ? 1 : along == "z" ? 2 : 0;
}
} // namespace

std::pair<double, double> SceneRun::rank_range() const {
  if (rank_slab_axis(scene_) == "angle")
    return scene_.periodic_angle_deg > 0 ? std::pair{0.0, scene_.periodic_angle_deg * pi / 180}
                                         : std::pair{-pi, pi};
  const int a = slab_axis(rank_slab_axis(scene_));
  if (scene_.periodic_direction != "none")
    return {scene_.periodic_from, scene_.periodic_to};
  return {scene_.domain_min[std::size_t(a)], scene_.domain_max[std::size_t(a)]};
}

void SceneRun::set_rank_link(RankLink* link) {
  link_ = link && link->n_ranks() > 1 ? link : nullptr;
  if (!link_) {
    system_.set_rank_link(nullptr, nullptr);
    return;
  }
  const bool ring = rank_ring(scene_);
  if (link->ring() != ring)
    throw std::logic_error(std::string("SceneRun over ranks: the ranks must form a ") +
                           (ring ? "ring (angular slabs or a periodic scene)" : "line"));
  const auto [lo, hi] = rank_range();
  use_rank_slabs(SlabDecomposition::uniform_slabs(lo, hi, link->n_ranks()));
}

void SceneRun::use_rank_slabs(std::vector<double> bound) {
  RankLink* link = rank_link();
  if (!link)
    return;
  if (rank_slab_axis(scene_) == "angle") {
    // The arcs are measured at the smallest distance from the axis a particle has now.
    double r = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < system_.particles.n_real; ++i)
      r = std::min(r, std::hypot(system_.particles.position[i].x, system_.particles.position[i].y));
    r = -r;
    link->max_over_ranks(&r, 1);
    slabs_ = SlabDecomposition::angular(std::move(bound), std::max(0.0, -r));
  } else {
    slabs_ = SlabDecomposition::along_axis(slab_axis(rank_slab_axis(scene_)), std::move(bound));
  }
  system_.set_rank_link(link, &slabs_);
}

void SceneRun::fit_rank_slabs(bool always_balanced) {
  RankLink* link = rank_link();
  if (!link)
    return;
  const auto [lo, hi] = rank_range();
  if (scene_.rank_slabs == "uniform" && !always_balanced) {
    use_rank_slabs(SlabDecomposition::uniform_slabs(lo, hi, link->n_ranks()));
    return;
  }
  // The slab coordinate as the engine takes it (an angle in the range of the cuts).
  SlabCuts range;
  range.angular = rank_slab_axis(scene_) == "angle";
  range.axis = slab_axis(rank_slab_axis(scene_));
  range.bound = {lo, hi};
  std::vector<double> count(histogram_bins, 0.0);
  const auto& p = system_.particles;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const double u = (range.coordinate(p.position[i]) - lo) / (hi - lo);
    const auto bin = std::size_t(std::clamp(u, 0.0, 1.0) * double(histogram_bins));
    count[std::min(bin, histogram_bins - 1)] += 1;
  }
  use_rank_slabs(SlabDecomposition::balanced_slabs(count, lo, hi, link->n_ranks()));
}

double SceneRun::rank_imbalance() const {
  RankLink* link = rank_link();
  if (!link || !engine_ready())
    return 1;
  const double n = double(system_.particles.n_real);
  double most = n, total = n;
  link->max_over_ranks(&most, 1);
  link->sum_in_rank_order(&total, 1);
  return total > 0 ? most * link->n_ranks() / total : 1;
}

std::unique_ptr<SceneRun> SceneRun::rebalanced() const {
  RankLink* link = rank_link();
  if (!link || !engine_ready())
    throw std::logic_error("SceneRun::rebalanced: a scene over ranks with its engine set up");
  SceneRunState whole = state();
  whole.system = whole_state_on_every_rank(whole.system, *link);
  whole.rank_bounds.clear();
  auto next = std::make_unique<SceneRun>(scene_, dem_, walls_, impact_);
  next->set_rank_link(link);
  next->cut_balanced_ = true;
  next->node_moves_ = node_moves_; // walls_ hold their moved surfaces
  next->resume(whole);
  return next;
}

std::string SceneRun::rank_layout() const {
  const RankLink* link = rank_link();
  std::ostringstream s;
  s << "over " << (link ? link->n_ranks() : 1) << " MPI rank(s)";
  if (!link)
    return s.str();
  const bool angle = rank_slab_axis(scene_) == "angle";
  s << ": " << scene_.rank_slabs << " slabs along " << rank_slab_axis(scene_);
  if (!engine_ready() && scene_.rank_slabs == "balanced")
    return s.str() + ", cut when the first particles arrive";
  s << " at";
  for (const double b : slabs_.cuts().bound)
    s << " " << (angle ? b * 180 / pi : b);
  s << (angle ? " deg" : " m");
  return s.str();
}

Particles SceneRun::particles_on_first_rank() const {
  return gather_particles(system_.particles, rank_link(), GatherTo::first_rank);
}

} // namespace wear::dem

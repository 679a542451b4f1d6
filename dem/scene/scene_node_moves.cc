// A scene's walls whose nodes move inside the DEM: the reference (node-moving) method on any
// wearing wall that keeps its place (scene_run.h, wall_node_moves.h).
//
// The engine's steps are run in chunks that end on every multiple of the update interval
// (counted in the engine's steps, which a resume restores, so the moves fall on the same steps),
// where the moving walls' nodes move by their window's wear so far; advance() moves them once
// more at a window's end, so that a window's moves add up to its amplified wear-law volume. The
// scene's copy of such a wall's surface follows the moves, so that its loads are laid on the
// moved faces and a rebalanced or resumed scene builds the wall as it stands.
#include "dem/scene/scene_run.h"

#include <algorithm>
#include <stdexcept>

namespace wear::dem {

void SceneRun::run_steps(std::uint64_t n) {
  while (n > 0) {
    // one update interval for every moving wall (move_wall_nodes)
    const std::uint64_t k =
        node_moves_.empty() ? n : std::min(n, node_moves_.front().steps_to_move(system_.n_steps()));
    system_.run(k);
    n -= k;
    if (!node_moves_.empty() && system_.n_steps() % node_moves_.front().every() == 0)
      move_nodes();
  }
}

void SceneRun::move_nodes() {
  for (auto& m : node_moves_)
    walls_[std::size_t(m.wall())].surface.mesh = m.move(system_);
}

void SceneRun::move_wall_nodes(std::size_t k, const WearLawParameters& law, std::uint64_t every,
                               double amplification) {
  const SceneWallParameters& wall = walls_.at(k).parameters;
  if (!wall.wears || system_.wall_kind(int(k)) != WallKind::mesh)
    throw std::invalid_argument(scene_wall_path(wall) + ": the node-moving method moves a "
                                                        "wearing wall's triangles (Wears = true)");
  if (system_.wall(int(k)).moving()) // its nodes are the body frame's, posed by the motion
    throw std::invalid_argument(scene_wall_path(wall) +
                                "/Motion: the node-moving method moves "
                                "the nodes of a wall that keeps its place (fixed, or a surface "
                                "motion), not of one that moves as a whole");
  if (!node_moves_.empty() && every != node_moves_.front().every())
    throw std::logic_error("SceneRun::move_wall_nodes: one update interval for every wall");
  node_moves_.emplace_back(int(k), walls_[k].surface.mesh, law, every, amplification);
}

const WallNodeMoves* SceneRun::node_moves(std::size_t k) const {
  for (const auto& m : node_moves_)
    if (m.wall() == int(k))
      return &m;
  return nullptr;
}

} // namespace wear::dem

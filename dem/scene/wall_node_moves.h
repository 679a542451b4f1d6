#pragma once
// The node-moving (reference) method on any scene wall (docs/theory.md section 5): the wall's
// nodes recede inside the DEM, every few engine steps, by the wear the wall took since the
// last move; its topology never changes, so the method holds until the surface distorts.
// SceneRun owns one per wall that moves (SceneRun::move_wall_nodes) and calls it between steps.
#include "dem/engine/system.h"
#include "dem/wear/reference_deformation.h"
#include "dem/wear/wear_law.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace wear::dem {

class WallNodeMoves {
public:
  /// Wall `wall` of the engine, a triangle wall whose surface is `mesh` (the wall's frame),
  /// its wear by `law`, moved every `every` engine steps by `amplification` times the removed
  /// volume. Throws naming the parameter for a zero interval or a non-positive amplification.
  WallNodeMoves(int wall, const meshes::SurfaceMesh& mesh, const WearLawParameters& law,
                std::uint64_t every, double amplification);
  WallNodeMoves(const WallNodeMoves& other);
  WallNodeMoves(WallNodeMoves&&) = default;
  WallNodeMoves& operator=(const WallNodeMoves& other) { return *this = WallNodeMoves(other); }
  WallNodeMoves& operator=(WallNodeMoves&&) = default;

  int wall() const { return wall_; }
  std::uint64_t every() const { return every_; } ///< [steps] between two moves
  /// The engine steps until the next move is due (at least 1) at engine step `n_steps`.
  std::uint64_t steps_to_move(std::uint64_t n_steps) const { return every_ - n_steps % every_; }
  /// The wall's integrals were reset: the volume the nodes took up starts again from zero.
  void begin_window();
  /// Moves the nodes by the wear since the last move (the window's integrals over the ranks,
  /// every rank calling it together) and gives the engine the new surface; a move that would
  /// distort the surface is undone and the surface stays as it was from then on. Returns the
  /// surface as it now is.
  const meshes::SurfaceMesh& move(System& system);
  const ReferenceDeformation& deformation() const { return *deformation_; }
  /// The moves so far, between two windows (the next window starts its sums afresh).
  ReferenceDeformationState state() const { return deformation_->state(); }
  /// Continues from `s` (a state() of the same wall) and gives the engine the moved surface.
  void resume(const ReferenceDeformationState& s, System& system);

private:
  int wall_;
  std::unique_ptr<WearLaw> law_;
  WearLawParameters law_parameters_;
  std::uint64_t every_;
  double amplification_;
  std::unique_ptr<ReferenceDeformation> deformation_;
  std::vector<double> taken_; ///< [m^3] per face, the window's removed volume moved so far
};

} // namespace wear::dem

// The node-moving method on a scene wall (wall_node_moves.h).
//
// The wall's integrals run over the scene's window; the wear law turns them into the removed
// volume V_f of the window so far. A move takes the part not yet moved,
//   dV_f = A (V_f - V_f,taken),   V_f,taken := V_f,
// and recedes the nodes by it (ReferenceDeformation::update: the area-weighted node recession,
// distortion checked and undone). Over a window the moves therefore add up to A times the
// window's wear-law volume, whatever the interval. Moves fall on engine steps that are
// multiples of the interval (and at each window's end, SceneRun::advance), so a run repeats
// them on the same steps.
#include "dem/scene/wall_node_moves.h"

#include <algorithm>
#include <stdexcept>

namespace wear::dem {

WallNodeMoves::WallNodeMoves(int wall, const meshes::SurfaceMesh& mesh,
                             const WearLawParameters& law, std::uint64_t every,
                             double amplification)
    : wall_(wall), law_(make_wear_law(law)), law_parameters_(law), every_(every),
      amplification_(amplification) {
  if (every_ < 1)
    throw std::invalid_argument("Deformation/Update interval: must be at least one step");
  if (!(amplification_ > 0))
    throw std::invalid_argument("Coupling/Amplification: must be positive");
  deformation_ = std::make_unique<ReferenceDeformation>(mesh);
  taken_.assign(mesh.n_faces(), 0);
}

WallNodeMoves::WallNodeMoves(const WallNodeMoves& o)
    : wall_(o.wall_), law_(make_wear_law(o.law_parameters_)), law_parameters_(o.law_parameters_),
      every_(o.every_), amplification_(o.amplification_),
      deformation_(std::make_unique<ReferenceDeformation>(*o.deformation_)), taken_(o.taken_) {}

void WallNodeMoves::begin_window() {
  std::fill(taken_.begin(), taken_.end(), 0.0);
}

void WallNodeMoves::resume(const ReferenceDeformationState& s, System& system) {
  deformation_->resume(s);
  system.set_wall_vertices(wall_, deformation_->mesh().vertices);
}

const meshes::SurfaceMesh& WallNodeMoves::move(System& system) {
  const std::vector<double> removed = law_->removed_volume(system.wear_integrals_over_ranks(wall_));
  std::vector<double> delta(removed.size());
  for (std::size_t f = 0; f < delta.size(); ++f)
    delta[f] = amplification_ * (removed[f] - taken_[f]);
  taken_ = removed;
  if (!deformation_->first_distortion()) // frozen at its last valid surface
    system.set_wall_vertices(wall_, deformation_->update(delta, system.time()));
  return deformation_->mesh();
}

} // namespace wear::dem

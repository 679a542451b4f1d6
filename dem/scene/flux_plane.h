#pragma once
// The mass that crosses a plane of a scene (a chute's cross-section, below a hopper's
// orifice), counted from the side each particle is on at successive samples; in a periodic
// scene from the image of its position nearest the last sample's, so a particle wrapped
// through a periodic plane does not count as crossing.
#include "dem/engine/particles.h"
#include "dem/engine/rank_link.h"

#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace wear::dem {

/// What a flux plane has counted, for checkpoints.
struct FluxPlaneState {
  double net_mass = 0; ///< [kg]
  std::uint64_t n_forward = 0, n_backward = 0;
  std::vector<std::int64_t> ids; ///< particles sampled, ascending
  std::vector<Vec3> last;        ///< [m] their positions at the last sample
};

/// The periodic image of `current` [m] nearest `previous` [m] (a periodic scene's); the
/// identity without a periodic boundary.
using NearestImage = std::function<Vec3(const Vec3& previous, const Vec3& current)>;

class FluxPlane {
public:
  /// The plane through `point` [m] with normal `normal` (any length; forward is along it).
  /// Throws std::invalid_argument naming the plane for a zero normal.
  FluxPlane(std::string name, const Vec3& point, const Vec3& normal);
  const std::string& name() const { return name_; }
  /// Books the real particles of p that changed side since their last sample: + their mass
  /// forwards, - backwards. A particle's first sample only records its position. With
  /// `nearest_image`, a particle's side now is that of its image nearest its last position.
  /// Over ranks (`link`; every rank calls it together) p is this rank's part: a particle that
  /// passed to another rank since its last sample takes its last position there, and the
  /// counts are summed over the ranks (the same on every rank).
  void sample(const Particles& p, const NearestImage& nearest_image = {}, RankLink* link = nullptr);
  double net_mass() const { return net_mass_; } ///< [kg] forwards minus backwards so far
  std::uint64_t n_forward() const { return n_forward_; }
  std::uint64_t n_backward() const { return n_backward_; }
  /// Over ranks (`link`; every rank calls it together) the whole scene's: every rank's last
  /// positions, so that a run resumes on any rank count.
  FluxPlaneState state(RankLink* link = nullptr) const;
  /// Over ranks every rank takes the whole state; the entries of particles another rank holds
  /// leave at the first sample.
  void restore(const FluxPlaneState& s);

private:
  std::string name_;
  Vec3 point_, normal_;
  std::unordered_map<std::int64_t, Vec3> last_; ///< [m] by stable id: at the last sample
  double net_mass_ = 0;
  std::uint64_t n_forward_ = 0, n_backward_ = 0;
  /// Over ranks: hands the last positions of the particles this rank no longer holds to the
  /// rank that holds them now (an entry no rank claims, a particle an outlet took, is dropped).
  void pass_entries(const Particles& p, RankLink& link);
};

} // namespace wear::dem

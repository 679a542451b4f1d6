// Flux planes (flux_plane.h). A particle is ahead when (x - p) . n > 0. Between two samples
// a particle may cross and cross back; only its net change of side counts, which is the net
// flux exactly. Sampled every exchange interval by the scene run, before the outlets take
// their particles, so a particle that crossed and reached an outlet in the same interval is
// counted.
#include "dem/scene/flux_plane.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace wear::dem {

FluxPlane::FluxPlane(std::string name, const Vec3& point, const Vec3& normal)
    : name_(std::move(name)), point_(point), normal_(meshes::normalized(normal)) {
  if (meshes::norm(normal) == 0)
    throw std::invalid_argument("Scene/Flux plane " + name_ + "/Normal must not be zero");
}

void FluxPlane::sample(const Particles& p) {
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const bool ahead = meshes::dot(p.position[i] - point_, normal_) > 0;
    auto [it, first] = ahead_.try_emplace(p.id[i], ahead);
    if (first || it->second == ahead)
      continue;
    it->second = ahead;
    if (ahead) {
      net_mass_ += p.mass[i];
      ++n_forward_;
    } else {
      net_mass_ -= p.mass[i];
      ++n_backward_;
    }
  }
}

FluxPlaneState FluxPlane::state() const {
  FluxPlaneState s{net_mass_, n_forward_, n_backward_, {}, {}};
  for (const auto& [id, ahead] : ahead_)
    s.ids.push_back(id);
  std::sort(s.ids.begin(), s.ids.end());
  for (const auto id : s.ids)
    s.ahead.push_back(ahead_.at(id) ? 1 : 0);
  return s;
}

void FluxPlane::restore(const FluxPlaneState& s) {
  if (s.ids.size() != s.ahead.size())
    throw std::invalid_argument("flux plane '" + name_ + "': a state with " +
                                std::to_string(s.ids.size()) + " ids and " +
                                std::to_string(s.ahead.size()) + " sides");
  net_mass_ = s.net_mass;
  n_forward_ = s.n_forward;
  n_backward_ = s.n_backward;
  ahead_.clear();
  for (std::size_t k = 0; k < s.ids.size(); ++k)
    ahead_[s.ids[k]] = s.ahead[k] != 0;
}

} // namespace wear::dem

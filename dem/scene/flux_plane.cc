// Flux planes (flux_plane.h). A particle is ahead when (x - p) . n > 0. Between two samples
// a particle may cross and cross back; only its net change of side counts, which is the net
// flux exactly. Sampled every exchange interval by the scene run, before the outlets take
// their particles, so a particle that crossed and reached an outlet in the same interval is
// counted. In a periodic scene a particle wrapped between two samples has jumped by a period:
// its side is taken at the image of its position nearest the last one (NearestImage), which
// a particle does not leave within a sample interval.
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

void FluxPlane::sample(const Particles& p, const NearestImage& nearest_image) {
  for (std::size_t i = 0; i < p.n_real; ++i) {
    auto [it, first] = last_.try_emplace(p.id[i], p.position[i]);
    if (first)
      continue;
    const Vec3 now = nearest_image ? nearest_image(it->second, p.position[i]) : p.position[i];
    const bool was = meshes::dot(it->second - point_, normal_) > 0;
    const bool ahead = meshes::dot(now - point_, normal_) > 0;
    it->second = p.position[i];
    if (was == ahead)
      continue;
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
  for (const auto& [id, x] : last_)
    s.ids.push_back(id);
  std::sort(s.ids.begin(), s.ids.end());
  for (const auto id : s.ids)
    s.last.push_back(last_.at(id));
  return s;
}

void FluxPlane::restore(const FluxPlaneState& s) {
  if (s.ids.size() != s.last.size())
    throw std::invalid_argument("flux plane '" + name_ + "': a state with " +
                                std::to_string(s.ids.size()) + " ids and " +
                                std::to_string(s.last.size()) + " positions");
  net_mass_ = s.net_mass;
  n_forward_ = s.n_forward;
  n_backward_ = s.n_backward;
  last_.clear();
  for (std::size_t k = 0; k < s.ids.size(); ++k)
    last_[s.ids[k]] = s.last[k];
}

} // namespace wear::dem

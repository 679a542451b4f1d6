// Flux planes (flux_plane.h). A particle is ahead when (x - p) . n > 0. Between two samples
// a particle may cross and cross back; only its net change of side counts, which is the net
// flux exactly. Sampled every exchange interval by the scene run, before the outlets take
// their particles, so a particle that crossed and reached an outlet in the same interval is
// counted.
#include "dem/scene/flux_plane.h"

#include <stdexcept>

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

} // namespace wear::dem

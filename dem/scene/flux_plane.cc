// Flux planes (flux_plane.h). A particle is ahead when (x - p) . n > 0. Between two samples
// a particle may cross and cross back; only its net change of side counts, which is the net
// flux exactly. Sampled every exchange interval by the scene run, before the outlets take
// their particles, so a particle that crossed and reached an outlet in the same interval is
// counted. In a periodic scene a particle wrapped between two samples has jumped by a period:
// its side is taken at the image of its position nearest the last one (NearestImage), which
// a particle does not leave within a sample interval.
//
// Over ranks each rank samples the particles it holds; the last position of a particle that
// passed to another rank since the last sample is handed to that rank first, so no crossing is
// lost or counted twice, and the counts are summed over the ranks.
#include "dem/scene/flux_plane.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>

namespace wear::dem {

FluxPlane::FluxPlane(std::string name, const Vec3& point, const Vec3& normal)
    : name_(std::move(name)), point_(point), normal_(meshes::normalized(normal)) {
  if (meshes::norm(normal) == 0)
    throw std::invalid_argument("Scene/Flux plane " + name_ + "/Normal must not be zero");
}

void FluxPlane::pass_entries(const Particles& p, RankLink& link) {
  std::unordered_set<std::int64_t> held(p.id.begin(), p.id.begin() + long(p.n_real));
  std::vector<double> leaving, all;
  for (auto it = last_.begin(); it != last_.end();)
    if (held.count(it->first) == 0) {
      leaving.insert(leaving.end(), {double(it->first), it->second.x, it->second.y, it->second.z});
      it = last_.erase(it);
    } else {
      ++it;
    }
  link.gather_in_rank_order(leaving, all);
  for (std::size_t k = 0; k + 3 < all.size(); k += 4) {
    const auto id = std::int64_t(all[k]);
    if (held.count(id) != 0)
      last_.try_emplace(id, Vec3{all[k + 1], all[k + 2], all[k + 3]});
  }
}

void FluxPlane::sample(const Particles& p, const NearestImage& nearest_image, RankLink* link) {
  if (link)
    pass_entries(p, *link);
  // One process adds into the totals as it goes; over ranks each rank's change is summed.
  double change[3] = {0, 0, 0}; // mass, forward, backward
  double& mass = link ? change[0] : net_mass_;
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
      mass += p.mass[i];
      change[1] += 1;
    } else {
      mass -= p.mass[i];
      change[2] += 1;
    }
  }
  if (link) {
    link->sum_in_rank_order(change, 3);
    net_mass_ += change[0];
  }
  n_forward_ += std::uint64_t(change[1]);
  n_backward_ += std::uint64_t(change[2]);
}

FluxPlaneState FluxPlane::state(RankLink* link) const {
  FluxPlaneState s{net_mass_, n_forward_, n_backward_, {}, {}};
  std::vector<std::pair<std::int64_t, Vec3>> entries(last_.begin(), last_.end());
  if (link) {
    std::vector<double> mine, all;
    for (const auto& [id, x] : entries)
      mine.insert(mine.end(), {double(id), x.x, x.y, x.z});
    link->gather_in_rank_order(mine, all);
    entries.clear();
    for (std::size_t k = 0; k + 3 < all.size(); k += 4)
      entries.push_back({std::int64_t(all[k]), {all[k + 1], all[k + 2], all[k + 3]}});
  }
  // By id; over ranks a particle held by one rank and still listed by the one it left (before
  // the next sample passes the entry on) is taken once, the holder's being the same position.
  std::sort(entries.begin(), entries.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [id, x] : entries)
    if (s.ids.empty() || s.ids.back() != id) {
      s.ids.push_back(id);
      s.last.push_back(x);
    }
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

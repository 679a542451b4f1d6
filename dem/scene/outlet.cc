// Outlets: the particles whose centres lie in an outlet's box leave the system between steps
// (System::remove_particles, which keeps the other contacts' histories); each is booked to
// the first outlet, in the scene's order, that holds it, so every removed particle is
// counted once and inserted = in the system + removed holds exactly in count (over ranks: in
// the system of every rank).
#include "dem/scene/outlet.h"

namespace wear::dem {

std::size_t apply_outlets(System& system, std::vector<Outlet>& outlets) {
  if (outlets.empty())
    return 0;
  const auto removed = system.remove_particles([&outlets](const Vec3& x, double) {
    for (const auto& o : outlets)
      if (o.contains(x))
        return true;
    return false;
  });
  RankLink* link = system.rank_link();
  if (!link) {
    for (const auto& r : removed)
      for (auto& o : outlets)
        if (o.contains(r.position)) {
          o.removed_mass += r.mass;
          ++o.n_removed;
          break;
        }
    return removed.size();
  }
  // This rank's mass and count per outlet, then their sums over the ranks in rank order.
  std::vector<double> taken(2 * outlets.size() + 1, 0.0);
  for (const auto& r : removed)
    for (std::size_t k = 0; k < outlets.size(); ++k)
      if (outlets[k].contains(r.position)) {
        taken[2 * k] += r.mass;
        taken[2 * k + 1] += 1;
        break;
      }
  taken.back() = double(removed.size());
  link->sum_in_rank_order(taken.data(), taken.size());
  for (std::size_t k = 0; k < outlets.size(); ++k) {
    outlets[k].removed_mass += taken[2 * k];
    outlets[k].n_removed += std::uint64_t(taken[2 * k + 1]);
  }
  return std::size_t(taken.back());
}

} // namespace wear::dem

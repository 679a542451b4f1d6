// Outlets: the particles whose centres lie in an outlet's box leave the system between steps
// (System::remove_particles, which keeps the other contacts' histories); each is booked to
// the first outlet, in the scene's order, that holds it, so every removed particle is
// counted once and inserted = in the system + removed holds exactly in count.
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
  for (const auto& r : removed)
    for (auto& o : outlets)
      if (o.contains(r.position)) {
        o.removed_mass += r.mass;
        ++o.n_removed;
        break;
      }
  return removed.size();
}

} // namespace wear::dem

// What surrounds a particle that stops the run (System::check_particles_or_throw): the walls
// within the contact search's reach of its centre, each by its closest point over its faces
// (feature, label, and whether the force pass counts a contact there, MeshWall::
// contact_ownership), the deepest first, and the particles overlapping it. The message then
// tells a user whether the particle was pressed into a wall, stuck between two, or crushed
// in a particle cluster, without a debugger. Runs once, when the run stops: no cost to steps.
#include "dem/engine/system.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace wear::dem {

namespace {

const char* feature_name(Feature f) {
  switch (f) {
  case Feature::face:
    return "face";
  case Feature::edge:
    return "an edge of face";
  default:
    return "a vertex of face";
  }
}

const char* ownership_note(ContactOwnership o) {
  switch (o) {
  case ContactOwnership::owned:
    return "";
  case ContactOwnership::junction:
    return ", a junction of covered faces";
  default:
    return ", not counted there";
  }
}

/// "<depth> um deep" or "<gap> um clear" for a depth [m] (positive: overlap).
std::string depth_text(double depth) {
  std::ostringstream s;
  s.precision(3);
  s << std::abs(depth) * 1e6 << (depth > 0 ? " um deep" : " um clear");
  return s.str();
}

} // namespace

std::string System::describe_surroundings(std::size_t i) const {
  const auto& p = particles;
  const Vec3 x = p.position[i];
  const double r = p.radius[i];
  struct Near {
    double depth; ///< [m] r minus the distance to the closest point
    std::string text;
  };
  std::vector<Near> near;
  for (int w = 0; w < n_walls(); ++w) {
    const std::size_t local = std::size_t(wall_local_[w]);
    if (wall_kind_[w] == WallKind::revolution) {
      const double d = meshes::norm(x - revolution_walls_[local].closest(x));
      if (d < r + skin_)
        near.push_back({r - d, "wall '" + wall_name(w) + "' " + depth_text(r - d)});
      continue;
    }
    const MeshWall& mw = walls_[local];
    const Vec3 xb = mw.to_body(x);
    const auto [b, e] = mw.candidates(xb);
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_face = 0;
    ClosestFeature best_cf;
    for (auto f = b; f != e; ++f) {
      const ClosestFeature cf = mw.closest(*f, xb);
      const double d = meshes::norm(xb - cf.point);
      if (d < best) {
        best = d;
        best_face = *f;
        best_cf = cf;
      }
    }
    if (!(best < r + skin_))
      continue;
    std::ostringstream s;
    s << "wall '" << wall_name(w) << "' " << depth_text(r - best) << " at "
      << feature_name(best_cf.feature) << " " << best_face << " (label "
      << mw.mesh().face_labels[best_face]
      << ownership_note(mw.contact_ownership(best_face, best_cf, xb)) << ")";
    near.push_back({r - best, s.str()});
  }
  std::sort(near.begin(), near.end(),
            [](const Near& a, const Near& b) { return a.depth > b.depth; });
  std::size_t n_overlapping = 0;
  double deepest = 0;
  std::int64_t deepest_id = -1;
  for (std::size_t j = 0; j < p.position.size(); ++j) {
    if (j == i)
      continue;
    const double overlap = r + p.radius[j] - meshes::norm(p.position[j] - x);
    if (overlap > 0) {
      ++n_overlapping;
      if (overlap > deepest) {
        deepest = overlap;
        deepest_id = p.id[j];
      }
    }
  }
  std::ostringstream s;
  s << "Around it now: ";
  if (near.empty())
    s << "no wall within " << skin_ * 1e6 << " um of its surface";
  for (std::size_t k = 0; k < near.size() && k < 3; ++k)
    s << (k ? ", " : "") << near[k].text;
  s << "; " << n_overlapping << " particle(s) overlapping it";
  if (n_overlapping > 0)
    s << ", the deepest " << depth_text(deepest) << " (particle " << deepest_id << ")";
  s << ".";
  return s.str();
}

} // namespace wear::dem

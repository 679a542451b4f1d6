// The role of each region label (label_roles.h): a small table sorted by label, searched by
// bisection. A mesh has a handful of labels (at most some hundred: a convex pattern's
// elements, a CAD part's surfaces), read once per face where a role matters.
#include "meshes/label_roles.h"

#include <algorithm>
#include <stdexcept>

namespace wear::meshes {

const char* role_name(FaceRole role) {
  switch (role) {
  case FaceRole::free:
    return "free";
  case FaceRole::wearing:
    return "wearing";
  case FaceRole::clamped:
    return "clamped";
  case FaceRole::held:
    return "held";
  }
  return "?";
}

FaceRole role_from_name(const std::string& name) {
  for (FaceRole r : {FaceRole::free, FaceRole::wearing, FaceRole::clamped, FaceRole::held})
    if (name == role_name(r))
      return r;
  throw std::invalid_argument("unknown face role '" + name + "' (free, wearing, clamped or held)");
}

void LabelRoles::set(int label, FaceRole role) {
  const auto it = std::lower_bound(roles_.begin(), roles_.end(), label,
                                   [](const auto& e, int l) { return e.first < l; });
  if (it != roles_.end() && it->first == label)
    it->second = role;
  else
    roles_.insert(it, {label, role});
}

FaceRole LabelRoles::of(int label) const {
  const auto it = std::lower_bound(roles_.begin(), roles_.end(), label,
                                   [](const auto& e, int l) { return e.first < l; });
  return it != roles_.end() && it->first == label ? it->second : FaceRole::free;
}

bool LabelRoles::any(FaceRole role) const {
  return std::any_of(roles_.begin(), roles_.end(),
                     [role](const auto& e) { return e.second == role; });
}

} // namespace wear::meshes

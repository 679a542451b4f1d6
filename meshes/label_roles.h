#pragma once
// What each region label of a surface does in the wear and the FEM: its faces wear, are free,
// are clamped, or are held on their sides. The role is carried beside the label (a table per
// mesh, SurfaceMesh::roles), set where the labels are made (the sample generator, a scene's
// wearing part) and read wherever a face's role matters; a label number implies no role.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace wear::meshes {

enum class FaceRole : std::uint8_t {
  free = 0,    ///< neither wears nor is supported (traction-free in the FEM)
  wearing = 1, ///< receives the wall loads and recedes with the wear
  clamped = 2, ///< zero displacement in the FEM, never moves
  held = 3,    ///< rests against a support: zero normal displacement, slides along it
};

/// "free", "wearing", "clamped", "held".
const char* role_name(FaceRole role);
/// Inverse of role_name(); throws std::invalid_argument naming `name`.
FaceRole role_from_name(const std::string& name);

class LabelRoles {
public:
  /// Sets (or replaces) the role of `label`.
  void set(int label, FaceRole role);
  /// The role of `label`; free when none was set.
  FaceRole of(int label) const;
  bool wears(int label) const { return of(label) == FaceRole::wearing; }
  bool clamped(int label) const { return of(label) == FaceRole::clamped; }
  bool held(int label) const { return of(label) == FaceRole::held; }
  /// Clamped or held: faces that never move, whatever wears beside them.
  bool fixed(int label) const { return clamped(label) || held(label); }
  /// True when any label has `role`.
  bool any(FaceRole role) const;
  /// (label, role) sorted by label.
  const std::vector<std::pair<int, FaceRole>>& entries() const { return roles_; }
  bool empty() const { return roles_.empty(); }
  bool operator==(const LabelRoles& o) const { return roles_ == o.roles_; }
  bool operator!=(const LabelRoles& o) const { return !(*this == o); }

private:
  std::vector<std::pair<int, FaceRole>> roles_; ///< sorted by label, one entry per label
};

} // namespace wear::meshes

// What is left of a worn part (meshes/part_life.h).
//
// An element's foot is the mean height of the vertices it shares with the other wearing
// labels (the base around it), its height the top above the foot, its volume
// sum_f (z_c - foot) n_z A over its faces (the prism volume between the faces and the foot's
// plane: exact for a graph over that plane, which a convex element is). The thinnest point is
// the lowest wearing vertex above the clamped faces' lowest vertex: for a sample clamped at
// its bottom, the remaining thickness under the deepest wear.
#include "meshes/part_life.h"

#include <algorithm>
#include <limits>

namespace wear::meshes {

std::map<int, ElementStanding> convex_element_standing(const SurfaceMesh& m) {
  std::map<int, ElementStanding> standing;
  std::map<int, std::pair<double, int>> rim; // sum of heights, count
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (label::is_convex_element(m.face_labels[f]))
      for (const auto v : m.triangles[f]) {
        auto [it, added] = standing.try_emplace(m.face_labels[f]);
        it->second.top = added ? m.vertices[v].z : std::max(it->second.top, m.vertices[v].z);
      }
  for (const auto& [edge, faces] : edge_faces(m)) {
    if (faces.size() != 2)
      continue;
    const int a = m.face_labels[faces[0]], b = m.face_labels[faces[1]];
    if (a == b || !m.roles.wears(a) || !m.roles.wears(b))
      continue;
    for (const auto& [l, other] : {std::pair{a, b}, std::pair{b, a}})
      if (label::is_convex_element(l)) {
        auto& r = rim[l];
        r.first += m.vertices[edge.first].z + m.vertices[edge.second].z;
        r.second += 2;
        ++standing[l].neighbours[other];
      }
  }
  for (auto it = standing.begin(); it != standing.end();) {
    const auto r = rim.find(it->first);
    if (r == rim.end()) { // no wearing neighbour: not an element on a base
      it = standing.erase(it);
      continue;
    }
    it->second.foot = r->second.first / r->second.second;
    it->second.volume = volume_above_plane(m, it->first, it->second.foot);
    ++it;
  }
  return standing;
}

PartLife part_life(const SurfaceMesh& m, double vanish_height) {
  PartLife life;
  life.elements = convex_element_standing(m);
  for (const auto& [label, e] : life.elements)
    life.n_standing += e.height() > vanish_height;
  life.volume = enclosed_volume(m);
  double wear_low = std::numeric_limits<double>::infinity();
  double clamped_low = std::numeric_limits<double>::infinity();
  const auto area = face_areas(m);
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const FaceRole role = m.face_role(f);
    for (const auto v : m.triangles[f]) {
      if (role == FaceRole::clamped)
        clamped_low = std::min(clamped_low, m.vertices[v].z);
      else if (m.roles.wears(m.face_labels[f]))
        wear_low = std::min(wear_low, m.vertices[v].z);
    }
    if (role == FaceRole::clamped)
      life.clamped_area += area[f];
  }
  if (std::isfinite(wear_low) && std::isfinite(clamped_low))
    life.thinnest = wear_low - clamped_low;
  return life;
}

} // namespace wear::meshes

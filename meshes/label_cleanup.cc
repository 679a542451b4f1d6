// Labels on a new worn surface (the implicit recession's, meshes/implicit_recession.h), whose
// faces took the label of the nearest old face: the boundaries between labels are made
// straight, speckled islands join their surroundings, convex elements worn down join the
// label around them, and teeth of no width along a seam join the label they point into.
//
// Majority filter: a face whose neighbours across two or three of its edges carry one other
// label takes it. Islands: connected pieces of a label under a fraction of the area of that
// label's largest piece take the label they share most edges with. Vanished elements: an
// element label C<j><k> whose highest vertex stands at most a given height above its foot
// (meshes/part_life.h) joins the label it shares most edges with. Teeth: a face of triangle
// quality below 1e-3 whose two edges at one vertex (the tip) border one other label, and whose
// tip has no other face of its own label, takes that label. Assumes a closed manifold surface
// (face_neighbours).
#include "meshes/label_cleanup.h"

#include "meshes/mesh_quality.h"
#include "meshes/part_life.h"

#include <algorithm>
#include <map>

namespace wear::meshes {

// The boundaries between labels on the grid's zero set zigzag from face to face (each face
// takes its own nearest old face); a face whose three neighbours across its edges carry one
// other label, or two of them the same other label, takes it (a majority filter), in
// `passes` sweeps. The remesher's curves along the boundaries are then straighter, and
// small labels keep their area through the remesh.
void smooth_label_boundaries(SurfaceMesh& m, int passes) {
  const auto across = face_neighbours(m);
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<int> next = m.face_labels;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
      const int a = m.face_labels[across[f][0]], b = m.face_labels[across[f][1]],
                c = m.face_labels[across[f][2]], own = m.face_labels[f];
      if (a == b && a != own)
        next[f] = a;
      else if (a == c && a != own)
        next[f] = a;
      else if (b == c && b != own)
        next[f] = b;
    }
    m.face_labels = std::move(next);
  }
}

// Islands of a label (connected pieces smaller than `fraction` of that label's largest piece,
// by area), left where the new faces' labels speckle along a label boundary, join the label
// they share most edges with: gmsh would have to parametrise each as a patch of its own.
void merge_label_islands(SurfaceMesh& m, double fraction) {
  const auto across = face_neighbours(m);
  const auto area = face_areas(m);
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<std::int32_t> piece(m.n_faces(), -1);
    std::vector<double> piece_area;
    std::vector<int> piece_label;
    std::map<int, double> largest;
    std::vector<std::uint32_t> stack;
    for (std::uint32_t f = 0; f < m.n_faces(); ++f) {
      if (piece[f] >= 0)
        continue;
      const auto id = std::int32_t(piece_area.size());
      piece_area.push_back(0);
      piece_label.push_back(m.face_labels[f]);
      piece[f] = id;
      stack.assign(1, f);
      while (!stack.empty()) {
        const auto g = stack.back();
        stack.pop_back();
        piece_area[std::size_t(id)] += area[g];
        for (const auto n : across[g])
          if (piece[n] < 0 && m.face_labels[n] == m.face_labels[f]) {
            piece[n] = id;
            stack.push_back(n);
          }
      }
      auto& l = largest[m.face_labels[f]];
      l = std::max(l, piece_area[std::size_t(id)]);
    }
    std::map<std::int32_t, std::map<int, int>> votes; // island -> label -> shared edges
    for (std::uint32_t f = 0; f < m.n_faces(); ++f) {
      const auto id = piece[f];
      if (piece_area[std::size_t(id)] >= fraction * largest[piece_label[std::size_t(id)]])
        continue;
      for (const auto n : across[f])
        if (m.face_labels[n] != m.face_labels[f])
          ++votes[id][m.face_labels[n]];
    }
    if (votes.empty())
      return;
    std::map<std::int32_t, int> into;
    for (const auto& [id, v] : votes)
      into[id] = std::max_element(v.begin(), v.end(), [](const auto& x, const auto& y) {
                   return x.second < y.second;
                 })->first;
    for (std::uint32_t f = 0; f < m.n_faces(); ++f) {
      const auto it = into.find(piece[f]);
      if (it != into.end())
        m.face_labels[f] = it->second;
    }
  }
}

// Convex elements worn away: an element label whose highest vertex stands at most `height`
// above its foot (meshes/part_life.h) joins the label it shares most edges with. Returns the
// labels removed.
std::vector<int> merge_vanished_elements(SurfaceMesh& m, double height) {
  std::vector<int> gone;
  std::map<int, int> into;
  for (const auto& [l, e] : convex_element_standing(m)) {
    if (e.height > height)
      continue;
    const auto& around = e.neighbours;
    into[l] = std::max_element(around.begin(), around.end(), [](const auto& x, const auto& y) {
                return x.second < y.second;
              })->first;
    gone.push_back(l);
  }
  for (auto& label : m.face_labels) {
    const auto it = into.find(label);
    if (it != into.end())
      label = it->second;
  }
  return gone;
}

// A face of one label whose three vertices went onto one seam of the old surface is left of
// no width: a tooth of its label into the next one, where the remesher's label boundary
// doubles back on itself. Where two of its edges border faces of one other label and the
// vertex between those edges (the tooth's tip) has no other face of the tooth's label, the
// face joins that label and its patch: the boundary then runs along its third edge, and the
// tip goes onto the other label's patch. Returns the faces joined.
std::size_t join_label_teeth(SurfaceMesh& m, std::vector<int>& patch_of_face) {
  const auto across = face_neighbours(m);
  const auto around = vertex_faces(m);
  std::size_t n_joined = 0;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const auto& t = m.triangles[f];
    if (triangle_quality(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]) >= 1e-3)
      continue;
    const int own = m.face_labels[f];
    for (int k = 0; k < 3; ++k) {
      // Edge k runs from vertex k to k + 1: the edges k and k + 2 meet at vertex k.
      const auto g = across[f][std::size_t(k)], h = across[f][std::size_t((k + 2) % 3)];
      const int other = m.face_labels[g];
      if (other == own || m.face_labels[h] != other)
        continue;
      const auto tip = m.triangles[f][std::size_t(k)];
      bool alone = true;
      for (auto i = around.offsets[tip]; i < around.offsets[tip + 1] && alone; ++i)
        alone = around.faces[i] == f || m.face_labels[around.faces[i]] != own;
      if (!alone)
        continue;
      m.face_labels[f] = other;
      patch_of_face[f] = patch_of_face[g];
      ++n_joined;
      break;
    }
  }
  return n_joined;
}

} // namespace wear::meshes

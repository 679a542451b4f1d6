// Area-weighted node recession of a worn surface (model.md section 5, also the starting
// field of the FEM recession): D_v = sum_{f in W(v)} V_f / sum_{f in W(v)} A_f along
// n_v = normalized(sum_{f in W(v)} A_f n_f), W(v) the wearing faces around v. Only wearing
// faces enter both sums, so a node where the wear face meets a side moves with the wear face.
//
// Spreading (where a recession would fold): explicit conservative diffusion of the depth
// d_f = V_f / A_f over the region R (wearing faces within k vertex rings of the folding faces):
// per step, across every edge (f, g) inside R, volume q = w (d_f - d_g) min(A_f, A_g) with
// w = 1/4 goes from f to g. A face gives at most 3 w V_f < V_f per step, so volumes stay
// non-negative, and every transfer is antisymmetric, so the total is kept. The assumption is
// physical as well as numerical: a tip thinner than the wear of one step is not cut into a
// sliver, its neighbourhood recedes with it.
#include "meshes/recession.h"

#include <algorithm>
#include <cmath>

namespace wear::meshes {

std::vector<Vec3> area_weighted_recession(const SurfaceMesh& m,
                                          const std::vector<double>& removed_volume) {
  const std::size_t nv = m.n_vertices();
  const auto area = face_areas(m);
  std::vector<double> volume(nv, 0), area_sum(nv, 0);
  std::vector<Vec3> normal(nv), out(nv);
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    if (!label::wears(m.face_labels[f]))
      continue;
    const Vec3 n = face_normal_unnormalized(m, f);
    for (const auto v : m.triangles[f]) {
      volume[v] += removed_volume[f];
      area_sum[v] += area[f];
      normal[v] += n;
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (area_sum[v] > 0 && norm(normal[v]) > 0)
      out[v] = normalized(normal[v]) * (-volume[v] / area_sum[v]);
  return out;
}

std::vector<char> faces_within_rings(const SurfaceMesh& m, const std::vector<std::uint32_t>& seeds,
                                     int rings) {
  const std::size_t nf = m.n_faces();
  const auto vf = vertex_faces(m);
  std::vector<char> in_region(nf, 0);
  std::vector<std::uint32_t> front;
  for (const auto f : seeds)
    if (f < nf && !in_region[f]) {
      in_region[f] = 1;
      front.push_back(f);
    }
  for (int k = 0; k < rings; ++k) {
    std::vector<std::uint32_t> next;
    for (const auto f : front)
      for (const auto v : m.triangles[f])
        for (auto i = vf.offsets[v]; i < vf.offsets[v + 1]; ++i) {
          const auto g = vf.faces[i];
          if (!in_region[g]) {
            in_region[g] = 1;
            next.push_back(g);
          }
        }
    front.swap(next);
  }
  return in_region;
}

double spread_removed_volume(const SurfaceMesh& m, std::vector<double>& removed_volume,
                             const std::vector<std::uint32_t>& seeds, int rings) {
  const std::size_t nf = m.n_faces();
  std::vector<char> in_region = faces_within_rings(m, seeds, rings);
  for (std::size_t f = 0; f < nf; ++f)
    if (!label::wears(m.face_labels[f]))
      in_region[f] = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& [edge, faces] : edge_faces(m))
    if (faces.size() == 2 && in_region[faces[0]] && in_region[faces[1]])
      pairs.emplace_back(faces[0], faces[1]);
  const auto area = face_areas(m);
  const std::vector<double> before = removed_volume;
  std::vector<double> change(nf, 0);
  constexpr double w = 0.25;
  for (int step = 0; step < rings * rings; ++step) {
    for (const auto& [f, g] : pairs) {
      const double q = w * (removed_volume[f] / area[f] - removed_volume[g] / area[g]) *
                       std::min(area[f], area[g]);
      change[f] -= q;
      change[g] += q;
    }
    for (const auto& [f, g] : pairs)
      for (const auto h : {f, g})
        if (change[h] != 0) {
          removed_volume[h] = std::max(0.0, removed_volume[h] + change[h]);
          change[h] = 0;
        }
  }
  double moved = 0;
  for (std::size_t f = 0; f < nf; ++f)
    moved += std::abs(removed_volume[f] - before[f]);
  return 0.5 * moved;
}

} // namespace wear::meshes

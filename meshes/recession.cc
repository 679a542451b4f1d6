// Area-weighted node recession of a worn surface (model.md section 5, also the starting
// field of the FEM recession): D_v = sum_{f in W(v)} V_f / sum_{f in W(v)} A_f along
// n_v = normalized(sum_{f in W(v)} A_f n_f), W(v) the wearing faces around v. Only wearing
// faces enter both sums, so a node where the wear face meets a side moves with the wear face.
#include "meshes/recession.h"

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

} // namespace wear::meshes

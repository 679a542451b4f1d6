// Lawson flips in flat regions of a triangle surface.
//
// Edge (a, b) shared by f = (a, b, c) and g = (b, a, d), both of one label with normals within
// a small angle, is flipped to (a, d, c), (d, b, c) when the angles at c and d sum to more than
// pi (d lies inside the circumcircle of a, b, c): the Delaunay criterion in the common plane.
// A non-Delaunay edge of a planar pair always has a strictly convex quadrilateral around it,
// so the flipped faces keep the orientation; they are checked anyway against round-off. Each
// flip raises the smallest angle of the pair, so the passes end (bounded for safety).
// A flip is not made when the new edge (c, d) is already an edge of the surface (c and d
// joined elsewhere, as across a thin wedge of a worn part): it would be shared by four faces,
// and the surface would be no manifold.
#include "meshes/planar_flip.h"

#include "meshes/constants.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace wear::meshes {

namespace {
double angle_at(const Vec3& apex, const Vec3& p, const Vec3& q) {
  const Vec3 u = p - apex, w = q - apex;
  return std::atan2(norm(cross(u, w)), dot(u, w));
}
std::uint32_t opposite(const Triangle& t, std::uint32_t a, std::uint32_t b) {
  for (const auto v : t)
    if (v != a && v != b)
      return v;
  return t[0];
}
// True when face t runs a -> b.
bool runs(const Triangle& t, std::uint32_t a, std::uint32_t b) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == a && t[(k + 1) % 3] == b)
      return true;
  return false;
}
} // namespace

std::size_t flip_flat_edges(SurfaceMesh& m, double max_angle_deg) {
  const double cos_flat = std::cos(max_angle_deg * pi / 180);
  std::size_t n_flips = 0;
  for (int pass = 0; pass < 100; ++pass) {
    std::size_t n_pass = 0;
    std::vector<char> touched(m.n_faces(), 0);
    const auto faces_of_edge = edge_faces(m);
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& [edge, faces] : faces_of_edge)
      edges.insert(edge);
    for (const auto& [edge, faces] : faces_of_edge) {
      if (faces.size() != 2)
        continue;
      const auto f = faces[0], g = faces[1];
      if (touched[f] || touched[g] || m.face_labels[f] != m.face_labels[g])
        continue;
      const Vec3 nf = face_normal_unnormalized(m, f), ng = face_normal_unnormalized(m, g);
      if (dot(nf, ng) < cos_flat * norm(nf) * norm(ng))
        continue;
      // Orient the edge as f runs it.
      std::uint32_t a = edge.first, b = edge.second;
      if (!runs(m.triangles[f], a, b))
        std::swap(a, b);
      const std::uint32_t c = opposite(m.triangles[f], a, b), d = opposite(m.triangles[g], a, b);
      const auto& x = m.vertices;
      if (angle_at(x[c], x[a], x[b]) + angle_at(x[d], x[a], x[b]) <= pi + 1e-12)
        continue;
      const Triangle t1{a, d, c}, t2{d, b, c};
      const Vec3 n1 = cross(x[d] - x[a], x[c] - x[a]), n2 = cross(x[b] - x[d], x[c] - x[d]);
      if (dot(n1, nf) <= 0 || dot(n2, nf) <= 0)
        continue;
      const auto new_edge = std::make_pair(std::min(c, d), std::max(c, d));
      if (!edges.insert(new_edge).second)
        continue;
      edges.erase(edge);
      m.triangles[f] = t1;
      m.triangles[g] = t2;
      touched[f] = touched[g] = 1;
      ++n_pass;
    }
    n_flips += n_pass;
    if (n_pass == 0)
      break;
  }
  if (n_flips > 0)
    m.bump_revision();
  return n_flips;
}

} // namespace wear::meshes

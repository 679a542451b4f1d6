// Sliding constraints of surface vertices on the unworn surface.
//
// The non-wearing faces around a vertex are grouped by normal (greedy: a face joins the first
// group whose seed normal is within the crease angle, else it seeds a new group); each group's
// plane normal is the area-weighted mean of its faces' normals. A vertex on one group moves in
// that plane (d - (d.n) n), on two along the crease line (direction n1 x n2), on more not at
// all. Assumption: the unworn surface is piecewise flat (sample sides and bottom), so sliding
// in these planes and lines leaves its shape, and the enclosed volume, unchanged.
#include "meshes/sliding_constraint.h"

#include "meshes/constants.h"

#include <cmath>

namespace wear::meshes {

std::vector<SlidingConstraint> sliding_constraints(const SurfaceMesh& m, double crease_angle_deg) {
  const std::size_t nv = m.n_vertices();
  const double cos_crease = std::cos(crease_angle_deg * pi / 180);
  // Up to three groups per vertex: a fourth makes it fixed anyway.
  struct Groups {
    int n = 0;
    Vec3 seed[3], sum[3];
  };
  std::vector<Groups> groups(nv);
  std::vector<char> overfull(nv, 0);
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    if (m.face_wears(f))
      continue;
    const Vec3 weighted = face_normal_unnormalized(m, f);
    const Vec3 n = normalized(weighted);
    for (const auto v : m.triangles[f]) {
      auto& g = groups[v];
      int k = 0;
      while (k < g.n && dot(g.seed[k], n) < cos_crease)
        ++k;
      if (k == g.n) {
        if (g.n == 3) {
          overfull[v] = 1;
          continue;
        }
        g.seed[g.n++] = n;
      }
      g.sum[k] += weighted;
    }
  }
  std::vector<SlidingConstraint> out(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const auto& g = groups[v];
    auto& c = out[v];
    if (overfull[v] || g.n >= 3) {
      c.n_free = 0;
    } else if (g.n == 2) {
      c.axis = normalized(cross(g.sum[0], g.sum[1]));
      c.n_free = norm(c.axis) > 0 ? 1 : 0;
    } else if (g.n == 1) {
      c.axis = normalized(g.sum[0]);
      c.n_free = norm(c.axis) > 0 ? 2 : 0;
    }
  }
  return out;
}

} // namespace wear::meshes

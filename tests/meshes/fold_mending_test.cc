// Fold mending: a vertex of valence 3 beside a straight label boundary, pushed across it so
// that one of its faces turns over (as the remesher leaves them at an element's foot), is
// mended back into a flat top; the box stays closed, its volume and labels are kept, and a
// vertex that may not move is left as it is.
#include "meshes/fold_mending.h"
#include "meshes/mesh_quality.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <tuple>

using namespace wear::meshes;

namespace {

// The box [0, n h]^3, each side cut into n x n squares of two triangles; the top (z = n h)
// is label base, the rest label side.
SurfaceMesh box(int n, double h) {
  SurfaceMesh m;
  std::map<std::tuple<int, int, int>, std::uint32_t> id;
  const auto vertex = [&](int i, int j, int k) {
    const auto [it, added] = id.try_emplace({i, j, k}, std::uint32_t(m.vertices.size()));
    if (added)
      m.vertices.push_back({i * h, j * h, k * h});
    return it->second;
  };
  // Side `axis` at `level` (0 or n), squares over the two other axes.
  for (int axis = 0; axis < 3; ++axis)
    for (const int level : {0, n})
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const auto at = [&](int u, int v) {
            int c[3];
            c[axis] = level;
            c[(axis + 1) % 3] = u;
            c[(axis + 2) % 3] = v;
            return vertex(c[0], c[1], c[2]);
          };
          const auto p = at(a, b), q = at(a + 1, b), r = at(a + 1, b + 1), s = at(a, b + 1);
          const int l = axis == 2 && level == n ? label::base : label::side;
          if (level == n) { // (u, v, axis) is right-handed: counter-clockwise seen from +axis
            m.triangles.push_back({p, q, r});
            m.triangles.push_back({p, r, s});
          } else {
            m.triangles.push_back({p, r, q});
            m.triangles.push_back({p, s, r});
          }
          m.face_labels.push_back(l);
          m.face_labels.push_back(l);
        }
  return m;
}

} // namespace

TEST_CASE("a face turned over beside a label boundary is mended, the box kept", "[meshes][fold]") {
  const int n = 4;
  const double h = 1e-3, a = n * h;
  SurfaceMesh m = box(n, h);
  REQUIRE(check_closed(m).closed());
  REQUIRE(enclosed_volume(m) == Approx(a * a * a).epsilon(1e-12));
  // The top's first triangle at the edge y = 0 (the boundary with the side below it) gets a
  // vertex of valence 3, pushed 0.1 h across that edge and 0.05 h down.
  std::size_t f = 0;
  for (; f < m.n_faces(); ++f) {
    const auto& t = m.triangles[f];
    if (m.face_labels[f] == label::base && m.vertices[t[0]].y == 0 && m.vertices[t[1]].y == 0)
      break;
  }
  REQUIRE(f < m.n_faces());
  const auto [p, q, r] = m.triangles[f];
  const auto v = std::uint32_t(m.n_vertices());
  m.vertices.push_back({0.5 * (m.vertices[p].x + m.vertices[q].x), -0.1 * h, a - 0.05 * h});
  m.triangles[f] = {p, q, v};
  m.triangles.push_back({q, r, v});
  m.triangles.push_back({r, p, v});
  m.face_labels.push_back(label::base);
  m.face_labels.push_back(label::base);
  REQUIRE(check_closed(m).closed());
  REQUIRE(check_closed(m).consistently_oriented());
  const auto n_folded = find_folded_edges(m, -0.5).size();
  REQUIRE(n_folded == 2); // (p, q, v) faces down, against (q, r, v) and (r, p, v)
  const auto area = area_per_label(m);
  const double volume = enclosed_volume(m);
  const auto revision = m.revision();

  FoldMendingParameters p_mend;
  p_mend.max_shift = 0.25e-3;
  SECTION("the vertex may move: the fold is mended within max_shift") {
    const std::vector<char> removable(m.n_vertices(), 1);
    const auto before = m;
    const auto r = mend_folds(m, removable, p_mend);
    CHECK(r.n_folds_before == 2);
    CHECK(r.n_folds_after == 0);
    CHECK(find_folded_edges(m, -0.5).empty());
    CHECK(r.n_flips + r.n_collapses + r.n_moves >= 1);
    CHECK(m.revision() > revision);
    CHECK(check_closed(m).closed());
    CHECK(check_closed(m).consistently_oriented());
    // Every top face faces up again (within 10 degrees), every other one is untouched.
    const auto normal = face_normals(m);
    for (std::size_t g = 0; g < m.n_faces(); ++g)
      if (m.face_labels[g] == label::base)
        CHECK(normal[g].z > std::cos(10 * 3.141592653589793 / 180));
    // The surface moved by at most max_shift over the star of v (3 faces, half a square):
    // the volume changes by at most that much times their area.
    CHECK(std::abs(enclosed_volume(m) - volume) <= p_mend.max_shift * 0.5 * h * h);
    for (const auto& [label, area0] : area)
      CHECK(area_per_label(m).at(label) == Approx(area0).epsilon(0.02));
    // The old vertices map onto themselves (a collapsed v onto one of p, q, r).
    for (std::uint32_t w = 0; w < v; ++w)
      CHECK(norm(m.vertices[r.new_index[w]] - before.vertices[w]) == 0);
  }
  SECTION("no vertex may move, and no flip mends it: the surface is left as it was") {
    const std::vector<char> removable(m.n_vertices(), 0);
    const auto before = m;
    const auto r = mend_folds(m, removable, p_mend);
    CHECK(r.n_folds_after == n_folded);
    CHECK(r.n_flips + r.n_collapses + r.n_moves == 0);
    CHECK(m.revision() == revision);
    CHECK(m.triangles == before.triangles);
  }
}

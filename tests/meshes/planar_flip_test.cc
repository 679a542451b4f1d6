// Delaunay flips in flat regions: a jittered grid folded along a line (two planes) is
// re-triangulated so every edge inside a plane is locally Delaunay; the area, the orientation,
// the open boundary and the fold line are kept, and the smallest angle does not drop.
#include "meshes/constants.h"
#include "meshes/planar_flip.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

using namespace wear::meshes;
using wear::pi;

namespace {
double min_angle(const SurfaceMesh& m) {
  double a = 10;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = m.vertices[t[(k + 1) % 3]] - m.vertices[t[k]],
                 w = m.vertices[t[(k + 2) % 3]] - m.vertices[t[k]];
      a = std::min(a, std::atan2(norm(cross(u, w)), dot(u, w)));
    }
  return a;
}
} // namespace

TEST_CASE("Delaunay flips in flat regions keep the surface and fix its triangles",
          "[meshes][flip]") {
  // 13 x 9 vertices on [0, 12] x [0, 8] mm; x > 6 is tilted up by 30 degrees about x = 6.
  // Interior vertices are jittered along the grid lines (within their plane), which leaves
  // many edges not Delaunay; diagonals all run the same way.
  const int nx = 13, ny = 9;
  const double h = 1e-3, tilt = 30 * pi / 180;
  SurfaceMesh m;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double u = i * h, y = j * h;
      if (i > 0 && i < nx - 1 && i != 6 && j > 0 && j < ny - 1) {
        u += 0.3 * h * std::sin(3.1 * i + 1.7 * j);
        y += 0.3 * h * std::cos(2.3 * i - 0.9 * j);
      }
      const double x = u <= 6 * h ? u : 6 * h + (u - 6 * h) * std::cos(tilt);
      const double z = u <= 6 * h ? 0 : (u - 6 * h) * std::sin(tilt);
      m.vertices.push_back({x, y, z});
    }
  const auto id = [&](int i, int j) { return std::uint32_t(i + nx * j); };
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  m.face_labels.assign(m.triangles.size(), label::side);
  for (const auto& n0 : face_normals(m)) // the jitter leaves every face the right way up
    REQUIRE(n0.z > 0);
  const auto area0 = face_areas(m);
  double total0 = 0;
  for (const double a : area0)
    total0 += a;
  const double angle0 = min_angle(m);
  std::set<std::pair<std::uint32_t, std::uint32_t>> boundary0;
  for (const auto& [e, f] : edge_faces(m))
    if (f.size() == 1)
      boundary0.insert(e);
  const auto revision0 = m.revision();

  const auto n = flip_flat_edges(m);
  CHECK(n > 0);
  CHECK(m.revision() != revision0);
  CHECK(min_angle(m) >= angle0);
  double total = 0;
  for (const double a : face_areas(m))
    total += a;
  CHECK(total == Approx(total0).epsilon(1e-13));
  const auto normal = face_normals(m);
  std::set<std::pair<std::uint32_t, std::uint32_t>> boundary;
  for (const auto& [e, f] : edge_faces(m)) {
    if (f.size() == 1) {
      boundary.insert(e);
      continue;
    }
    REQUIRE(f.size() == 2);
    const bool same_plane = dot(normal[f[0]], normal[f[1]]) > 1 - 1e-12;
    // Every face stays in one of the two planes: the fold line's edges are still edges.
    if (!same_plane) {
      CHECK(m.vertices[e.first].x == Approx(6 * h));
      CHECK(m.vertices[e.second].x == Approx(6 * h));
      continue;
    }
    double opposite = 0;
    for (const auto g : f)
      for (const auto v : m.triangles[g])
        if (v != e.first && v != e.second) {
          const Vec3 u = m.vertices[e.first] - m.vertices[v],
                     w = m.vertices[e.second] - m.vertices[v];
          opposite += std::atan2(norm(cross(u, w)), dot(u, w));
        }
    CHECK(opposite <= pi + 1e-9);
  }
  CHECK(boundary == boundary0);
  for (std::size_t f = 0; f < m.n_faces(); ++f) // orientation kept: normals up
    CHECK(normal[f].z > 0);
  // Fold-line edges: 8 segments on x = 6 h, still present.
  int n_fold = 0;
  for (const auto& [e, f] : edge_faces(m))
    n_fold += f.size() == 2 && dot(normal[f[0]], normal[f[1]]) < 1 - 1e-12;
  CHECK(n_fold == ny - 1);
  // A second call has nothing left to flip.
  CHECK(flip_flat_edges(m) == 0);
}

TEST_CASE("A flat flip whose new edge exists elsewhere is not made", "[meshes][flip]") {
  // A closed sliver of zero thickness: on top, a -> c -> b and a -> b -> d, flat, their
  // common edge (a, b) far from Delaunay (the angles at c and d sum to 293 degrees); below,
  // the same quadrilateral split along (c, d). Flipping (a, b) on top would make (c, d) an
  // edge of four faces: the worn part's thin wedge in the limit, where the decimation's flips
  // once left a surface the isotropic remeshing could not take.
  const double h = 1e-3;
  SurfaceMesh m;
  m.vertices = {{-h, 0, 0}, {h, 0, 0}, {0, -0.3 * h, 0}, {0, 0.3 * h, 0}}; // a b c d
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {2, 0, 3}, {2, 3, 1}};
  m.face_labels.assign(4, label::side);
  REQUIRE(check_closed(m).closed());
  REQUIRE(check_closed(m).consistently_oriented());
  CHECK(flip_flat_edges(m) == 0);
  const auto closed = check_closed(m);
  CHECK(closed.n_nonmanifold_edges == 0);
  CHECK(closed.closed());
}

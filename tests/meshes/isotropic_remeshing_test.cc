// Isotropic remeshing against a shape whose every point is known: a 10 mm box. Remeshed to
// 1 mm edges, each vertex stays on the box's planes, the corners stay, every label keeps its
// area, and the triangles come out well shaped; its sharp edges are kept either as label
// boundaries or as curves, and without either they are cut.
#include "meshes/isotropic_remeshing.h"
#include "meshes/mesh_quality.h"
#include "test_shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace wear::meshes;

namespace {

constexpr double a = 10e-3; // [m] box side

// Largest distance of a vertex from the box's surface.
double off_box(const SurfaceMesh& m) {
  double worst = 0;
  for (const auto& x : m.vertices) {
    double d = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k)
      d = std::min({d, std::abs(x[k]), std::abs(x[k] - a)});
    for (int k = 0; k < 3; ++k)
      d = std::max({d, -x[k], x[k] - a}); // outside the box counts too
    worst = std::max(worst, d);
  }
  return worst;
}

std::size_t n_corners_kept(const SurfaceMesh& m) {
  std::size_t n = 0;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner{a * (c & 1), a * ((c >> 1) & 1), a * ((c >> 2) & 1)};
    n += std::any_of(m.vertices.begin(), m.vertices.end(),
                     [&](const Vec3& x) { return norm(x - corner) == 0; });
  }
  return n;
}

} // namespace

TEST_CASE("isotropic remeshing keeps a box's planes, corners and label areas",
          "[isotropic_remeshing]") {
  IsotropicRemeshParameters p;
  p.target_edge = 1e-3;

  SECTION("the box's sides as labels") {
    auto m = testing::box(a, a, a);
    for (std::size_t f = 0; f < m.n_faces(); ++f)
      m.face_labels[f] = int(f / 2) + 1; // one label per side
    std::vector<std::pair<std::uint32_t, std::uint32_t>> curves;
    const auto r = isotropic_remesh(m, curves, p);
    INFO(r.n_faces_after << " faces, worst quality " << r.min_quality_after);
    CHECK(check_closed(m).closed());
    CHECK(off_box(m) < 1e-15);
    CHECK(n_corners_kept(m) == 8);
    for (const auto& [label, area] : area_per_label(m))
      CHECK(area == Approx(a * a).epsilon(1e-12));
    CHECK(min_triangle_quality(m) > 0.5);
    // About 6 a^2 / (sqrt(3) / 4 L^2) = 1386 faces of side L.
    CHECK(m.n_faces() > 1000);
    CHECK(m.n_faces() < 2000);
  }
  SECTION("one label, the box's edges as curves") {
    auto m = testing::box(a, a, a);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> curves;
    const auto normal = face_normals(m);
    for (const auto& [edge, faces] : edge_faces(m))
      if (dot(normal[faces[0]], normal[faces[1]]) < 0.5)
        curves.push_back(edge);
    REQUIRE(curves.size() == 12);
    isotropic_remesh(m, curves, p);
    CHECK(off_box(m) < 1e-15);
    CHECK(n_corners_kept(m) == 8);
    CHECK(enclosed_volume(m) == Approx(a * a * a).epsilon(1e-12));
    CHECK(min_triangle_quality(m) > 0.5);
    // The curves come back split along the box's 12 edges, 12 a in all.
    double length = 0;
    for (const auto& [u, v] : curves)
      length += norm(m.vertices[u] - m.vertices[v]);
    CHECK(length == Approx(12 * a).epsilon(1e-12));
  }
  SECTION("one label and no curves: the edges are cut") {
    auto m = testing::box(a, a, a);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> curves;
    isotropic_remesh(m, curves, p);
    // Its vertices are projected onto the box, but triangles span the edges and cut them.
    CHECK(enclosed_volume(m) < a * a * a * (1 - 1e-4));
  }
}

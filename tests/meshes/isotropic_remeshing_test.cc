// Isotropic remeshing against a shape whose every point is known: a 10 mm box. Remeshed to
// 1 mm edges, each vertex stays on the box's planes, the corners stay, every label keeps its
// area, and the triangles come out well shaped; its sharp edges are kept either as label
// boundaries or as curves, and without either they are cut.
#include "meshes/isotropic_remeshing.h"
#include "meshes/mesh_quality.h"
#include "meshes/surface_decimation.h"
#include "meshes/surface_locator.h"
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

TEST_CASE("flat regions coarsened after an isotropic remeshing keep a narrow bump that long "
          "edges cut",
          "[isotropic_remeshing]") {
  // A 20 x 20 x 5 mm block whose top carries a bump h cos^2(pi r / (2 r0)), r0 = 1.5 mm,
  // h = 1.5 mm (a worn element's remnant), on a 0.25 mm grid. Remeshed at 2 mm edges the
  // bump's faces are collapsed into a few long ones that cut through it. Remeshed at 1 mm and
  // then coarsened where flat (coarsen_flat_regions: edges up to 2 mm, 0.125 mm error, the
  // implicit recession's flat edge at its 0.25 mm grid) the bump keeps its 1 mm triangles and
  // its shape, and the flat top, sides and bottom take long ones: far fewer faces than 1 mm;
  // the sides' vertical corners, curves inside one label, stay sharp.
  constexpr double l = 20e-3, z0 = 5e-3, r0 = 1.5e-3, h = 1.5e-3;
  const auto top = [&](double x, double y) {
    const double r = std::hypot(x - l / 2, y - l / 2);
    const double c = std::cos(M_PI * r / (2 * r0));
    return r < r0 ? z0 + h * c * c : z0;
  };
  const auto block =
      testing::height_field_block(80, 80, l, l, top, [](double, double) { return label::base; });
  const auto remeshed = [&](double target, double flat) {
    auto m = block;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> curves;
    const auto normal = face_normals(m);
    for (const auto& [edge, faces] : edge_faces(m)) // the block's vertical edges (one label)
      if (m.face_labels[faces[0]] == m.face_labels[faces[1]] &&
          dot(normal[faces[0]], normal[faces[1]]) < 0.5)
        curves.push_back(edge);
    IsotropicRemeshParameters p;
    p.target_edge = target;
    isotropic_remesh(m, curves, p);
    if (flat > 0)
      coarsen_flat_regions(m, curves, flat, 0.125e-3);
    INFO("target " << target << ", flat " << flat << ": " << m.n_faces() << " faces");
    CHECK(check_closed(m).closed());
    CHECK(surface_quality(m).valid());
    return m;
  };
  const auto coarse = remeshed(2e-3, 0), fine = remeshed(1e-3, 0), adaptive = remeshed(1e-3, 2e-3);
  // How far the block's own vertices (the bump at 0.25 mm) lie from each remeshed surface.
  const double off_coarse = farthest_point(block, coarse).distance,
               off_fine = farthest_point(block, fine).distance,
               off_adaptive = farthest_point(block, adaptive).distance;
  INFO("block off the surfaces at 2 mm: "
       << off_coarse * 1e3 << " mm, 1 mm: " << off_fine * 1e3 << " mm, 1 mm coarsened: "
       << off_adaptive * 1e3 << " mm; faces " << coarse.n_faces() << ", " << fine.n_faces() << ", "
       << adaptive.n_faces() << "; worst quality " << min_triangle_quality(coarse) << ", "
       << min_triangle_quality(fine) << ", " << min_triangle_quality(adaptive));
  CHECK(off_adaptive < off_fine + 0.01e-3); // the bump's 1 mm triangles kept
  CHECK(off_coarse > 1.5 * off_fine);
  CHECK(adaptive.n_faces() < 0.5 * fine.n_faces());
  CHECK(min_triangle_quality(adaptive) > 0.3);
  // The block's vertical corners are curves inside one label (side): no face spans one.
  const auto normal = face_normals(adaptive);
  double worst_axis = 1;
  for (std::size_t f = 0; f < adaptive.n_faces(); ++f)
    if (adaptive.face_labels[f] == label::side)
      worst_axis =
          std::min(worst_axis,
                   std::max({std::abs(normal[f].x), std::abs(normal[f].y), std::abs(normal[f].z)}));
  CHECK(worst_axis > 1 - 1e-12);
  // Volume: the coarsening keeps vertices in place, so flat regions lose nothing.
  CHECK(std::abs(enclosed_volume(adaptive) - enclosed_volume(fine)) < 1e-3 * enclosed_volume(fine));
}

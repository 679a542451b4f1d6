// Labels on a new worn surface (meshes/label_cleanup.h), on a flat-topped block whose top is
// split between the base and an element label along a grid line: a straight boundary is kept
// by the majority filter and a stray face is taken back; a small island joins its
// surroundings while a larger one stays; an element lower than the vanish height joins the
// base while a higher one stands; a tooth of no width along the boundary joins the label it
// points into, unless it has some width or its tip has another face of its own label.
#include "meshes/label_cleanup.h"
#include "meshes/mesh_quality.h"
#include "meshes/sample_generator.h"
#include "test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear::meshes;

namespace {

const int element = label::convex_element(1, 1);

// An n x n block over n mm x n mm, 1 mm high: the top is base below y = split [mm], the
// element label above.
SurfaceMesh split_block(int n, double split) {
  return testing::height_field_block(
      n, n, n * 1e-3, n * 1e-3, [](double, double) { return 1e-3; },
      [&](double, double y) { return y < split * 1e-3 ? label::base : element; });
}

std::size_t count_label(const SurfaceMesh& m, int l) {
  return std::size_t(std::count(m.face_labels.begin(), m.face_labels.end(), l));
}

// The face holding the directed edge a -> b.
std::size_t face_with_edge(const SurfaceMesh& m, std::uint32_t a, std::uint32_t b) {
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (m.triangles[f][std::size_t(k)] == a && m.triangles[f][std::size_t((k + 1) % 3)] == b)
        return f;
  FAIL("no face holds the edge " << a << " -> " << b);
  return 0;
}

// The vertex of the top at grid point (i, j) of split_block(n, ...).
std::uint32_t top_vertex(int n, int i, int j) {
  return std::uint32_t((n + 1) * (n + 1) + i + (n + 1) * j);
}

// The labels of the top's faces off its rim: at the block's corners a top face has two edges
// on the sides, and the majority filter gives it their label.
std::vector<int> inner_top_labels(const SurfaceMesh& m, double side) {
  std::vector<int> labels;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    bool inner = m.face_labels[f] != label::bottom && m.face_labels[f] != label::side;
    for (const auto v : m.triangles[f]) {
      const auto& p = m.vertices[v];
      inner = inner && p.x > 0 && p.y > 0 && p.x < side && p.y < side;
    }
    if (inner)
      labels.push_back(m.face_labels[f]);
  }
  return labels;
}

} // namespace

TEST_CASE("the majority filter keeps a straight label boundary and takes a stray face back",
          "[meshes][labels]") {
  const int n = 6;
  SurfaceMesh m = split_block(n, 3);
  const auto before = inner_top_labels(m, n * 1e-3);
  REQUIRE(before.size() == 2 * (n - 2) * (n - 2)); // the quads off the rim
  smooth_label_boundaries(m, 2);
  // Each face has at most one neighbour across the boundary.
  CHECK(inner_top_labels(m, n * 1e-3) == before);
  // A base face two rows below the boundary given the element's label: all three neighbours
  // are base.
  const auto stray = face_with_edge(m, top_vertex(n, 2, 1), top_vertex(n, 3, 1));
  REQUIRE(m.face_labels[stray] == label::base);
  m.face_labels[stray] = element;
  smooth_label_boundaries(m, 1);
  CHECK(m.face_labels[stray] == label::base);
  CHECK(inner_top_labels(m, n * 1e-3) == before);
}

TEST_CASE("a label's island below the fraction of its largest piece joins its surroundings",
          "[meshes][labels]") {
  const int n = 8;
  SurfaceMesh m = split_block(n, 4); // the element's piece: 32 quads
  // One quad (2 faces) of the base's half given the element's label: 1/32 of its largest piece.
  const auto a = face_with_edge(m, top_vertex(n, 2, 1), top_vertex(n, 3, 1));
  const auto b = face_with_edge(m, top_vertex(n, 3, 2), top_vertex(n, 2, 2));
  REQUIRE(m.face_labels[a] == label::base);
  REQUIRE(m.face_labels[b] == label::base);
  m.face_labels[a] = m.face_labels[b] = element;
  SurfaceMesh kept = m;
  merge_label_islands(kept, 0.02); // 1/32 > 0.02: it stays
  CHECK(kept.face_labels == m.face_labels);
  merge_label_islands(m, 0.05);
  CHECK(m.face_labels[a] == label::base);
  CHECK(m.face_labels[b] == label::base);
  CHECK(count_label(m, element) == 2 * 32);
  CHECK(count_label(m, label::base) == 2 * 32);
}

TEST_CASE("an element standing no higher than the vanish height joins the base",
          "[meshes][labels]") {
  // 2 x 2 quads about (4, 4) mm labelled as the element; its one inner vertex raised by
  // `bump` above the flat top, so the element's height above its foot is `bump`.
  const auto block = [](double bump) {
    return testing::height_field_block(
        8, 8, 8e-3, 8e-3,
        [bump](double x, double y) {
          return std::abs(x - 4e-3) < 1e-6 && std::abs(y - 4e-3) < 1e-6 ? 1e-3 + bump : 1e-3;
        },
        [](double x, double y) {
          return std::abs(x - 4e-3) < 1e-3 && std::abs(y - 4e-3) < 1e-3 ? element : label::base;
        });
  };
  SurfaceMesh low = block(0.2e-3);
  low.roles = sample_roles(true);
  REQUIRE(count_label(low, element) == 8);
  CHECK(merge_vanished_elements(low, 0.25e-3) == std::vector<int>{element});
  CHECK(count_label(low, element) == 0);
  CHECK(count_label(low, label::base) == 2 * 64);
  SurfaceMesh high = block(0.3e-3);
  high.roles = sample_roles(true);
  CHECK(merge_vanished_elements(high, 0.25e-3).empty());
  CHECK(count_label(high, element) == 8);
}

TEST_CASE("a base face of no width along the element's boundary joins the element",
          "[meshes][labels]") {
  // The boundary edge a -> b at y = 2 mm between the base face below and the element's face
  // (a, b, d) above is split by a tip t at height `offset` above its midpoint: the base's
  // tooth (a, b, t) and the element's faces (t, b, d) and (a, t, d). With `second_own`, the
  // element's face (a, t, d) is split about an inner point e and its part (t, d, e) labelled
  // base, so the tip has a second base face.
  const int n = 4;
  const auto tooth = [&](double offset, bool second_own, std::size_t& f_tooth) {
    SurfaceMesh m = split_block(n, 2);
    const auto a = top_vertex(n, 1, 2), b = top_vertex(n, 2, 2), d = top_vertex(n, 2, 3);
    const auto above = face_with_edge(m, a, b);
    REQUIRE(m.face_labels[above] == element);
    REQUIRE(m.triangles[above][2] == d);
    const auto t = std::uint32_t(m.n_vertices());
    m.vertices.push_back((m.vertices[a] + m.vertices[b]) * 0.5 + Vec3{0, offset, 0});
    m.triangles[above] = {a, b, t};
    m.face_labels[above] = label::base;
    f_tooth = above;
    m.triangles.push_back({t, b, d});
    m.face_labels.push_back(element);
    if (second_own) {
      const auto e = std::uint32_t(m.n_vertices());
      m.vertices.push_back((m.vertices[a] + m.vertices[t] + m.vertices[d]) / 3.0);
      m.triangles.push_back({a, t, e});
      m.triangles.push_back({t, d, e});
      m.triangles.push_back({d, a, e});
      m.face_labels.insert(m.face_labels.end(), {element, label::base, element});
    } else {
      m.triangles.push_back({a, t, d});
      m.face_labels.push_back(element);
    }
    REQUIRE(check_closed(m).closed());
    return m;
  };
  std::size_t f = 0;
  SECTION("a sliver whose tip has no other base face joins, with its neighbour's patch") {
    SurfaceMesh m = tooth(1e-7, false, f);
    REQUIRE(triangle_quality(m.vertices[m.triangles[f][0]], m.vertices[m.triangles[f][1]],
                             m.vertices[m.triangles[f][2]]) < 1e-3);
    std::vector<int> patch(m.n_faces());
    for (std::size_t g = 0; g < patch.size(); ++g)
      patch[g] = int(g);
    const int patch_beside = -1;
    patch[m.n_faces() - 1] = patch_beside; // (a, t, d), across the tooth's edge t -> a
    const auto labels = m.face_labels;
    CHECK(join_label_teeth(m, patch) == 1);
    CHECK(m.face_labels[f] == element);
    CHECK(patch[f] == patch_beside);
    for (std::size_t g = 0; g < m.n_faces(); ++g)
      if (g != f)
        CHECK(m.face_labels[g] == labels[g]);
  }
  SECTION("a tooth of some width stays") {
    SurfaceMesh m = tooth(0.3e-3, false, f);
    std::vector<int> patch(m.n_faces(), 0);
    CHECK(join_label_teeth(m, patch) == 0);
    CHECK(m.face_labels[f] == label::base);
  }
  SECTION("a sliver whose tip has another base face stays") {
    SurfaceMesh m = tooth(1e-7, true, f);
    std::vector<int> patch(m.n_faces(), 0);
    CHECK(join_label_teeth(m, patch) == 0);
    CHECK(m.face_labels[f] == label::base);
  }
}

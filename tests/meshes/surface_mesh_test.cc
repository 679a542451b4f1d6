#include "meshes/face_field.h"
#include "meshes/surface_mesh.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

using namespace wear::meshes;

TEST_CASE("box: area, volume, closedness, normals", "[meshes]") {
  auto m = testing::box(2, 3, 5);
  m.validate("box");
  CHECK(total_area(m) == Approx(2 * (6 + 10 + 15)).epsilon(1e-14));
  CHECK(enclosed_volume(m) == Approx(30).epsilon(1e-14));
  const auto r = check_closed(m);
  CHECK(r.closed());
  CHECK(r.consistently_oriented());
  const auto vn = vertex_normals(m);
  // Corner (a, b, c) touches +x, +y, +z faces; area weighting favours the larger faces.
  const Vec3 top = vn[7];
  CHECK(top.x > 0);
  CHECK(top.y > 0);
  CHECK(top.z > 0);
  CHECK(norm(top) == Approx(1).epsilon(1e-14));
  const auto bb = bounding_box(m);
  CHECK(bb.extent() == Vec3{2, 3, 5});
  // volume above z = 0 of the +z faces: 2*3*5
  auto labelled = m;
  for (std::size_t f = 2; f < 4; ++f)
    labelled.face_labels[f] = label::base;
  CHECK(volume_above_plane(labelled, label::base, 0.0) == Approx(30).epsilon(1e-14));
}

TEST_CASE("orientation repair and hole detection", "[meshes]") {
  auto m = testing::box();
  std::swap(m.triangles[3][1], m.triangles[3][2]);
  std::swap(m.triangles[7][1], m.triangles[7][2]);
  CHECK(check_closed(m).n_misoriented_edges > 0);
  const auto rev = m.revision();
  CHECK(orient_outward(m) == 2);
  CHECK(m.revision() > rev);
  CHECK(check_closed(m).consistently_oriented());
  CHECK(enclosed_volume(m) == Approx(1));

  // An inside-out box is turned outward as a whole.
  auto inv = testing::box();
  for (auto& t : inv.triangles)
    std::swap(t[1], t[2]);
  CHECK(enclosed_volume(inv) == Approx(-1));
  orient_outward(inv);
  CHECK(enclosed_volume(inv) == Approx(1));

  auto open = testing::box();
  open.triangles.pop_back();
  open.face_labels.pop_back();
  const auto r = check_closed(open);
  CHECK_FALSE(r.closed());
  CHECK(r.n_boundary_edges == 3);
}

TEST_CASE("adjacency", "[meshes]") {
  const auto m = testing::box();
  const auto ef = edge_faces(m);
  CHECK(ef.size() == 18); // Euler: V - E + F = 8 - 18 + 12 = 2
  const auto vf = vertex_faces(m);
  std::size_t total = 0;
  for (std::size_t v = 0; v < m.n_vertices(); ++v)
    total += vf.offsets[v + 1] - vf.offsets[v];
  CHECK(total == 36);
}

TEST_CASE("face field is tied to a revision", "[meshes]") {
  auto m = testing::box();
  FaceField<double> wear("wear volume", "m^3", Extensivity::extensive, m, 0.5);
  CHECK(wear.sum() == Approx(6.0));
  wear.check_matches(m);
  m.bump_revision();
  CHECK_THROWS_WITH(wear.check_matches(m), Catch::Contains("revision"));
}

TEST_CASE("label names round-trip", "[meshes]") {
  for (int id : {1, 2, 3, 4, 11, 15, 24, 55, 99})
    CHECK(label::from_name(label::name(id)) == id);
  CHECK(label::name(label::convex_element(3, 2)) == "C32");
  CHECK_THROWS(label::from_name("C0x"));
}

TEST_CASE("label roles: set, replaced, free by default, named", "[meshes]") {
  LabelRoles r;
  CHECK(r.of(3) == FaceRole::free);
  r.set(3, FaceRole::wearing);
  r.set(1, FaceRole::clamped);
  r.set(2002, FaceRole::held);
  CHECK(r.wears(3));
  CHECK(r.clamped(1));
  CHECK(r.held(2002));
  CHECK(r.of(2) == FaceRole::free);
  r.set(3, FaceRole::free);
  CHECK(!r.wears(3));
  CHECK(r.entries().size() == 3);
  CHECK(r.entries().front().first == 1); // sorted by label
  CHECK(r.any(FaceRole::held));
  CHECK(!r.any(FaceRole::wearing));
  for (FaceRole role : {FaceRole::free, FaceRole::wearing, FaceRole::clamped, FaceRole::held})
    CHECK(role_from_name(role_name(role)) == role);
  CHECK_THROWS_WITH(role_from_name("worn"), Catch::Contains("'worn'"));
}

TEST_CASE("validate rejects bad indices and NaN", "[meshes]") {
  auto m = testing::box();
  m.triangles[0][0] = 99;
  CHECK_THROWS_WITH(m.validate("test mesh"),
                    Catch::Contains("test mesh") && Catch::Contains("vertex 99"));
  auto n = testing::box();
  n.vertices[0].x = std::nan("");
  CHECK_THROWS_WITH(n.validate("test mesh"), Catch::Contains("non-finite"));
}

TEST_CASE("keeping some faces drops the vertices no kept face uses, the order kept", "[meshes]") {
  // Two boxes, the second (2 x 3 x 5, labelled base) after the first's 8 vertices.
  auto m = testing::box();
  const auto second = testing::box(2, 3, 5);
  for (const auto& x : second.vertices)
    m.vertices.push_back(x + Vec3{10, 0, 0});
  for (auto t : second.triangles) {
    for (auto& v : t)
      v += 8;
    m.triangles.push_back(t);
    m.face_labels.push_back(label::base);
  }
  std::vector<char> keep(m.n_faces(), 0);
  for (std::size_t f = 12; f < 24; ++f)
    keep[f] = 1;
  const auto new_index = keep_faces(m, keep);
  REQUIRE(new_index.size() == 16);
  for (std::uint32_t v = 0; v < 8; ++v) {
    CHECK(new_index[v] == no_vertex);
    CHECK(new_index[v + 8] == v);
  }
  CHECK(m.n_vertices() == 8);
  CHECK(m.n_faces() == 12);
  CHECK(m.labels() == std::vector<int>{label::base});
  CHECK(check_closed(m).closed());
  CHECK(enclosed_volume(m) == Approx(30).epsilon(1e-14));
  CHECK(m.vertices[0] == second.vertices[0] + Vec3{10, 0, 0});
}

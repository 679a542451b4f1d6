#include "meshes/mesh_quality.h"
#include "meshes/tester_walls.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear::meshes;

TEST_CASE("quality of a clean box", "[meshes][quality]") {
  const auto m = testing::box();
  const auto n = face_normals(m);
  const auto q = surface_quality(m, &n);
  CHECK(q.valid());
  CHECK(q.min_angle_deg == Approx(45));
  // right isosceles triangle: l_max = sqrt 2, r_in = (2 - sqrt 2) / 2
  CHECK(q.max_aspect_ratio == Approx(std::sqrt(2.0) / (std::sqrt(3.0) * (2 - std::sqrt(2.0)))));
}

TEST_CASE("equilateral triangle has aspect ratio 1", "[meshes][quality]") {
  SurfaceMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}};
  m.triangles = {{0, 1, 2}};
  m.face_labels = {label::wall};
  const auto q = surface_quality(m);
  CHECK(q.max_aspect_ratio == Approx(1).epsilon(1e-12));
  CHECK(q.min_angle_deg == Approx(60).epsilon(1e-12));
}

TEST_CASE("a vertex pushed through the opposite face is found", "[meshes][quality]") {
  auto m = testing::box();
  const auto n0 = face_normals(m);
  m.vertices[7] = {0.5, 0.5, -0.5}; // top corner pushed through the bottom face
  const auto q = surface_quality(m, &n0);
  CHECK_FALSE(q.valid());
  CHECK(q.n_self_intersections > 0);
  CHECK(q.n_inverted > 0);
  CHECK(q.first_bad_face >= 0);
}

TEST_CASE("two crossing triangles intersect, separated ones do not", "[meshes][quality]") {
  SurfaceMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, -1}, {0.2, 0.2, 1}, {0.3, 0.5, 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  m.face_labels = {4, 4};
  CHECK(find_self_intersections(m).size() == 1);
  m.vertices[3].z = 0.5; // lift the second triangle off the plane
  m.vertices[5].z = 0.5;
  CHECK(find_self_intersections(m).empty());
}

TEST_CASE("degenerate face is reported", "[meshes][quality]") {
  auto m = testing::box();
  m.vertices.push_back({0.5, 0.0, 0.0});
  m.triangles.push_back({0, 1, 8}); // collinear: zero area
  m.face_labels.push_back(label::wall);
  const auto q = surface_quality(m);
  CHECK(q.n_degenerate == 1);
  CHECK(q.first_bad_face == 12);
}

TEST_CASE("self-intersection search scales (grid, not all pairs)", "[meshes][quality]") {
  TesterGeometry t;
  t.wall_mesh_size = 2e-3; // ~ 100k triangles on the floor
  const auto w = generate_tester_walls(t);
  REQUIRE(w.floor.n_faces() > 50000);
  CHECK(find_self_intersections(w.floor).empty());
}

TEST_CASE("two faces folded flat onto each other over their edge are a fold", "[meshes][quality]") {
  // Face 0 lies in z = 0 with normal +z; face 1 shares its edge (1, 2). Folded: its third
  // vertex lies on face 0's side of the edge, so it covers face 0 with the opposite normal
  // (the self-intersection test skips faces sharing an edge). Unfolded: it continues the plane.
  for (const bool folded : {true, false}) {
    SurfaceMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, folded ? Vec3{0.3, 0.3, 0} : Vec3{1, 1, 0}};
    m.triangles = {{0, 1, 2}, {2, 1, 3}};
    m.face_labels = {label::base, label::side};
    const auto q = surface_quality(m);
    CHECK(q.n_folded_edges == (folded ? 1u : 0u));
    CHECK(q.valid() == !folded);
    if (folded)
      CHECK(q.bad_faces.size() == 2);
  }
}

#include "meshes/stl_io.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <random>

using namespace wear::meshes;

namespace {
// Faces compared by their corner coordinates and labels (vertex numbering may change).
void require_same_faces(const SurfaceMesh& a, const SurfaceMesh& b) {
  REQUIRE(a.n_faces() == b.n_faces());
  for (std::size_t f = 0; f < a.n_faces(); ++f) {
    CHECK(a.face_labels[f] == b.face_labels[f]);
    for (int k = 0; k < 3; ++k)
      CHECK(a.vertices[a.triangles[f][k]] == b.vertices[b.triangles[f][k]]);
  }
}

SurfaceMesh jittered_box() {
  auto m = testing::box(0.1, 0.2, 0.3);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  for (auto& v : m.vertices)
    v += Vec3{u(rng), u(rng), u(rng)};
  // Two labels, faces grouped by label as the ASCII writer emits them.
  for (std::size_t f = 6; f < m.n_faces(); ++f)
    m.face_labels[f] = label::convex_element(1, 2);
  return m;
}
} // namespace

TEST_CASE("ASCII STL round trip is exact for doubles", "[meshes][stl]") {
  const auto m = jittered_box();
  write_stl(m, "roundtrip_ascii.stl", StlFormat::ascii);
  const auto r = read_stl("roundtrip_ascii.stl");
  require_same_faces(m, r);
  CHECK(r.n_vertices() == 8);
  CHECK(check_closed(r).closed());
}

TEST_CASE("binary STL round trip is exact", "[meshes][stl]") {
  const auto m = jittered_box();
  write_stl(m, "roundtrip_1.stl", StlFormat::binary);
  const auto r1 = read_stl("roundtrip_1.stl");
  // float32 quantisation happens once; from then on the round trip is exact.
  for (std::size_t v = 0; v < r1.n_vertices(); ++v)
    for (int d = 0; d < 3; ++d)
      CHECK(double(float(r1.vertices[v][d])) == r1.vertices[v][d]);
  write_stl(r1, "roundtrip_2.stl", StlFormat::binary);
  const auto r2 = read_stl("roundtrip_2.stl");
  require_same_faces(r1, r2);
  CHECK(r1.face_labels[11] == label::convex_element(1, 2));
}

TEST_CASE("bad STL input fails with a message naming the file", "[meshes][stl]") {
  CHECK_THROWS_WITH(read_stl("no_such_file.stl"),
                    Catch::Contains("no_such_file.stl") && Catch::Contains("cannot be opened"));
  {
    std::ofstream o("malformed.stl");
    o << "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0\n";
  }
  CHECK_THROWS_WITH(read_stl("malformed.stl"),
                    Catch::Contains("malformed.stl") && Catch::Contains("line 5"));
  {
    std::ofstream o("two_vertices.stl");
    o << "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n endloop\n"
         " endfacet\nendsolid\n";
  }
  CHECK_THROWS_WITH(read_stl("two_vertices.stl"), Catch::Contains("expected 3"));
  {
    std::ofstream o("truncated.stl", std::ios::binary);
    char header[80] = {};
    o.write(header, 80);
    const std::uint32_t n = 10;
    o.write(reinterpret_cast<const char*>(&n), 4);
    const char facet[50] = {};
    o.write(facet, 50);
  }
  CHECK_THROWS_WITH(read_stl("truncated.stl"), Catch::Contains("truncated.stl"));
}

TEST_CASE("writing into a missing folder fails clearly", "[meshes][stl]") {
  CHECK_THROWS_WITH(write_stl(testing::box(), "no/such/folder/x.stl", StlFormat::ascii),
                    Catch::Contains("no/such/folder/x.stl"));
}

#include "meshes/tester_walls.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear::meshes;

TEST_CASE("tester walls: areas, normals, cut planes", "[meshes][walls]") {
  TesterGeometry t;
  const auto w = generate_tester_walls(t);
  const double pi = 3.14159265358979323846, Th = t.sector_angle_deg * pi / 180;
  const double ri = t.inner_radius, ro = t.outer_radius, H = t.wall_height;
  // Chords of the polygonal arcs lose area of order (dtheta)^2 / 6.
  CHECK(total_area(w.floor) == Approx(Th / 2 * (ro * ro - ri * ri)).epsilon(1e-4));
  CHECK(total_area(w.inner) == Approx(Th * ri * H).epsilon(1e-4));
  CHECK(total_area(w.outer) == Approx(Th * ro * H).epsilon(1e-4));
  for (const auto& n : face_normals(w.floor))
    CHECK(n.z == Approx(1));
  const auto c_in = face_centroids(w.inner);
  const auto n_in = face_normals(w.inner);
  for (std::size_t f = 0; f < n_in.size(); ++f)
    CHECK(dot(n_in[f], normalized(Vec3{c_in[f].x, c_in[f].y, 0})) > 0.99);
  const auto c_out = face_centroids(w.outer);
  const auto n_out = face_normals(w.outer);
  for (std::size_t f = 0; f < n_out.size(); ++f)
    CHECK(dot(n_out[f], normalized(Vec3{c_out[f].x, c_out[f].y, 0})) < -0.99);
  REQUIRE(w.consolidator);
  for (const auto& n : face_normals(*w.consolidator))
    CHECK(n.z == Approx(-1));
  // Every floor vertex lies in the sector, with vertices exactly on both cut planes.
  int on_start = 0, on_end = 0;
  for (const auto& v : w.floor.vertices) {
    const double th = std::atan2(v.y, v.x);
    const double r = std::hypot(v.x, v.y);
    CHECK(r >= ri - 1e-12);
    CHECK(r <= ro + 1e-12);
    on_start += std::abs(v.y) < 1e-15;
    on_end += std::abs(th - Th) < 1e-12;
  }
  CHECK(on_start > 1);
  CHECK(on_end == on_start);
  // No edge longer than the requested size.
  for (const auto& tri : w.floor.triangles)
    for (int k = 0; k < 3; ++k)
      CHECK(norm(w.floor.vertices[tri[k]] - w.floor.vertices[tri[(k + 1) % 3]]) <=
            t.wall_mesh_size * std::sqrt(2.0) + 1e-12);
}

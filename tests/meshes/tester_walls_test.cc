#include "meshes/constants.h"
#include "meshes/tester_walls.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace wear::meshes;
using wear::pi;

TEST_CASE("tester walls: areas, normals, cut planes", "[meshes][walls]") {
  TesterGeometry t;
  const auto w = generate_tester_walls(t);
  const double Th = t.sector_angle_deg * pi / 180;
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

TEST_CASE("the sample holder: a closed frame whose pocket is the sample's sides and bottom",
          "[meshes][walls][holder]") {
  SampleGeometry s;
  TesterGeometry t;
  const double W = s.width, L = s.length, T = s.thickness, w = t.holder_rim_width;
  const auto h = generate_holder(s, t);
  h.validate("holder");
  // Closed and outward: its volume is the frame's, outer box less the pocket (exact for
  // planar faces up to round-off).
  const auto closed = check_closed(h);
  CHECK(closed.closed());
  CHECK(closed.consistently_oriented());
  CHECK(enclosed_volume(h) ==
        Approx((W + 2 * w) * (L + 2 * w) * (T + w) - W * L * T).epsilon(1e-12));
  // The pocket is exactly the sample's sides and bottom; the rest is what the bed meets.
  const auto area = area_per_label(h);
  CHECK(area.at(label::pocket) == Approx(2 * (W + L) * T + W * L).epsilon(1e-12));
  CHECK(
      area.at(label::wall) ==
      Approx(2 * (W + 2 * w) * (L + 2 * w) - W * L + 2 * (W + L + 4 * w) * (T + w)).epsilon(1e-12));
  // The rim top lies in the wear face's plane z = T, flush; every face on a box plane.
  const auto n = face_normals(h);
  const auto c = face_centroids(h);
  int rim_top = 0;
  for (std::size_t f = 0; f < h.n_faces(); ++f) {
    CHECK(std::max({std::abs(n[f].x), std::abs(n[f].y), std::abs(n[f].z)}) == 1.0);
    if (h.face_labels[f] == label::wall && n[f].z == 1.0) {
      CHECK(c[f].z == T);
      CHECK((std::abs(c[f].x) > W / 2 || std::abs(c[f].y) > L / 2));
      ++rim_top;
    }
  }
  CHECK(rim_top > 0);
  // No edge longer than the wall mesh size's diagonal.
  for (const auto& tri : h.triangles)
    for (int k = 0; k < 3; ++k)
      CHECK(norm(h.vertices[tri[k]] - h.vertices[tri[(k + 1) % 3]]) <=
            std::min(t.wall_mesh_size, w) * std::sqrt(2.0) + 1e-12);
}

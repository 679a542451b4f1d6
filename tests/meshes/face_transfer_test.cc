// Nearest-face queries against brute force, and face-field transfer between two
// triangulations of one surface: exact conservation of extensive fields per label, and the
// reproduction of a smooth density within the sampling resolution.
#include "meshes/face_transfer.h"
#include "meshes/structured_grid.h"
#include "meshes/surface_locator.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace wear::meshes;

namespace {
// A wavy 60 x 40 mm plate z = 1 mm sin(...) as two labels (x < 30 mm: base, else C11).
SurfaceMesh wavy_plate(int n_u, int n_v, Diagonals diagonals) {
  auto m = structured_grid(
      n_u, n_v,
      [](double u, double v) {
        const double x = 0.06 * u, y = 0.04 * v;
        return Vec3{x, y, 1e-3 * std::sin(60 * x) * std::cos(50 * y)};
      },
      false, label::base, diagonals);
  const auto c = face_centroids(m);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (c[f].x > 0.03)
      m.face_labels[f] = label::convex_element(1, 1);
  return m;
}
} // namespace

TEST_CASE("nearest face equals the brute-force nearest face", "[meshes][locator]") {
  const auto m = wavy_plate(30, 20, Diagonals::alternating);
  const SurfaceLocator locator(m);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-0.01, 0.07), y(-0.01, 0.05), z(-0.01, 0.01);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p{x(rng), y(rng), z(rng)};
    for (const int label : {-1, label::base}) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t f = 0; f < m.n_faces(); ++f) {
        if (label >= 0 && m.face_labels[f] != label)
          continue;
        const auto& t = m.triangles[f];
        best = std::min(best, norm(closest_point_on_triangle(m.vertices[t[0]], m.vertices[t[1]],
                                                             m.vertices[t[2]], p)
                                       .point -
                                   p));
      }
      const auto hit = locator.nearest(p, label);
      REQUIRE(hit.face >= 0);
      CHECK(hit.distance == Approx(best).margin(1e-15));
      if (label >= 0)
        CHECK(m.face_labels[hit.face] == label);
    }
  }
  CHECK(one_sided_distance(m, m) < 1e-15);
}

TEST_CASE("face fields transfer conservatively between two triangulations", "[meshes][transfer]") {
  const auto coarse = wavy_plate(24, 16, Diagonals::uniform);
  const auto fine = wavy_plate(41, 27, Diagonals::alternating);
  const auto area = face_areas(coarse);
  const auto centroid = face_centroids(coarse);
  // A smooth density rho(x, y) [m^3 / m^2] as an extensive field (rho A), a vector field, and
  // the same density as an intensive field.
  const auto rho = [](const Vec3& c) { return 1e-6 * (1 + 0.5 * std::sin(80 * c.x + 40 * c.y)); };
  FaceField<double> volume("removed volume", "m^3", Extensivity::extensive, coarse);
  FaceField<Vec3> force("force", "N", Extensivity::extensive, coarse);
  FaceField<double> depth("wear depth", "m", Extensivity::intensive, coarse);
  for (std::size_t f = 0; f < coarse.n_faces(); ++f) {
    volume[f] = rho(centroid[f]) * area[f];
    force[f] = Vec3{1, -2, 3} * area[f];
    depth[f] = rho(centroid[f]);
  }
  const FaceTransfer transfer(coarse, fine);
  const auto v2 = transfer.apply(volume);
  const auto f2 = transfer.apply(force);
  const auto d2 = transfer.apply(depth);
  CHECK(v2.revision() == fine.revision());
  CHECK(transfer.n_relabelled() == 0);
  // Exact per label: every sample stays on its label.
  std::map<int, double> before, after;
  for (std::size_t f = 0; f < coarse.n_faces(); ++f)
    before[coarse.face_labels[f]] += volume[f];
  for (std::size_t g = 0; g < fine.n_faces(); ++g)
    after[fine.face_labels[g]] += v2[g];
  for (const auto& [label, v] : before)
    CHECK(after[label] == Approx(v).epsilon(1e-12));
  const Vec3 total = force.sum(), total2 = f2.sum();
  for (int d = 0; d < 3; ++d)
    CHECK(total2[d] == Approx(total[d]).epsilon(1e-12));
  // The density is reproduced to the sampling resolution (coarse face / 4 per edge): the
  // area-weighted mean error of the transferred density below 3 %, intensive likewise.
  const auto area2 = face_areas(fine);
  const auto centroid2 = face_centroids(fine);
  double err = 0, err_intensive = 0, a_sum = 0;
  for (std::size_t g = 0; g < fine.n_faces(); ++g) {
    const double exact = rho(centroid2[g]);
    err += std::abs(v2[g] / area2[g] - exact) / exact * area2[g];
    err_intensive += std::abs(d2[g] - exact) / exact * area2[g];
    a_sum += area2[g];
  }
  INFO("mean relative density error " << err / a_sum << ", intensive " << err_intensive / a_sum);
  CHECK(err / a_sum < 0.03);
  CHECK(err_intensive / a_sum < 0.03);
  // A field of another revision is refused.
  SurfaceMesh moved = coarse;
  moved.bump_revision();
  CHECK_THROWS_WITH(transfer.apply(FaceField<double>("x", "m^3", Extensivity::extensive, moved)),
                    Catch::Contains("revision"));
}

TEST_CASE("the farthest unworn face is the one moved farthest off the original surface",
          "[meshes][locator]") {
  // The plate's base half does not wear, its C11 half does. The C11 half is lowered by 2 mm
  // (wear: not counted; the seam stays) and one base face by 0.3 mm beside it (an evolution that
  // moved what must stay): the farthest unworn face is that one, 0.3 mm off, at its own centroid.
  auto original = wavy_plate(30, 20, Diagonals::alternating);
  original.roles.set(label::convex_element(1, 1), FaceRole::wearing);
  original.roles.set(label::base, FaceRole::free);
  CHECK(farthest_unworn_face(original, original).distance < 1e-15);
  auto moved = original;
  const auto centroid = face_centroids(original);
  std::size_t lowered = 0;
  // Vertices on the seam belong to base faces too and stay.
  std::vector<char> on_base(moved.n_vertices(), 0);
  for (std::size_t f = 0; f < moved.n_faces(); ++f)
    if (!moved.face_wears(f))
      for (const auto v : moved.triangles[f])
        on_base[v] = 1;
  for (std::size_t v = 0; v < moved.n_vertices(); ++v)
    if (!on_base[v])
      moved.vertices[v].z -= 2e-3;
  // A base face away from the seam, all three vertices lowered.
  for (std::size_t f = 0; f < moved.n_faces(); ++f)
    if (!moved.face_wears(f) && std::abs(centroid[f].x - 0.015) < 1e-3 &&
        std::abs(centroid[f].y - 0.02) < 1e-3) {
      lowered = f;
      break;
    }
  for (const auto v : moved.triangles[lowered])
    moved.vertices[v].z -= 0.3e-3;
  const auto o = farthest_unworn_face(moved, original);
  REQUIRE(o.face >= 0);
  CHECK(std::size_t(o.face) == lowered);
  CHECK(o.label == label::base);
  // The lowered face lies 0.3 mm below its old place, nearer to the slopes of the wave:
  // between 0.15 and 0.3 mm from the old surface.
  CHECK(o.distance <= 0.3e-3 + 1e-12);
  CHECK(o.distance > 0.15e-3);
  CHECK(norm(o.centroid - face_centroids(moved)[lowered]) < 1e-15);
}

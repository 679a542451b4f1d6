// The area-weighted node recession shared by both deformation schemes: a uniform depth on a
// flat plate moves every wear-face vertex straight down by that depth (the vertices it shares
// with the side too), the depth it reports is the displacement's length, and vertices
// without wearing faces stay. Spreading removed volume around a fold: the total is conserved
// to round-off, no face goes negative, only wearing faces within the ring count receive
// volume, and a point load diffuses into a neighbourhood whose size grows with the ring count.
#include "meshes/recession.h"
#include "meshes/structured_grid.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>

using namespace wear::meshes;
using wear::meshes::testing::uniform_depth_volume;

namespace {
// A flat 20 x 20 mm plate, 20 x 20 quads; the strip x > 15 mm is a non-wearing side.
SurfaceMesh plate() {
  auto m = structured_grid(
      20, 20,
      [](double u, double v) {
        return Vec3{0.02 * u, 0.02 * v, 0};
      },
      false, label::base);
  const auto c = face_centroids(m);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (c[f].x > 0.015)
      m.face_labels[f] = label::side;
  m.roles.set(label::base, FaceRole::wearing); // the side keeps no role: free
  return m;
}
} // namespace

TEST_CASE("area-weighted recession of a uniform depth: straight down, by that depth",
          "[meshes][recession]") {
  const auto m = plate();
  const std::vector<double> v = uniform_depth_volume(m, 2e-4);
  const auto depth = area_weighted_depth(m, v);
  const auto displacement = area_weighted_recession(m, v);
  std::vector<char> on_wear_face(m.n_vertices(), 0);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (m.face_wears(f))
      for (const auto k : m.triangles[f])
        on_wear_face[k] = 1;
  std::size_t n_moved = 0;
  for (std::size_t k = 0; k < m.n_vertices(); ++k) {
    if (!on_wear_face[k]) {
      CHECK(depth[k] == 0);
      CHECK(norm(displacement[k]) == 0);
      continue;
    }
    ++n_moved;
    CHECK(depth[k] == Approx(2e-4).epsilon(1e-12));
    CHECK(norm(displacement[k]) == Approx(depth[k]).epsilon(1e-12));
    // The plate's outward normal is +z or -z; either way the motion is along it, inward.
    CHECK(std::abs(displacement[k].x) < 1e-15);
    CHECK(std::abs(displacement[k].y) < 1e-15);
  }
  CHECK(n_moved > 0);
  CHECK(n_moved < m.n_vertices());
}

TEST_CASE("spreading removed volume keeps the total and stays local", "[meshes][recession]") {
  const auto m = plate();
  const auto centroid = face_centroids(m);
  // All the volume on one face near the middle of the wearing part.
  std::uint32_t seed = 0;
  double best = 1e9;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const double d = norm(centroid[f] - Vec3{0.008, 0.01, 0});
    if (m.face_wears(f) && d < best)
      best = d, seed = std::uint32_t(f);
  }
  const double total = 1e-9; // [m^3]
  double previous_peak = 2 * total;
  for (const int rings : {2, 4, 8}) {
    std::vector<double> v(m.n_faces(), 0);
    v[seed] = total;
    const double moved = spread_removed_volume(m, v, {seed}, rings);
    const double sum = std::accumulate(v.begin(), v.end(), 0.0);
    CHECK(std::abs(sum - total) < 1e-12 * total);
    double peak = 0, reach = 0;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
      CHECK(v[f] >= 0);
      if (v[f] > 0) {
        CHECK(m.face_wears(f)); // nothing onto the side strip
        // faces are 1 mm; k vertex rings reach at most about k + 1 face widths away
        reach = std::max(reach, norm(centroid[f] - centroid[seed]));
      }
      peak = std::max(peak, v[f]);
    }
    CHECK(reach < (rings + 1.5) * 1.5e-3);
    CHECK(reach > 0.5 * rings * 1e-3);
    CHECK(peak < previous_peak); // a wider region flattens the load further
    // every other face started empty, so what moved is what left the seed
    CHECK(moved == Approx(total - v[seed]).epsilon(1e-9));
    previous_peak = peak;
  }
}

TEST_CASE("spreading leaves a uniform depth unchanged", "[meshes][recession]") {
  const auto m = plate();
  const std::vector<double> v = uniform_depth_volume(m, 2e-4);
  auto spread = v;
  const double moved = spread_removed_volume(m, spread, {0, 1, 2}, 8);
  CHECK(moved < 1e-12 * std::accumulate(v.begin(), v.end(), 0.0));
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    CHECK(spread[f] == Approx(v[f]).epsilon(1e-12).margin(1e-30));
}

TEST_CASE("the role a label carries decides which faces recede, not the label's number",
          "[meshes][recession]") {
  // The plate's wear face relabelled 7 (a number no convention gives a role) recedes only
  // when its role says it wears; the base label with no role stays put.
  auto m = plate();
  for (auto& l : m.face_labels)
    if (l == label::base)
      l = 7;
  const auto area = face_areas(m);
  std::vector<double> v(m.n_faces(), 0);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (m.face_labels[f] == 7)
      v[f] = 2e-4 * area[f];
  const auto moved_most = [&](const SurfaceMesh& s) {
    double d = 0;
    for (const auto& x : area_weighted_recession(s, v))
      d = std::max(d, norm(x));
    return d;
  };
  CHECK(moved_most(m) == 0); // label 7 has no role yet: free
  m.roles.set(7, FaceRole::wearing);
  CHECK(moved_most(m) == Approx(2e-4).epsilon(1e-12));
  m.roles.set(7, FaceRole::clamped);
  CHECK(moved_most(m) == 0);
}

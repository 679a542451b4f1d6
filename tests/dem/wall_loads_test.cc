// The DEM's window loads as FaceFields: windows add face by face (sums conserved), loads
// follow a mesh in another frame with impulse vectors rotated and scalar loads unchanged,
// loads of another mesh revision are refused rather than silently mixed, and the
// coarse-grained traction of a real DEM window keeps its force and moment.
#include "dem/wear/wall_loads.h"
#include "meshes/sample_frame.h"
#include "meshes/structured_grid.h"
#include "meshes/surface_locator.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

using namespace wear;

namespace {
meshes::SurfaceMesh two_triangles() {
  meshes::SurfaceMesh m;
  m.vertices = {{0, 0, 0}, {1e-3, 0, 0}, {1e-3, 1e-3, 0}, {0, 1e-3, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.face_labels = {meshes::label::base, meshes::label::base};
  return m;
}

dem::WallLoads window(const meshes::SurfaceMesh& m, double scale) {
  dem::WearIntegrals wi;
  wi.impulse = {{1 * scale, 2, -3}, {0.5, -1, -2 * scale}};
  wi.normal_impulse = {3 * scale, 2};
  wi.archard = {0.1, 0.2 * scale};
  wi.sliding_work = {0.01 * scale, 0.02};
  wi.contact_steps = {10, 20 * scale};
  return dem::wall_loads(wi, {1e-12 * scale, 2e-12}, m, 0.5);
}
} // namespace

TEST_CASE("wall loads: windows add face by face and keep their totals", "[wall_loads]") {
  const auto m = two_triangles();
  auto sum = dem::WallLoads::zero(m);
  const auto a = window(m, 1), b = window(m, 3);
  sum += a;
  sum += b;
  CHECK(sum.duration == 1.0);
  CHECK(sum.normal_impulse.sum() == Approx(a.normal_impulse.sum() + b.normal_impulse.sum()));
  CHECK(sum.wear_volume[0] == Approx(4e-12));
  CHECK(sum.impulse[1].z == Approx(-2 - 6));
  CHECK(sum.archard.extensive());
  CHECK(sum.archard.revision() == m.revision());
}

TEST_CASE("wall loads: following another frame rotates impulses only", "[wall_loads]") {
  const auto m = two_triangles();
  meshes::SamplePlacement pl;
  pl.incline_deg = 5;
  const meshes::SampleFrame frame(meshes::SampleGeometry{}, pl);
  const auto placed = frame.place_in_tester(m);
  const auto in_tester = window(placed, 2);
  const auto in_sample =
      in_tester.follow(m, [&](const meshes::Vec3& v) { return frame.vector_to_sample(v); });
  CHECK(in_sample.impulse.revision() == m.revision());
  for (std::size_t f = 0; f < 2; ++f) {
    CHECK(norm(in_sample.impulse[f] - frame.vector_to_sample(in_tester.impulse[f])) == 0);
    CHECK(norm(in_sample.impulse[f]) == Approx(norm(in_tester.impulse[f])).epsilon(1e-14));
    CHECK(in_sample.normal_impulse[f] == in_tester.normal_impulse[f]);
    CHECK(in_sample.archard[f] == in_tester.archard[f]);
  }
}

TEST_CASE("wall loads: loads of another mesh revision are refused", "[wall_loads]") {
  const auto m = two_triangles();
  auto other = m;
  other.bump_revision();
  auto sum = dem::WallLoads::zero(m);
  CHECK_THROWS_WITH(sum += window(other, 1), Catch::Contains("revision"));
  dem::WearIntegrals short_integrals;
  short_integrals.impulse = {{0, 0, 1}};
  CHECK_THROWS_WITH(dem::wall_loads(short_integrals, {0}, m, 1), Catch::Contains("faces"));
}

namespace {
// A 40 x 40 mm plate with a 6 mm high Gaussian hill (radius 6 mm) in its middle, h = 1 mm;
// the hill (z > 2 mm) is element C11, the rest the base.
meshes::SurfaceMesh hill_plate() {
  auto m = meshes::structured_grid(
      40, 40,
      [](double u, double v) {
        const double x = 0.04 * u - 0.02, y = 0.04 * v - 0.02;
        return meshes::Vec3{x, y, 0.006 * std::exp(-(x * x + y * y) / (2 * 0.006 * 0.006))};
      },
      false, meshes::label::base);
  const auto c = meshes::face_centroids(m);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (c[f].z > 0.002)
      m.face_labels[f] = meshes::label::convex_element(1, 1);
  return m;
}
} // namespace

TEST_CASE("wall loads: a DEM window's coarse-grained traction keeps its force (1e-10) and its "
          "moment about the sample centre (1e-6); the wear volume keeps each label's total",
          "[wall_loads][coarse-graining]") {
  dem::System s;
  const int g = dem::testing::add_gravel(s, 0.5, 0.5, 0.1);
  const auto plate = hill_plate();
  const int w = s.add_wall(dem::MeshWall(plate, g, {}, true, "sample"));
  // Particles thrown across the hill and the plate: sliding, rolling, bouncing contacts on
  // faces, edges and vertices of both labels.
  const double r = 2e-3;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      s.particles.add({-0.015 + 0.006 * i, -0.015 + 0.006 * j, 0.012 + 0.0015 * ((i + j) % 3)},
                      {0.3 - 0.1 * j, 0.2 * (i % 2) - 0.1, -0.5}, r, 2650, g);
  s.setup();
  s.run(3000);
  const auto wi = s.wear_integrals(w);
  std::vector<double> volume(wi.archard.size());
  for (std::size_t f = 0; f < volume.size(); ++f)
    volume[f] = 1e-9 * wi.archard[f];
  const auto loads = dem::wall_loads(wi, volume, plate, 0.1, {3e-3, true, true});
  const meshes::Vec3 centre{0, 0, 0.001};
  const meshes::Vec3 force = wi.total_impulse;
  const meshes::Vec3 moment = wi.total_impulse_moment - cross(centre, wi.total_impulse);
  const auto x = meshes::face_centroids(plate);
  meshes::Vec3 cg_force{}, cg_moment{}, centroid_moment{};
  for (std::size_t f = 0; f < plate.n_faces(); ++f) {
    cg_force += loads.traction_impulse[f];
    cg_moment += cross(x[f] - centre, loads.traction_impulse[f]);
    centroid_moment += cross(x[f] - centre, loads.impulse[f]);
  }
  REQUIRE(norm(force) > 0);
  CHECK(norm(cg_force - force) / norm(force) < 1e-10);
  CHECK(norm(cg_moment - moment) / norm(moment) < 1e-6);
  // Per-face impulses at the face centroids lose the moment at the face size's scale.
  CHECK(norm(centroid_moment - moment) / norm(moment) > 1e-5);
  for (const int l : plate.labels()) {
    double before = 0, after = 0;
    for (std::size_t f = 0; f < plate.n_faces(); ++f)
      if (plate.face_labels[f] == l) {
        before += volume[f];
        after += loads.wear_volume[f];
      }
    CAPTURE(l);
    CHECK(std::abs(after - before) <= 1e-12 * before);
  }
}

TEST_CASE("wall loads: a DEM window on a flat plate meshed at h = w/2 and w/4: the coarse-"
          "grained traction at fixed points changes by under 10 %, the per-face one by over 3x "
          "that",
          "[wall_loads][coarse-graining]") {
  // 100 particles (r = 2 mm = w) dropped in two layers onto a 40 x 40 mm plate, sliding at
  // 0.2 m/s. On a plane a contact's force does not depend on the face, edge or vertex that
  // holds it, so both meshes see the same window up to round-off in the trajectories.
  const double L = 0.04, r = 2e-3, w = 2e-3;
  std::vector<meshes::Vec3> points;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j)
      points.push_back(
          {3 * w + (L - 6 * w) * (i + 0.5) / 60, 3 * w + (L - 6 * w) * (j + 0.5) / 60, 0});
  std::vector<std::vector<meshes::Vec3>> per_face, coarse;
  std::vector<meshes::Vec3> totals;
  for (const int n : {40, 80}) {
    const auto plate = meshes::structured_grid(
        n, n,
        [L](double u, double v) {
          return meshes::Vec3{L * u, L * v, 0};
        },
        false, meshes::label::base);
    dem::System s;
    const int g = dem::testing::add_gravel(s, 0.5, 0.5, 0.1);
    const int wall = s.add_wall(dem::MeshWall(plate, g, {}, true, "sample"));
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j)
          s.particles.add({0.006 + 0.0045 * i + 0.001 * k, 0.006 + 0.0045 * j + 0.0007 * k,
                           r * 1.001 + 0.0045 * k},
                          {0.2, 0.1 * ((i + j) % 3 - 1), 0}, r, 2650, g);
    s.setup();
    s.run(6000);
    const auto wi = s.wear_integrals(wall);
    totals.push_back(wi.total_impulse);
    const auto loads =
        dem::wall_loads(wi, std::vector<double>(plate.n_faces(), 0), plate, 1, {w, true, false});
    const meshes::SurfaceLocator locator(plate);
    const auto area = meshes::face_areas(plate);
    std::vector<meshes::Vec3> a, b;
    for (const auto& p : points) {
      const auto f = std::size_t(locator.nearest(p).face);
      a.push_back(loads.impulse[f] / area[f]);
      b.push_back(loads.traction_impulse[f] / area[f]);
    }
    per_face.push_back(a);
    coarse.push_back(b);
  }
  const auto change = [](const std::vector<meshes::Vec3>& fine,
                         const std::vector<meshes::Vec3>& coarse_mesh) {
    double d = 0, s = 0;
    for (std::size_t k = 0; k < fine.size(); ++k) {
      d += norm2(fine[k] - coarse_mesh[k]);
      s += norm2(coarse_mesh[k]);
    }
    return std::sqrt(d / s);
  };
  // The two runs carry the same window load.
  CHECK(norm(totals[1] - totals[0]) < 0.01 * norm(totals[0]));
  const double per_face_change = change(per_face[1], per_face[0]);
  const double coarse_change = change(coarse[1], coarse[0]);
  CHECK(coarse_change < 0.10);
  CHECK(per_face_change > 3 * coarse_change);
}

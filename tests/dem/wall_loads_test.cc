// The DEM's window loads as FaceFields: windows add face by face (sums conserved), loads
// follow a mesh in another frame with impulse vectors rotated and scalar loads unchanged, and
// loads of another mesh revision are refused rather than silently mixed.
#include "dem/tester/wall_loads.h"
#include "meshes/sample_frame.h"

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

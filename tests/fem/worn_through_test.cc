// A plate worn through: the implicit recession opens a hole where the wear reaches through the
// part, says so (the clamped area removed), and the remesher meshes the part with the hole.
// A 16 mm square plate 2 mm thick whose top is asked to wear 4 mm deep over a disk of radius
// 3 mm (the union of balls widens the pit, so the volume is matched at about 2.5 mm): the
// new surface has genus one (Euler characteristic 0, against 2 for the plate), the bottom
// loses about the disk's area, the volume removed is the asked volume, and gmsh keeps the
// triangles and fills the volume at its first attempt.
#include "fem/remesher.h"
#include "meshes/constants.h"
#include "meshes/implicit_recession.h"
#include "meshes/mesh_quality.h"
#include "meshes/sample_generator.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>

using namespace wear;
using meshes::euler_characteristic;

TEST_CASE("a plate worn through opens a hole that the remesher meshes",
          "[fem][implicit_recession]") {
  const double side = 16e-3, thickness = 2e-3, radius = 3e-3, depth = 4e-3;
  auto plate = meshes::testing::height_field_block(
      32, 32, side, side, [&](double, double) { return thickness; },
      [](double, double) { return meshes::label::base; });
  plate.roles = meshes::sample_roles(true); // bottom clamped, sides held, base wears
  REQUIRE(euler_characteristic(plate) == 2);
  const auto centroid = meshes::face_centroids(plate);
  const auto area = meshes::face_areas(plate);
  std::vector<double> removed(plate.n_faces(), 0.0);
  double asked = 0;
  for (std::size_t f = 0; f < plate.n_faces(); ++f)
    if (plate.face_wears(f) &&
        std::hypot(centroid[f].x - side / 2, centroid[f].y - side / 2) < radius) {
      removed[f] = depth * area[f];
      asked += removed[f];
    }
  meshes::ImplicitRecessionParameters p;
  const auto r = meshes::implicit_recession(plate, removed, p);
  INFO("faces " << r.surface.n_faces() << ", worn through " << r.worn_through_area * 1e6
                << " mm^2, removed " << r.removed_volume * 1e9 << " of " << asked * 1e9 << " mm^3");
  CHECK(meshes::check_closed(r.surface).closed());
  CHECK(meshes::surface_quality(r.surface).valid());
  CHECK(euler_characteristic(r.surface) == 0); // a hole through the plate
  // The disk through the bottom, widened by the balls of its rim: more than the disk, less
  // than the disk grown by the depth.
  CHECK(r.worn_through_area > wear::pi * radius * radius);
  CHECK(r.worn_through_area < wear::pi * (radius + depth) * (radius + depth));
  CHECK(r.removed_volume == Approx(asked).epsilon(1e-4));
  for (const auto& x : r.surface.vertices)
    if (std::abs(x.z) < 1e-6)
      CHECK(x.z == 0.0);

  fem::RemeshParameters remesh;
  remesh.sizes.mesh_size = 1e-3;
  remesh.sizes.mesh_size_bottom = 1e-3;
  remesh.sizes.thickness = thickness;
  remesh.sizes.curvature_refinement = false;
  const std::string dir = std::filesystem::temp_directory_path().string() + "/worn-through-plate";
  std::filesystem::create_directories(dir);
  fem::RemeshReport report;
  const auto remeshed = fem::remesh_sample(r.surface, remesh, dir + "/plate.msh", &report,
                                           fem::SurfaceKind::isotropic);
  INFO(report.n_tetrahedra << " tetrahedra, worst " << report.min_tet_quality
                           << ", failed: " << report.failed_attempts);
  CHECK(report.attempt == 1);
  CHECK(euler_characteristic(remeshed) == 0);
  CHECK(report.volume_after == Approx(meshes::enclosed_volume(r.surface)).epsilon(1e-9));
  std::filesystem::remove_all(dir);
}

// CAD import (meshes/cad_import.h): a box and a cylinder written by gmsh's OpenCASCADE kernel
// as STEP (and BREP) come back with their analytic area and enclosed volume within the
// meshing tolerance, in metres whatever the file's unit, closed and outward, one label per
// CAD surface; bad input is refused naming the file.
#include "meshes/cad_import.h"
#include "meshes/constants.h"
#include "meshes/gmsh_session.h"
#include "meshes/stl_io.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <gmsh.h>

#include <cmath>
#include <fstream>

using namespace wear::meshes;

namespace {

// A box [0, a] x [0, b] x [0, c] or a cylinder of radius r and height h on the z axis, in the
// file's own unit, written by OpenCASCADE (stdout of its STEP writer left as is: a test log).
void write_shape(const std::string& path, bool cylinder, double a, double b, double c) {
  GmshSession session("shape");
  if (cylinder)
    gmsh::model::occ::addCylinder(0, 0, 0, 0, 0, c, a);
  else
    gmsh::model::occ::addBox(0, 0, 0, a, b, c);
  gmsh::model::occ::synchronize();
  gmsh::write(path);
}

double sum(const std::vector<double>& v) {
  double s = 0;
  for (const double x : v)
    s += x;
  return s;
}

} // namespace

TEST_CASE("CAD import: a box from STEP in mm has its exact area and volume in metres",
          "[meshes][cad]") {
  write_shape("cad_box_mm.step", false, 100, 200, 50); // 0.1 x 0.2 x 0.05 m
  const auto s = read_cad_surface("cad_box_mm.step", {LengthUnit::millimetre, 0.02});
  const double area = 2 * (0.1 * 0.2 + 0.1 * 0.05 + 0.2 * 0.05), volume = 0.1 * 0.2 * 0.05;
  INFO(s.mesh.n_faces() << " triangles, area " << total_area(s.mesh) << " m^2, volume "
                        << enclosed_volume(s.mesh) << " m^3");
  CHECK(s.surface_labels.size() == 6);
  CHECK(s.mesh.labels() == s.surface_labels);
  CHECK(s.n_solids == 1);
  // Flat faces: the triangles cover them exactly (round-off of the scaling).
  CHECK(total_area(s.mesh) == Approx(area).epsilon(1e-12));
  CHECK(enclosed_volume(s.mesh) == Approx(volume).epsilon(1e-12));
  CHECK(sum(s.surface_areas) == Approx(area).epsilon(1e-9));
  CHECK(s.solid_volume == Approx(volume).epsilon(1e-9));
  const auto report = check_closed(s.mesh);
  CHECK(report.closed());
  CHECK(report.consistently_oriented());
  const auto box = bounding_box(s.mesh);
  CHECK(box.max.x == Approx(0.1).epsilon(1e-12));
  CHECK(box.max.y == Approx(0.2).epsilon(1e-12));
  CHECK(box.max.z == Approx(0.05).epsilon(1e-12));
  // The same file read as metres is 1000 times larger.
  const auto m = read_cad_surface("cad_box_mm.step", {LengthUnit::metre, 20.0});
  CHECK(total_area(m.mesh) == Approx(area * 1e6).epsilon(1e-12));
}

TEST_CASE("CAD import: a cylinder from STEP within the chord error of its mesh size",
          "[meshes][cad]") {
  const double r = 0.05, h = 0.1, size = 0.005;
  write_shape("cad_cylinder.step", true, r, 0, h);
  const auto s = read_cad_surface("cad_cylinder.step", {LengthUnit::metre, size});
  const double area = 2 * wear::pi * r * r + 2 * wear::pi * r * h, volume = wear::pi * r * r * h;
  // A polygon of edges h inscribed in a circle of radius r lacks about (h/r)^2 / 12 of its
  // area (h = 5 mm, r = 50 mm: 8.3e-4); the surface and the volume alike. Tolerance 2e-3.
  const double area_error = total_area(s.mesh) / area - 1;
  const double volume_error = enclosed_volume(s.mesh) / volume - 1;
  INFO(s.mesh.n_faces() << " triangles: area " << area_error << ", volume " << volume_error
                        << " relative");
  CHECK(std::abs(area_error) < 2e-3);
  CHECK(std::abs(volume_error) < 2e-3);
  CHECK(area_error < 0); // inscribed: never more than the cylinder
  CHECK(s.surface_labels.size() == 3);
  CHECK(sum(s.surface_areas) == Approx(area).epsilon(1e-6));
  CHECK(s.solid_volume == Approx(volume).epsilon(1e-6));
  CHECK(check_closed(s.mesh).closed());
  // Every label is meshed, each one's triangles near its CAD area.
  const auto per_label = area_per_label(s.mesh);
  for (std::size_t k = 0; k < s.surface_labels.size(); ++k)
    CHECK(per_label.at(s.surface_labels[k]) == Approx(s.surface_areas[k]).epsilon(2e-3));
}

TEST_CASE("CAD import: BREP and STL read alike", "[meshes][cad]") {
  // (IGES goes through the same OpenCASCADE import; gmsh 4.8 writes no IGES to test it with.)
  write_shape("cad_box.brep", false, 0.1, 0.2, 0.05);
  const double area = 2 * (0.1 * 0.2 + 0.1 * 0.05 + 0.2 * 0.05);
  const auto s = read_cad_surface("cad_box.brep", {LengthUnit::metre, 0.02});
  CHECK(total_area(s.mesh) == Approx(area).epsilon(1e-9));
  CHECK(s.surface_labels.size() == 6);
  // An STL in mm keeps its labels and is scaled.
  write_stl(testing::box(100, 200, 50), "cad_box_mm.stl", StlFormat::ascii);
  const auto stl = read_cad_surface("cad_box_mm.stl", {LengthUnit::millimetre, 0});
  CHECK(total_area(stl.mesh) == Approx(area).epsilon(1e-12));
  CHECK(stl.n_solids == 0);
  // Read as metres it is 1000 times too large for a 1 m domain, refused by its extent.
  CadImportOptions metres{LengthUnit::metre, 0, BoundingBox{{-1, -1, -1}, {1, 1, 1}}};
  CHECK_THROWS_WITH(read_cad_surface("cad_box_mm.stl", metres),
                    Catch::Contains("outside the domain"));
}

TEST_CASE("CAD import: bad input is refused naming the file", "[meshes][cad]") {
  CHECK_THROWS_WITH(read_cad_surface("no_such.step", {LengthUnit::metre, 0.01}),
                    Catch::Contains("'no_such.step' does not exist"));
  std::ofstream("cad_unknown.xyz") << "1 2 3\n";
  CHECK_THROWS_WITH(read_cad_surface("cad_unknown.xyz", {LengthUnit::metre, 0.01}),
                    Catch::Contains("unknown extension '.xyz'"));
  std::ofstream("cad_garbage.step") << "this is not STEP\n";
  CHECK_THROWS_WITH(read_cad_surface("cad_garbage.step", {LengthUnit::metre, 0.01}),
                    Catch::Contains("cad_garbage.step"));
  write_shape("cad_box_size.step", false, 0.1, 0.2, 0.05);
  CHECK_THROWS_WITH(read_cad_surface("cad_box_size.step", {LengthUnit::metre, 0}),
                    Catch::Contains("triangle size must be positive"));
  CHECK_THROWS_WITH(parse_length_unit("inch", "Scene/Wall/Unit"),
                    Catch::Contains("Scene/Wall/Unit: unknown length unit 'inch'"));
  CHECK(metres_per(parse_length_unit("mm", "u")) == 1e-3);
}

TEST_CASE("CAD import: primitives have their analytic areas", "[meshes][cad]") {
  const double size = 0.005;
  Primitive plane;
  plane.origin = {0.1, 0, 0.2};
  plane.edge_u = {0.3, 0, 0};
  plane.edge_v = {0, 0.1, 0.1}; // a tilted parallelogram, 0.3 x 0.1 sqrt(2)
  const auto p = primitive_surface(plane, size, "Scene/plane");
  CHECK(total_area(p.mesh) == Approx(0.3 * 0.1 * std::sqrt(2.0)).epsilon(1e-12));
  CHECK(check_closed(p.mesh).n_boundary_edges > 0);

  Primitive disc;
  disc.kind = PrimitiveKind::disc;
  disc.origin = {0, 0, 0.5};
  disc.axis = {1, 1, 0};
  disc.radius = 0.1;
  const auto d = primitive_surface(disc, size, "Scene/disc");
  const double disc_error = total_area(d.mesh) / (wear::pi * 0.01) - 1;
  INFO("disc: area " << disc_error << " relative");
  CHECK(std::abs(disc_error) < 2e-3);
  // Turned onto its normal: every vertex in the plane through the centre normal to (1, 1, 0).
  double off_plane = 0;
  for (const auto& v : d.mesh.vertices)
    off_plane = std::max(off_plane, std::abs(dot(v - disc.origin, Vec3{1, 1, 0}) / std::sqrt(2.0)));
  CHECK(off_plane < 1e-12);
  // With a hole: an annulus (a hopper's floor), its inner boundary the hole's circle.
  disc.radius_inner = 0.03;
  const auto ring = primitive_surface(disc, size, "Scene/ring");
  CHECK(total_area(ring.mesh) == Approx(wear::pi * (0.01 - 0.0009)).epsilon(2e-3));
  double nearest = 1;
  for (const auto& v : ring.mesh.vertices)
    nearest = std::min(nearest, norm(v - disc.origin));
  CHECK(nearest == Approx(0.03).epsilon(1e-9));
  disc.radius_inner = 0.1;
  CHECK_THROWS_WITH(primitive_surface(disc, size, "Scene/ring"), Catch::Contains("hole"));
  disc.radius_inner = 0;

  Primitive tube;
  tube.kind = PrimitiveKind::cylinder;
  tube.origin = {0, 0, 0};
  tube.axis = {0, 0, 0.2};
  tube.radius = 0.1;
  const auto t = primitive_surface(tube, size, "Scene/tube");
  CHECK(t.surface_labels.size() == 1); // the side only
  const double tube_error = total_area(t.mesh) / (2 * wear::pi * 0.1 * 0.2) - 1;
  INFO("open cylinder: area " << tube_error << " relative");
  CHECK(std::abs(tube_error) < 2e-3);
  CHECK(!check_closed(t.mesh).closed());
  tube.caps = true;
  const auto closed = primitive_surface(tube, size, "Scene/tube");
  CHECK(closed.surface_labels.size() == 3);
  CHECK(check_closed(closed.mesh).closed());
  CHECK(enclosed_volume(closed.mesh) == Approx(wear::pi * 0.01 * 0.2).epsilon(2e-3));

  Primitive cone;
  cone.kind = PrimitiveKind::cone;
  cone.axis = {0, 0, 0.1};
  cone.radius = 0.1;
  cone.radius_top = 0.05;
  const auto c = primitive_surface(cone, size, "Scene/cone");
  const double slant = std::sqrt(0.1 * 0.1 + 0.05 * 0.05);
  CHECK(total_area(c.mesh) == Approx(wear::pi * (0.1 + 0.05) * slant).epsilon(2e-3));

  Primitive box;
  box.kind = PrimitiveKind::box;
  box.origin = {-0.1, -0.1, 0};
  box.axis = {0.2, 0.3, 0.4};
  const auto b = primitive_surface(box, 0.05, "Scene/box");
  CHECK(enclosed_volume(b.mesh) == Approx(0.024).epsilon(1e-12));
  CHECK(check_closed(b.mesh).closed());

  // Bad dimensions are named.
  disc.radius = -1;
  CHECK_THROWS_WITH(primitive_surface(disc, size, "Scene/disc"),
                    Catch::Contains("Scene/disc: the radius must be positive"));
  plane.edge_v = 2 * plane.edge_u;
  CHECK_THROWS_WITH(primitive_surface(plane, size, "Scene/plane"),
                    Catch::Contains("edges are parallel"));
  box.axis.y = 0;
  CHECK_THROWS_WITH(primitive_surface(box, size, "Scene/box"), Catch::Contains("y size"));
  cone.radius_top = 0.1;
  CHECK_THROWS_WITH(primitive_surface(cone, size, "Scene/cone"), Catch::Contains("top radius"));
}

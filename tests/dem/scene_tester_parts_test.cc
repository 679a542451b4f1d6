// The wear tester's own sample and holder as scene walls (Source = sample, holder), and a
// part standing submerged in a scene's fill: the sample lands where the tester's placement
// says, with its labels, exact areas and volume; the holder's pocket is the sample's sides
// and bottom; the fill leaves a submerged part's box and volume out.
#include "dem/scene/scene_fill.h"
#include "dem/scene/scene_run.h"
#include "dem/tester/tester_parameters.h"
#include "meshes/constants.h"
#include "meshes/sample_frame.h"
#include "meshes/solid_region.h"
#include "scene_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <memory>

using namespace wear::dem;
namespace label = wear::meshes::label;

using testing::gravel;

namespace {

/// The plain sample at 3 mm at 15 degrees, as cases/quick places it.
wear::meshes::GeometryParameters quick_geometry() {
  wear::meshes::GeometryParameters g;
  g.sample.convex = false;
  g.sample.mesh_size = 3e-3;
  g.sample.mesh_size_bottom = 5e-3;
  g.sample.curvature_refinement = false;
  g.placement.angle_deg = 15;
  return g;
}

SceneParameters sample_in_holder() {
  SceneParameters s = scene_with_names({"sample, holder", "", ""});
  s.walls[0].source = "sample";
  s.walls[0].material = "sample";
  s.walls[0].wears = true;
  s.walls[1].source = "holder";
  s.walls[1].material = "holder";
  s.walls[1].mesh_size = 4e-3;
  return s;
}

} // namespace

TEST_CASE("scene walls: the tester's sample and holder stand where the tester puts them") {
  const auto g = quick_geometry();
  const auto walls = build_scene_walls(sample_in_holder(), g);
  REQUIRE(walls.size() == 2);
  const auto& sample = walls[0].surface;
  const double W = g.sample.width, L = g.sample.length, T = g.sample.thickness;
  REQUIRE(sample.surface_labels == std::vector<int>{label::bottom, label::side, label::base});
  const auto area = wear::meshes::area_per_label(sample.mesh);
  // Planar faces: the triangles tile them exactly (round-off only).
  CHECK(area.at(label::base) == Approx(W * L).epsilon(1e-9));
  CHECK(area.at(label::bottom) == Approx(W * L).epsilon(1e-9));
  CHECK(area.at(label::side) == Approx(2 * (W + L) * T).epsilon(1e-9));
  CHECK(sample.surface_areas[2] == Approx(W * L).epsilon(1e-9)); // OpenCASCADE's
  CHECK(wear::meshes::enclosed_volume(sample.mesh) == Approx(W * L * T).epsilon(1e-9));
  CHECK(sample.solid_volume == Approx(W * L * T).epsilon(1e-9));
  // The wear face's centre (the base's area centroid, a rectangle's centre) at the placement's
  // radius, polar angle and height: 0.395 m, 15 deg, 40 mm above the floor.
  wear::meshes::Vec3 c;
  const auto face = wear::meshes::face_areas(sample.mesh);
  const auto centre = wear::meshes::face_centroids(sample.mesh);
  for (std::size_t f = 0; f < sample.mesh.n_faces(); ++f)
    if (sample.mesh.face_labels[f] == label::base)
      c += face[f] * centre[f];
  c = c * (1 / area.at(label::base));
  CHECK(std::hypot(c.x, c.y) == Approx(0.395).epsilon(1e-9));
  CHECK(std::atan2(c.y, c.x) * 180 / wear::pi == Approx(15).epsilon(1e-9));
  CHECK(c.z == Approx(0.040).epsilon(1e-9));
  // Sides and bottom rest in the holder's pocket, named covered on both walls (one contact
  // where the wear face meets the rim, as in the tester).
  CHECK(walls[0].covered_labels == std::vector<int>{label::side, label::bottom});
  CHECK(walls[1].covered_labels == std::vector<int>{label::pocket});
  const auto holder_area = wear::meshes::area_per_label(walls[1].surface.mesh);
  CHECK(holder_area.at(label::pocket) ==
        Approx(area.at(label::side) + area.at(label::bottom)).epsilon(1e-9));
  const wear::meshes::SampleFrame frame(g.sample, g.placement);
  const auto& h = walls[1].surface.mesh;
  for (std::size_t f = 0; f < h.n_faces(); ++f)
    if (h.face_labels[f] == label::pocket)
      for (auto v : h.triangles[f]) {
        const auto q = frame.point_to_sample(h.vertices[v]);
        REQUIRE(std::abs(q.x) <= W / 2 + 1e-12);
        REQUIRE(std::abs(q.y) <= L / 2 + 1e-12);
        REQUIRE(q.z >= -1e-12);
        REQUIRE(q.z <= T + 1e-12);
      }
}

TEST_CASE("scene walls: the tester's sample and holder refuse what they cannot be") {
  const auto g = quick_geometry();
  SceneParameters s = sample_in_holder();
  s.walls[1].wears = true;
  CHECK_THROWS_WITH(build_scene_walls(s, g),
                    Catch::Contains("Scene/Wall holder/Wears: the holder is steel"));
  s = sample_in_holder();
  s.walls[0].clamped_surfaces = "1";
  CHECK_THROWS_WITH(build_scene_walls(s, g), Catch::Contains("Scene/Wall sample: the tester's "
                                                             "sample (Source = sample) brings "
                                                             "its own roles"));
  s = sample_in_holder();
  s.walls[0].source = "box";
  CHECK_THROWS_WITH(build_scene_walls(s, g),
                    Catch::Contains("a wall with Source = holder needs the sample it holds"));
  s = sample_in_holder();
  s.domain_max = {0.3, 0.3, 0.3};
  CHECK_THROWS_WITH(build_scene_walls(s, g),
                    Catch::Contains("Scene/Wall sample (sample): the vertex") &&
                        Catch::Contains("outside Scene/Domain"));
}

TEST_CASE("scene run: a part standing in the fill is left out of it, its volume off the count") {
  // A closed 20 x 20 x 10 mm box standing in the bin, wholly inside the fill cylinder.
  SceneParameters scene = testing::pinhole_bin_cylinder_fill("bin, floor, block");
  auto& block = scene.walls[2];
  block.source = "box";
  block.origin = {-0.01, -0.01, 0.003};
  block.axis = {0.02, 0.02, 0.01};
  block.mesh_size = 0.005;
  SceneRun counted(scene, gravel(), build_scene_walls(scene));
  counted.setup();
  const auto& p = counted.system().particles;
  REQUIRE(p.n_real == 600);
  const double clear = 0.006; // the largest diameter around the block
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const auto& x = p.position[i];
    const double dx = std::fmax(std::abs(x.x) - 0.01, 0), dy = std::fmax(std::abs(x.y) - 0.01, 0),
                 dz = std::fmax(std::fmax(0.003 - x.z, x.z - 0.013), 0);
    REQUIRE(std::sqrt(dx * dx + dy * dy + dz * dz) >= clear); // from the block, 0 inside
  }
  // To a bed height: the count of the bed without the block less the block's volume, at the
  // assumed packing (TesterDemParameters::assumed_packing) in 6 mm spheres.
  scene.fill.count = 0;
  scene.fill.bed_height = 0.03;
  SceneRun bed(scene, gravel(), build_scene_walls(scene));
  bed.setup();
  const double footprint = wear::pi * 0.058 * 0.058, v = wear::pi * std::pow(0.006, 3) / 6;
  const double phi = gravel().assumed_packing;
  const auto n = [&](double volume) { return std::size_t(phi * volume / v); };
  CHECK(bed.system().particles.n_real == n(footprint * 0.03 - 0.02 * 0.02 * 0.01));
  CHECK(n(footprint * 0.03) - bed.system().particles.n_real >= 10); // the block's share
  // A block reaching through the fill's floor is cut by it: refused.
  block.origin = {-0.01, -0.01, -0.002};
  CHECK_THROWS_WITH(SceneRun(scene, gravel(), build_scene_walls(scene)),
                    Catch::Contains("intersects wall 'block' (box)"));
}

TEST_CASE("scene fill: a closed submerged wall keeps its solid and a diameter around it clear, "
          "not its bounding box") {
  // The quick case's sample in its holder, turned by 15 degrees in the tester: the boxes of
  // both walls reach past their solids, where a bed may stand.
  SceneParameters s = sample_in_holder();
  const auto walls = build_scene_walls(s, quick_geometry());
  wear::meshes::BoundingBox all = wear::meshes::bounding_box(walls[0].surface.mesh);
  for (const auto& w : walls) {
    const auto b = wear::meshes::bounding_box(w.surface.mesh);
    for (int d = 0; d < 3; ++d) {
      all.min[d] = std::fmin(all.min[d], b.min[d]);
      all.max[d] = std::fmax(all.max[d], b.max[d]);
    }
  }
  const double c = 0.004; // [m] the clearance: a largest diameter
  s.fill.region = "box";
  s.fill.minimum = {all.min.x - 2 * c, all.min.y - 2 * c, all.min.z - 2 * c};
  s.fill.maximum = {all.max.x + 2 * c, all.max.y + 2 * c, all.max.z + 2 * c};
  s.fill.count = 100;
  SceneFillShape shape = fill_shape(s, 1);
  require_clear_of_walls(walls, shape, shape.hi.z, "");
  shape.clearance = c;
  REQUIRE(shape.submerged.size() == 2);
  const FillRegion region = shape.region(0, shape.hi.z);
  std::vector<std::unique_ptr<wear::meshes::SolidRegion>> solids;
  for (const auto& w : walls)
    solids.push_back(
        std::make_unique<wear::meshes::SolidRegion>(w.surface.mesh, w.parameters.name));
  // On a 25^3 grid over the fill box: a centre is admissible exactly when it lies outside both
  // solids and at least c from their surfaces; some admissible centres lie within c of a
  // wall's bounding box (the part turned in it), which the box alone would have refused.
  std::size_t n_in_box_admitted = 0, n_checked = 0;
  const int n = 24;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const Vec3 lo = shape.lo, hi = shape.hi;
        const Vec3 x{lo.x + (hi.x - lo.x) * i / n, lo.y + (hi.y - lo.y) * j / n,
                     lo.z + (hi.z - lo.z) * k / n};
        bool clear = true, in_box = false;
        for (std::size_t w = 0; w < walls.size(); ++w) {
          clear = clear && !solids[w]->contains(x) && solids[w]->distance(x) >= c;
          const auto& b = shape.submerged[w].box;
          in_box = in_box || (x.x > b.min.x - c && x.x < b.max.x + c && x.y > b.min.y - c &&
                              x.y < b.max.y + c && x.z > b.min.z - c && x.z < b.max.z + c);
        }
        REQUIRE(region.inside(x) == clear);
        n_in_box_admitted += clear && in_box;
        ++n_checked;
      }
  CHECK(n_in_box_admitted > n_checked / 20);
}

TEST_CASE("scene run: no particle is placed over a plate named in Fill/Clear above") {
  SceneParameters scene = testing::pinhole_bin_cylinder_fill("bin, floor, plate");
  auto& plate = scene.walls[2];
  plate.source = "plane";
  plate.origin = {-0.01, -0.01, 0.05};
  plate.edge_u = {0.02, 0, 0};
  plate.edge_v = {0, 0.02, 0};
  plate.mesh_size = 0.005;
  const auto over_plate = [](const SceneRun& run) {
    const auto& p = run.system().particles;
    std::size_t n = 0;
    for (std::size_t i = 0; i < p.n_real; ++i) {
      const auto& x = p.position[i];
      n += std::abs(x.x) < 0.016 && std::abs(x.y) < 0.016 && x.z > 0.044;
    }
    return n;
  };
  SceneRun loaded(scene, gravel(), build_scene_walls(scene));
  loaded.setup();
  CHECK(over_plate(loaded) > 0); // the plate alone keeps only its own slab clear
  scene.fill.clear_above = "plate";
  SceneRun cleared(scene, gravel(), build_scene_walls(scene));
  cleared.setup();
  REQUIRE(cleared.system().particles.n_real == 600);
  CHECK(over_plate(cleared) == 0);
  scene.fill.clear_above = "bin";
  CHECK_THROWS_WITH(SceneRun(scene, gravel(), build_scene_walls(scene)),
                    Catch::Contains("Scene/Fill/Clear above: wall 'bin' does not stand wholly"));
  scene.fill.clear_above = "lid";
  CHECK_THROWS_WITH(validate(scene),
                    Catch::Contains("Scene/Fill/Clear above: 'lid' is not a wall"));
}

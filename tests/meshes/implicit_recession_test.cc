// The implicit recession against analytic shapes: a cube and a sphere receding uniformly keep
// their shape (a smaller cube, a smaller sphere) and lose exactly the asked volume; a crest
// recedes along its bisector as the entropy solution; a convex bump worn until its rim-to-top
// height is gone leaves a flat base with its label removed; a thin plate worn through at a
// spot opens a hole and says so. Tolerances are stated in units of the grid spacing h.
#include "meshes/implicit_recession.h"
#include "meshes/level_set_grid.h"
#include "meshes/mesh_quality.h"
#include "meshes/sample_generator.h"
#include "meshes/surface_locator.h"
#include "tests/meshes/test_shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace wear::meshes;

namespace {
using testing::uniform_depth_volume;
double sum(const std::vector<double>& v) {
  double s = 0;
  for (const double x : v)
    s += x;
  return s;
}
// Recedes s by a uniform depth d on its wearing faces on a grid of spacing h, and checks what
// every case shares: a closed surface that lost the asked volume.
ImplicitRecession recede_uniformly(const SurfaceMesh& s, double d, double h,
                                   bool per_label = true) {
  const auto removed = uniform_depth_volume(s, d);
  ImplicitRecessionParameters p;
  p.spacing = h;
  p.volume_per_label = per_label;
  auto r = implicit_recession(s, removed, p);
  INFO(r.n_iterations << " fields, " << r.seconds << " s");
  CHECK(check_closed(r.surface).closed());
  CHECK(r.removed_volume == Approx(sum(removed)).epsilon(1e-3));
  return r;
}
} // namespace

TEST_CASE("the zero set of a sphere's signed distance encloses the grid's volume",
          "[implicit_recession]") {
  auto s = testing::icosphere(5e-3, 5);
  orient_outward(s);
  LevelSetGrid g(bounding_box(s), 0.25e-3, 1e-3);
  signed_distance(s, g, 0.75e-3);
  const auto z = zero_surface(g);
  CHECK(check_closed(z).closed());
  CHECK(check_closed(z).consistently_oriented());
  CHECK(enclosed_volume(z) == Approx(negative_volume(g)).epsilon(1e-9));
  // The icosphere's chords: its volume is within 0.2 % of the ball's.
  CHECK(negative_volume(g) == Approx(enclosed_volume(s)).epsilon(2e-3));
}

TEST_CASE("the inward front point lies at its depth under the face, on either side of it",
          "[implicit_recession]") {
  // One face in z = 0 looking up, 1 mm deep at its corners: a point above it, below it or on
  // it goes to 1 mm under its closest point; a point beside an edge, inside the part, onto
  // the ball about the edge's closest point, on the part's side.
  SurfaceMesh s;
  s.vertices = {{0, 0, 0}, {10e-3, 0, 0}, {0, 10e-3, 0}};
  s.triangles = {{0, 1, 2}};
  s.face_labels = {label::base};
  const std::vector<double> depth(3, 1e-3);
  const std::vector<Vec3> normal(3, Vec3{0, 0, 1});
  for (const double z : {0.3e-3, -0.3e-3, 0.0, -2e-3}) {
    const Vec3 y = inward_front_point(s, depth, normal, 0, {2e-3, 3e-3, z});
    INFO("z = " << z);
    CHECK(norm(y - Vec3{2e-3, 3e-3, -1e-3}) < 1e-15);
  }
  const Vec3 beside{-0.3e-3, 4e-3, -0.4e-3}; // closest point (0, 4 mm, 0) on the edge x = 0
  const Vec3 y = inward_front_point(s, depth, normal, 0, beside);
  CHECK(norm(y - Vec3{0, 4e-3, 0}) == Approx(1e-3).epsilon(1e-12));
  CHECK(y.z < 0);
  CHECK(y.x < 0);
}

TEST_CASE("a cube receding uniformly stays a cube and loses the asked volume",
          "[implicit_recession]") {
  const double a = 10e-3, d = 1e-3, h = 0.25e-3;
  auto s = testing::box(a, a, a);
  s.face_labels.assign(s.n_faces(), label::base);
  s.roles.set(label::base, FaceRole::wearing);
  const auto r = recede_uniformly(s, d, h);
  // The cube of the same volume, centred where the cube was.
  const double side = std::cbrt(a * a * a - r.asked_volume);
  double worst = 0;
  for (const auto& v : r.surface.vertices) {
    double dist = 0;
    for (int k = 0; k < 3; ++k)
      dist = std::max(dist, std::abs(v[k] - a / 2));
    worst = std::max(worst, std::abs(dist - side / 2));
  }
  INFO("side " << side * 1e3 << " mm, grid loss " << r.grid_loss * 1e9 << " mm^3");
  CHECK(worst < h);
}

TEST_CASE("a sphere receding uniformly stays a sphere and loses the asked volume",
          "[implicit_recession]") {
  const double radius = 5e-3, d = 1e-3, h = 0.2e-3;
  auto s = testing::icosphere(radius, 4);
  orient_outward(s);
  s.face_labels.assign(s.n_faces(), label::base);
  s.roles.set(label::base, FaceRole::wearing);
  const auto r = recede_uniformly(s, d, h);
  // The ball of the same volume (the icosphere's own volume less the removed one).
  const double expected =
      std::cbrt(3 * (enclosed_volume(s) - r.asked_volume) / (4 * 3.14159265358979323846));
  double worst = 0;
  for (const auto& v : r.surface.vertices)
    worst = std::max(worst, std::abs(norm(v) - expected));
  INFO("radius " << expected * 1e3 << " mm, worst " << worst * 1e3 << " mm");
  CHECK(worst < 0.5 * h);
}

TEST_CASE("a crest recedes along its bisector (the entropy solution), it does not fold",
          "[implicit_recession]") {
  // A ridge along y: flanks at 45 deg rising 3 mm above a 5 mm slab, its top at x = 10 mm.
  const double h = 0.2e-3, d = 1e-3;
  auto s = testing::height_field_block(
      40, 20, 20e-3, 10e-3,
      [](double x, double) { return std::max(5e-3, 8e-3 - std::abs(x - 10e-3)); },
      [](double, double) { return label::base; });
  s.roles.set(label::base, FaceRole::wearing);
  s.roles.set(label::bottom, FaceRole::clamped);
  s.roles.set(label::side, FaceRole::held);
  const auto r = recede_uniformly(s, d, h);
  // The depth the volume scaling settled on, from the flat part far from the ridge; then each
  // flank's plane has moved in by it, and the crest stands sqrt(2) of it lower, not one (the
  // vertex-normal offset's crest, which overhangs the flanks and folds).
  double flat = 0;
  int n_flat = 0;
  for (const auto& v : r.surface.vertices)
    if (v.z > 2e-3 && std::abs(v.x - 10e-3) > 6e-3 && v.y > 2e-3 && v.y < 8e-3 && v.x > 1e-3 &&
        v.x < 19e-3) {
      flat += v.z;
      ++n_flat;
    }
  REQUIRE(n_flat > 0);
  const double depth = 5e-3 - flat / n_flat;
  double crest = 0, above_flanks = -1;
  for (const auto& v : r.surface.vertices) {
    const double off = std::abs(v.x - 10e-3);
    if (v.y < 1e-3 || v.y > 9e-3)
      continue;
    if (off < 0.5e-3)
      crest = std::max(crest, v.z);
    if (off < 2e-3 && v.z > 5e-3) // on the receded flanks: below their offset planes
      above_flanks = std::max(above_flanks, v.z - (8e-3 - off - std::sqrt(2.0) * depth));
  }
  INFO("depth " << depth * 1e3 << " mm, crest " << crest * 1e3 << " mm, highest above the flanks "
                << above_flanks * 1e3 << " mm");
  CHECK(depth == Approx(d).epsilon(0.1));
  CHECK(std::abs(crest - (8e-3 - std::sqrt(2.0) * depth)) < 0.5 * h);
  CHECK(above_flanks < 0.5 * h);
}

TEST_CASE("a convex element worn at a uniform depth beyond its width vanishes into a flat base",
          "[implicit_recession]") {
  // A half-ellipsoid element (semi-axes 4, 1 and 3 mm, the pattern's shape at half size) on a
  // 5 mm block; the top wears 3 mm. Worn so, a narrow element leaves a mound of about
  // b^2 / (2 d) = 0.17 mm over the base, below the vanish height.
  const double h = 0.25e-3, d = 3e-3;
  const auto inside = [](double x, double y) {
    return std::pow((x - 8e-3) / 4e-3, 2) + std::pow((y - 8e-3) / 1e-3, 2);
  };
  auto s = testing::height_field_block(
      64, 64, 16e-3, 16e-3,
      [&](double x, double y) { return 5e-3 + 3e-3 * std::sqrt(std::max(0.0, 1 - inside(x, y))); },
      [&](double x, double y) {
        return inside(x, y) < 1 ? label::convex_element(1, 1) : label::base;
      });
  s.roles = sample_roles(true);
  // A uniform rate: every face by the same depth times one common factor.
  const auto r = recede_uniformly(s, d, h, false);
  REQUIRE(r.vanished_labels == std::vector<int>{label::convex_element(1, 1)});
  const auto labels = r.surface.labels();
  CHECK(std::find(labels.begin(), labels.end(), label::convex_element(1, 1)) == labels.end());
  // The top (base faces away from the held sides' rounded rims).
  double low = 1, high = 0;
  for (std::size_t f = 0; f < r.surface.n_faces(); ++f)
    if (r.surface.face_labels[f] == label::base)
      for (const auto v : r.surface.triangles[f]) {
        const auto& x = r.surface.vertices[v];
        if (x.x < 1e-3 || x.x > 15e-3 || x.y < 1e-3 || x.y > 15e-3)
          continue;
        low = std::min(low, x.z);
        high = std::max(high, x.z);
      }
  INFO("top between " << low * 1e3 << " and " << high * 1e3 << " mm");

  CHECK(high - low < ImplicitRecessionParameters().vanish_height);
}

TEST_CASE("the unworn convex sample's base recedes beside the elements' feet without a fold",
          "[implicit_recession][long]") {
  // The sample at 3 mm worn by 100 um x n_z^2 a face (`wearsim bench evolution --sample
  // convex --mesh-size 3e-3 --depth 100e-6`): the base most, the elements' flanks least.
  // Where the worn base meets an element's unworn foot, the volume-restoring offset of the
  // vertices along their normals laid thin faces onto their neighbours (2 folded base edges
  // at z = 10.09 mm); it is held still there, and the surface is valid with the volume exact.
  SampleGeometry g;
  g.mesh_size = 3e-3;
  const auto sample = generate_sample(g);
  const SurfaceMesh& s = sample.surface;
  const auto normal = face_normals(s);
  const auto area = face_areas(s);
  std::vector<double> removed(s.n_faces(), 0.0);
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_wears(f))
      removed[f] = 100e-6 * normal[f].z * normal[f].z * area[f];
  const auto r = implicit_recession(s, removed, ImplicitRecessionParameters{});
  const auto q = surface_quality(r.surface);
  INFO(q.n_folded_edges << " folded edges, " << q.n_self_intersections << " crossing pairs, "
                        << r.restore_held_rings << " rings held");
  CHECK(q.valid());
  CHECK(check_closed(r.surface).closed());
  CHECK(r.volume_not_restored == 0);
  CHECK(r.removed_volume == Approx(sum(removed)).epsilon(1e-3));
}

TEST_CASE("a worn top beside free sides that do not wear leaves the sides where they were",
          "[implicit_recession]") {
  // A 12 x 10 x 6 mm block whose top wears 1 mm and whose sides are free (they neither wear
  // nor are held): the top recedes to a sharp corner with the sides, which stay plane, and
  // the vertical corners between two sides stay sharp up to the new top. The grid's cells
  // there are crossed by the front (the top's balls reach the sides' upper millimetre), so a
  // test per cell would leave the sides' chamfered corners as the grid cut them.
  const double a = 12e-3, b = 10e-3, c = 6e-3, d = 1e-3, h = 0.25e-3;
  auto s = testing::box(a, b, c);
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    s.face_labels[f] = f < 2 ? label::bottom : f < 4 ? label::base : label::side;
  s.roles = sample_roles(false);
  REQUIRE(s.roles.of(label::side) == FaceRole::free);
  const auto r = recede_uniformly(s, d, h);
  const auto off = farthest_unworn_face(r.surface, s);
  double top_low = 1, top_high = 0;
  for (std::size_t f = 0; f < r.surface.n_faces(); ++f)
    if (r.surface.face_labels[f] == label::base)
      for (const auto v : r.surface.triangles[f]) {
        top_low = std::min(top_low, r.surface.vertices[v].z);
        top_high = std::max(top_high, r.surface.vertices[v].z);
      }
  INFO("unworn face farthest off " << off.distance * 1e3 << " mm at (" << off.centroid.x * 1e3
                                   << ", " << off.centroid.y * 1e3 << ", " << off.centroid.z * 1e3
                                   << ") mm; top between " << top_low * 1e3 << " and "
                                   << top_high * 1e3 << " mm");
  CHECK(off.distance < 0.05 * h);
  CHECK(top_high < c - d + 0.2 * h);
  CHECK(top_low > c - d - 0.5 * h);
}

TEST_CASE("a fragment of a few grid cells cut off the part is dropped, the volume kept exact",
          "[implicit_recession]") {
  // A 10 mm cube worn 1 mm on every face, beside a separate 0.4 mm cube (a fragment the front
  // left of an element's tip; 0.064 mm^3, below 8 h^3 = 0.125 mm^3). Decimated, such a piece
  // became two faces lying on one another, which gmsh refused (the wear-out's stage 11).
  const double a = 10e-3, b = 0.4e-3, d = 1e-3, h = 0.25e-3;
  auto s = testing::box(a, a, a);
  auto fragment = testing::box(b, b, b);
  const auto n = std::uint32_t(s.n_vertices());
  for (auto v : fragment.vertices)
    s.vertices.push_back(v + Vec3(a + 2e-3, 0, 0));
  for (auto t : fragment.triangles)
    s.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  s.face_labels.assign(s.n_faces(), label::base);
  s.roles.set(label::base, FaceRole::wearing);
  auto removed = uniform_depth_volume(s, d);
  for (std::size_t f = 12; f < removed.size(); ++f)
    removed[f] = 0; // the fragment does not wear: it stays whole on the grid
  ImplicitRecessionParameters p;
  p.spacing = h;
  const auto r = implicit_recession(s, removed, p);
  INFO(r.n_fragments << " fragments, " << r.fragment_volume * 1e9 << " mm^3");
  CHECK(r.n_fragments == 1);
  // The grid's zero set of the small cube (its corners and edges cut by the 0.25 mm cells).
  CHECK(r.fragment_volume > 0);
  CHECK(r.fragment_volume < b * b * b);
  double right = 0;
  for (const auto& v : r.surface.vertices)
    right = std::max(right, v.x);
  CHECK(right < a);
  CHECK(check_closed(r.surface).closed());
  CHECK(surface_quality(r.surface).valid());
  // What the fragment held (as the grid saw it) is removed with the asked volume; the cube
  // keeps its own volume less the asked one.
  CHECK(r.removed_volume == Approx(sum(removed) + r.fragment_volume).epsilon(1e-6));
  CHECK(enclosed_volume(r.surface) ==
        Approx(enclosed_volume(s) - sum(removed) - r.fragment_volume).epsilon(1e-9));
}

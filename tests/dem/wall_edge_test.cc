// A sphere on the boundary of a triangle-mesh wall (MeshWall, system_contacts.cc): a free edge
// (an edge of one triangle: the rim of a plate or of an orifice), an edge shared by two faces
// (flat, a convex fold, a concave fold), a vertex, and the rim of a polygonal orifice.
//
// The reference is the wall contact as the engine defines it (contact_law.h): along
// n = (c - p) / |c - p|, p the mesh's closest point to the centre c (a local minimum of the
// distance), the Hertz force F = 4/3 E* sqrt(r) delta^(3/2) of the overlap delta = r - |c - p|,
// r the particle radius; particle and wall of one material, E = 5e7 Pa, nu = 0.25, so
// E* = E / (2 (1 - nu^2)) = 2.667e7 Pa. Sphere r = 5 mm at delta = 50 um: F_H = 0.8889 N. Where
// a sphere touches several separate features the physical reference is one such contact per
// feature, summed.
//
// 1. At rest (zero velocity, no gravity, the force of setup()) on a face, a free edge from 11
//    directions about it, a shared flat edge and the vertex of six faces (on them and 1 pm to
//    1 um beside them), a convex fold within and beyond its edge's normals, a concave fold of
//    40 degrees, a slit of 3 mm, a plate's corner, a vertex of 8 faces, a pyramid's apex: the
//    force vector to 1e-9 F_H, the contacts kept, System::energy()'s elastic part (1e-9: the
//    energy of the contacts the force applies) and the
//    wear's split over the faces (1e-12: a free edge's to its face, a fold's halved, a
//    vertex's by the faces' angles).
// 2. System::energy() counts the wall contacts the force applies (1e-9), beside shared edges
//    and vertices and in a rim's corner.
#include "tests/dem/wall_edge_probes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

// The probes' namespace brings the engine's, the fixtures' and the vector names along.
using namespace wall_edge;

TEST_CASE("wall boundary: a sphere at rest on a face, a free edge or a shared flat edge",
          "[dem][walls][edges]") {
  const SurfaceMesh plate = grid_plate(0, 0, 0.01, 2); // 20 mm square, 8 triangles
  SECTION("the middle of a face") {
    const Vec3 centroid = Vec3{0.01 + 0.02 / 3, 0.01 / 3, 0};
    const Probe p = press(plate, centroid + Vec3{0, 0, dist0}, r0);
    INFO("force " << p.force.x << " " << p.force.y << " " << p.force.z << " N, F_H " << f0);
    CHECK(off(p.force, Vec3{0, 0, f0}, f0) <= 1e-9);
    CHECK(p.normals.size() == 1);
    CHECK(energy_off(p, delta0, r0) <= 1e-9);
    CHECK(p.total_impulse > 0);
  }
  SECTION("a free edge, from 11 directions about it, as a face at the same overlap") {
    // The plate's edge y = 0; directions from straight below (-90) through the plate's plane
    // (0) to straight above (90 degrees), all outside the plate. The closest point is on the
    // edge: the force is F_H along the direction, whatever the angle.
    const Vec3 foot{0.0037, 0, 0};
    for (double a : {-90.0, -60.0, -30.0, -10.0, 0.0, 10.0, 30.0, 45.0, 60.0, 80.0, 90.0}) {
      const Vec3 n{0, -std::cos(a * deg), std::sin(a * deg)};
      const Probe p = press(plate, foot + n * dist0, r0);
      INFO("angle " << a << " deg: force " << p.force.x << " " << p.force.y << " " << p.force.z
                    << " N, expected F_H n = " << f0 * n.y << " " << f0 * n.z);
      CHECK(off(p.force, n * f0, f0) <= 1e-9);
      CHECK(p.normals.size() == 1);
      CHECK(energy_off(p, delta0, r0) <= 1e-9);
      // A free edge has one face: the whole contact is its.
      const auto f = std::max_element(p.face_impulse.begin(), p.face_impulse.end());
      CHECK(*f == Approx(p.total_impulse).epsilon(1e-12));
    }
  }
  SECTION("a shared flat edge and the vertex of six faces, above them and just beside them") {
    // Over a diagonal, over a grid line and over the middle vertex (0.01, 0.01), and 1 pm,
    // 1 nm, 1 um to either side: the flat wall's F_H along z, one contact. (At 1 pm, within
    // the ownership's tolerance of 1e-9 |c - p| = 5 pm, or within the round-off of an edge's
    // line, two to four faces report the contact; the merge makes them one force,
    // System::energy() counts each: see the energy's case.)
    int n_cases = 0;
    for (const Vec3& on : {Vec3{0.005, 0.005, 0}, Vec3{0.01, 0.0037, 0}, Vec3{0.01, 0.01, 0}})
      for (double shift : {0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6})
        for (const Vec3& dir : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.6, -0.8, 0}}) {
          const Probe p = press(plate, on + dir * shift + Vec3{0, 0, dist0}, r0);
          INFO("over " << on.x << " " << on.y << " shifted " << shift << " m: force " << p.force.x
                       << " " << p.force.y << " " << p.force.z);
          CHECK(off(p.force, Vec3{0, 0, f0}, f0) <= 1e-9);
          CHECK(p.normals.size() == 1);
          if (std::abs(shift) != 1e-12)
            CHECK(energy_off(p, delta0, r0) <= 1e-9);
          double sum = 0;
          for (double v : p.face_impulse)
            sum += v;
          CHECK(sum == Approx(p.total_impulse).epsilon(1e-12));
          ++n_cases;
        }
    CHECK(n_cases == 63);
  }
}

TEST_CASE("wall boundary: a sphere at rest on a convex fold, in a concave fold, across a slit",
          "[dem][walls][edges]") {
  const double L = 0.02;
  SECTION("a convex fold: the edge between the faces' normals, a face beyond") {
    // Ridges turning by 10 and 40 degrees (slopes 5 and 20). Directions theta from z towards
    // +y: within the slope the closest point is on the fold, the overlap delta; beyond it on
    // the face, distance dist0 cos(theta - slope) from its plane.
    for (double slope : {5.0, 20.0}) {
      const SurfaceMesh ridge = fold(slope * deg, L);
      for (double th : {-slope, -0.5 * slope, 0.0, 0.3 * slope, slope, slope + 5, slope + 30}) {
        const Vec3 dir{0, std::sin(th * deg), std::cos(th * deg)};
        const Probe p = press(ridge, Vec3{0.003, 0, 0} + dir * dist0, r0);
        Vec3 expected = dir * f0;
        double overlap = delta0;
        if (std::abs(th) > slope) {
          const double sg = th > 0 ? 1 : -1;
          const Vec3 face_n{0, sg * std::sin(slope * deg), std::cos(slope * deg)};
          overlap = r0 - dist0 * std::cos((std::abs(th) - slope) * deg);
          expected = face_n * hertz(overlap, r0);
        }
        INFO("slope " << slope << " deg, direction " << th << " deg: force " << p.force.y << " "
                      << p.force.z << ", expected " << expected.y << " " << expected.z);
        CHECK(off(p.force, expected, norm(expected)) <= 1e-9);
        CHECK(p.normals.size() == 1);
        CHECK(energy_off(p, overlap, r0) <= 1e-9);
        // The fold's contact is halved between its two faces; a face's stays on the face (on
        // the border of the two, either).
        const double largest = *std::max_element(p.face_impulse.begin(), p.face_impulse.end());
        if (std::abs(th) != slope)
          CHECK(largest / p.total_impulse ==
                Approx(std::abs(th) < slope ? 0.5 : 1.0).epsilon(1e-12));
      }
    }
  }
  SECTION("a concave fold beyond the merge angle: two contacts, summed") {
    // A valley turning by 40 degrees (slopes -20), the sphere on its bisector at dist0 from
    // both faces: F = 2 F_H cos 20 along z.
    const double slope = -20 * deg;
    const SurfaceMesh valley = fold(slope, L);
    const double h = dist0 / std::cos(slope);
    const Probe p = press(valley, Vec3{0.003, 0, h}, r0);
    const Vec3 expected{0, 0, 2 * f0 * std::cos(slope)};
    INFO("force " << p.force.y << " " << p.force.z << ", expected " << expected.z);
    CHECK(off(p.force, expected, f0) <= 1e-9);
    CHECK(p.normals.size() == 2);
    CHECK(p.elastic == Approx(2 * hertz_energy(delta0, r0)).epsilon(1e-9));
  }
  SECTION("a slit wider than the merge angle: one contact on each free edge") {
    // Two plates 3 mm apart (one wall): a sphere over the gap touches both rims, its normals
    // +-17.6 degrees from z (35.3 apart, beyond the 25-degree merge): F = 2 F_H cos 17.6.
    const double w = 3e-3;
    const SurfaceMesh slit = slit_plate(w, L);
    const double tilt = std::asin(0.5 * w / dist0);
    const Probe p = press(slit, Vec3{0, 0.0007, dist0 * std::cos(tilt)}, r0);
    const Vec3 expected{0, 0, 2 * f0 * std::cos(tilt)};
    INFO("tilt " << tilt / deg << " deg: force " << p.force.x << " " << p.force.z << ", expected "
                 << expected.z);
    CHECK(off(p.force, expected, f0) <= 1e-9);
    CHECK(p.normals.size() == 2);
  }
}

TEST_CASE("wall boundary: a sphere at rest on a vertex", "[dem][walls][edges]") {
  SECTION("a plate's corner, from directions in the vertex's region") {
    // The corner (0, 0) of the 20 mm plate (two faces meet there, at 45 degrees each): any
    // direction with no component along the plate's two edges leaving the corner (-x, -y
    // components, any z) has its closest point at the corner.
    const SurfaceMesh plate = grid_plate(0, 0, 0.01, 2);
    for (const Vec3& d :
         {Vec3{-1, -1, 1}, Vec3{-1, -0.2, 0.5}, Vec3{-0.3, -1, -0.4}, Vec3{-1, -1, 0},
          Vec3{-1, 0, 1}, Vec3{0, -1, -1}, Vec3{-0.01, -0.01, 1}}) {
      const Vec3 n = normalized(d);
      const Probe p = press(plate, n * dist0, r0);
      INFO("direction " << n.x << " " << n.y << " " << n.z << ": force " << p.force.x << " "
                        << p.force.y << " " << p.force.z);
      CHECK(off(p.force, n * f0, f0) <= 1e-9);
      CHECK(p.normals.size() == 1);
      CHECK(energy_off(p, delta0, r0) <= 1e-9);
      double sum = 0;
      for (double v : p.face_impulse)
        sum += v;
      CHECK(sum == Approx(p.total_impulse).epsilon(1e-12));
    }
  }
  SECTION("a vertex of eight faces in a flat plate, above it and just beside it") {
    const SurfaceMesh star = fan(8, 0.02);
    for (double shift : {0.0, 1e-12, 1e-9, 1e-6})
      for (double az : {0.0, 22.5, 45.0, 100.0, 200.0}) {
        const Vec3 c{shift * std::cos(az * deg), shift * std::sin(az * deg), dist0};
        const Probe p = press(star, c, r0);
        INFO("shift " << shift << " m at " << az << " deg: force " << p.force.x << " " << p.force.y
                      << " " << p.force.z);
        CHECK(off(p.force, Vec3{0, 0, f0}, f0) <= 1e-9);
        CHECK(p.normals.size() == 1);
        if (shift == 0 || shift == 1e-6) // (see the flat edge's case)
          CHECK(energy_off(p, delta0, r0) <= 1e-9);
        if (shift == 0) // the vertex's contact, split by the faces' angles: 1/8 each
          for (double v : p.face_impulse)
            CHECK(v == Approx(p.total_impulse / 8).epsilon(1e-12));
      }
  }
  SECTION("the apex of a pyramid, from directions in its normal cone, and a face beyond") {
    // Faces sloping down at 30 degrees: their normals tilt 30 degrees from z towards +-x, +-y.
    // Directions tilted from z by up to 30 degrees towards a face's normal lie in the apex's
    // normal cone; 40 towards a face is that face's.
    const double slope = 30 * deg;
    const SurfaceMesh apex = pyramid(slope, 0.02);
    for (double tilt : {0.0, 10.0, 29.0, 40.0})
      for (double az : {0.0, 90.0, 180.0, 270.0}) {
        const Vec3 d{std::sin(tilt * deg) * std::cos(az * deg),
                     std::sin(tilt * deg) * std::sin(az * deg), std::cos(tilt * deg)};
        const Probe p = press(apex, d * dist0, r0);
        Vec3 expected = d * f0;
        double overlap = delta0;
        if (tilt > 30) {
          const Vec3 face_n{std::sin(slope) * std::cos(az * deg),
                            std::sin(slope) * std::sin(az * deg), std::cos(slope)};
          overlap = r0 - dist0 * std::cos(tilt * deg - slope);
          expected = face_n * hertz(overlap, r0);
        }
        INFO("tilt " << tilt << " deg at " << az << " deg: force " << p.force.x << " " << p.force.y
                     << " " << p.force.z);
        CHECK(off(p.force, expected, norm(expected)) <= 1e-9);
        CHECK(p.normals.size() == 1);
        CHECK(energy_off(p, overlap, r0) <= 1e-9);
      }
    // Towards an edge of the pyramid (azimuth 45 degrees): the apex's cone reaches 22.2
    // degrees there (tan = tan 30 / sqrt 2); 15 degrees is still the apex's.
    const Vec3 d = normalized(Vec3{std::sin(15 * deg) / std::sqrt(2.0),
                                   std::sin(15 * deg) / std::sqrt(2.0), std::cos(15 * deg)});
    const Probe p = press(apex, d * dist0, r0);
    CHECK(off(p.force, d * f0, f0) <= 1e-9);
    CHECK(energy_off(p, delta0, r0) <= 1e-9);
  }
}

TEST_CASE("wall boundary: System::energy() counts a wall contact as the force does",
          "[dem][walls][edges]") {
  // System::energy()'s elastic part is the Hertz energy of the contacts the force applies:
  // the same contacts found and merged (add_wall_elastic_energy and merged_into_another,
  // system_contacts.cc). It once summed every contact a face reported: just beside a shared
  // flat edge or a vertex, where the ownership's tolerance (1e-9 |c - p|, mesh_wall.cc) or the
  // round-off of the closest-point test lets two to four faces report the same touch, 16 of
  // the 83 positions below were counted 2 to 4 times; in a corner of an orifice's rim (two
  // contacts found, one applied) twice. Here: the flat cases of the first and third test
  // cases (63 over the 20 mm plate's edges and middle vertex, 20 about the fan's vertex) and
  // the 32-gon's corner, each to 1e-9 of the applied contact's energy.
  const SurfaceMesh plate = grid_plate(0, 0, 0.01, 2);
  const SurfaceMesh star = fan(8, 0.02);
  std::vector<Vec3> centres;
  for (const Vec3& on : {Vec3{0.005, 0.005, 0}, Vec3{0.01, 0.0037, 0}, Vec3{0.01, 0.01, 0}})
    for (double shift : {0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6})
      for (const Vec3& dir : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.6, -0.8, 0}})
        centres.push_back(on + dir * shift + Vec3{0, 0, dist0});
  const std::size_t n_plate = centres.size();
  for (double shift : {0.0, 1e-12, 1e-9, 1e-6})
    for (double az : {0.0, 22.5, 45.0, 100.0, 200.0})
      centres.push_back({shift * std::cos(az * deg), shift * std::sin(az * deg), dist0});
  int n_counted_more = 0;
  double most = 0, force_off = 0;
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const Probe p = press(k < n_plate ? plate : star, centres[k], r0);
    const double times = p.elastic / hertz_energy(delta0, r0);
    n_counted_more += times > 1 + 1e-9;
    most = std::max(most, times);
    force_off = std::max(force_off, off(p.force, Vec3{0, 0, f0}, f0));
  }
  INFO("flat plate beside its edges and vertices: "
       << n_counted_more << " of " << centres.size() << " positions counted more than once, up to "
       << most << " times; the force off F_H by " << force_off << " at most");
  CHECK(force_off <= 1e-9);
  CHECK(n_counted_more == 0);
  const int n = 32;
  const double s = (r_rim - delta_rim) / std::cos(pi / n);
  const Vec3 c = polygon_vertex(n, rim_radius, 0) * ((rim_radius - s) / rim_radius);
  const Probe p = press(orifice_plate(n, rim_radius), c, r_rim);
  CHECK(norm(p.force) == Approx(hertz(delta_rim, r_rim)).epsilon(1e-9));    // one contact applied
  CHECK(p.elastic == Approx(hertz_energy(delta_rim, r_rim)).epsilon(1e-9)); // the one applied
}

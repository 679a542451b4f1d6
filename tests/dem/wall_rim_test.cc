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
// The rim of a polygonal orifice (the hopper's: 25-, 32-, 50- and 128-gons of 25 mm radius,
// r = 3 mm, delta = 10 um): against the middle of a rim edge, the analytic force to 1e-9;
// along a whole edge, the engine's force is the deepest edge contact's (1e-9), and the share
// of the rim where two edges touch is reported.
// Failing, tagged [!mayfail] (see each case's comment): in a corner of the rim, across a slit
// 1.5 mm wide and on a hole smaller than the sphere, the sphere touches two or more edges
// whose normals lie within 25 degrees and the merge of system_contacts.cc keeps the deepest
// alone (half the force in a corner, its direction jumping across the bisector; a sideways
// force where the support is symmetric). The merge is meant for triangles that stand for a
// smooth surface (a worn fillet, a round orifice), where those contacts are one; against a
// polygon or a slit meant as such it loses real contacts.
#include "tests/dem/wall_edge_probes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

// The probes' namespace brings the engine's, the fixtures' and the vector names along.
using namespace wall_edge;

TEST_CASE("wall boundary: a sphere against the middle of an orifice's rim edge",
          "[dem][walls][edges]") {
  // In the plate's plane and 45 degrees above it, against the middle of rim edge 0 of the
  // n-gon: one contact, the analytic force (the sum over the rim's edges) to 1e-9.
  for (int n : {25, 32, 50, 128}) {
    const SurfaceMesh plate = orifice_plate(n, rim_radius);
    const Vec3 mid = (polygon_vertex(n, rim_radius, 0) + polygon_vertex(n, rim_radius, 1)) * 0.5;
    const Vec3 inward = normalized(-mid);
    for (double up : {0.0, 45.0}) {
      const Vec3 dir = inward * std::cos(up * deg) + Vec3{0, 0, std::sin(up * deg)};
      const Vec3 c = mid + dir * (r_rim - delta_rim);
      int n_touching = 0;
      const Vec3 expected = rim_force_sum(n, rim_radius, c, r_rim, n_touching);
      const Probe p = press(plate, c, r_rim);
      INFO(n << "-gon, " << up << " deg above the plane: force " << norm(p.force) << " N, "
             << "expected " << norm(expected) << " N over " << n_touching << " edge(s)");
      CHECK(n_touching == 1);
      CHECK(off(p.force, expected, norm(expected)) <= 1e-9);
      CHECK(p.normals.size() == 1);
      CHECK(energy_off(p, delta_rim, r_rim) <= 1e-9);
    }
  }
}

TEST_CASE("wall boundary: a sphere in a corner of an orifice's rim gets both edges' contacts",
          "[dem][walls][edges][!mayfail]") {
  // DEFECT (kept failing): a sphere on the bisector of the rim's corner at vertex 0, its
  // overlap delta_rim = 10 um with both edges that meet there, touches both: the rim pushes it
  // with 2 F_H cos(pi / n) towards the axis. The edges are free, so each is reported
  // (MeshWall::contact_ownership), but their normals differ by 2 pi / n < 25 degrees and
  // merged_into_another() (system_contacts.cc) keeps the deepest alone: F_H along one edge's
  // normal, half the force, pi / n off the bisector. Just either side of the bisector the kept
  // edge swaps: the force's direction jumps by 2 pi / n (its component along the rim by
  // 2 F_H sin(pi / n)) where the sum is continuous. System::energy() counts the contact
  // applied. (The merge is made for a triangulation that stands for a smooth surface, where
  // the two contacts are one: of a circle the rim approximates, the sphere touches one point.
  // Of a polygon meant as a polygon it loses one.)
  for (int n : {25, 32, 50, 128}) {
    const SurfaceMesh plate = orifice_plate(n, rim_radius);
    const Vec3 corner = polygon_vertex(n, rim_radius, 0);
    for (double up : {0.0, 45.0}) {
      // On the bisector (the radius through the corner) at in-plane distance h cos(up) from
      // both edge lines, h = r - delta.
      const double h = r_rim - delta_rim;
      const double s = h * std::cos(up * deg) / std::cos(pi / n); // from the corner
      const Vec3 c = corner * ((rim_radius - s) / rim_radius) + Vec3{0, 0, h * std::sin(up * deg)};
      int n_touching = 0;
      const Vec3 sum = rim_force_sum(n, rim_radius, c, r_rim, n_touching);
      const Probe p = press(plate, c, r_rim);
      // Just either side of the bisector: the azimuth turned by +-1e-9 rad.
      const auto turned = [&](double a) {
        return Vec3{c.x * std::cos(a) - c.y * std::sin(a), c.x * std::sin(a) + c.y * std::cos(a),
                    c.z};
      };
      const Vec3 f_minus = press(plate, turned(-1e-9), r_rim).force;
      const Vec3 f_plus = press(plate, turned(1e-9), r_rim).force;
      const double fh = hertz(delta_rim, r_rim);
      const double angle = std::acos(std::min(1.0, dot(p.force, sum) / norm(p.force) / norm(sum)));
      WARN(n << "-gon corner, " << up << " deg above the plane: " << n_touching
             << " edges touch; force " << norm(p.force) << " N against the sum's " << norm(sum)
             << " N (ratio " << norm(p.force) / norm(sum) << "), " << angle / deg
             << " deg off it; across the bisector the force jumps by "
             << norm(f_plus - f_minus) / fh << " F_H; elastic energy " << p.elastic
             << " J against the applied contact's " << hertz_energy(delta_rim, r_rim) << " J");
      CHECK(n_touching == 2);
      CHECK(off_deepest(n, rim_radius, c, r_rim, p.force) <= 1e-9); // what the engine does
      CHECK(off(p.force, sum, norm(sum)) <= 1e-6); // fails: the second contact is lost
      CHECK(norm(f_plus - f_minus) <= 1e-6 * fh);  // fails: the kept edge swaps
      // System::energy() counts the contact the force applies.
      CHECK(p.elastic == Approx(hertz_energy(delta_rim, r_rim)).epsilon(1e-9));
    }
  }
}

TEST_CASE("wall boundary: a sphere across a narrow slit or on a small hole is pushed straight up",
          "[dem][walls][edges][!mayfail]") {
  // DEFECT (kept failing): a sphere resting on two or more free edges whose normals lie within
  // 25 degrees of their neighbours' gets one contact, the deepest (on a tie the first found):
  // merged_into_another() merges a contact into any deeper one within the angle, and contacts
  // in a chain (each within 25 degrees of the next) all go into the one at its head, however
  // far apart they are. The force then points along one tilted normal: the sphere is pushed
  // sideways off a support that holds it upright.
  const double L = 0.02;
  SECTION("a slit 1.5 mm wide: two contacts 17.4 degrees apart") {
    const double w = 1.5e-3;
    const SurfaceMesh slit = slit_plate(w, L);
    const double tilt = std::asin(0.5 * w / dist0);
    const Probe p = press(slit, Vec3{0, 0.0007, dist0 * std::cos(tilt)}, r0);
    const Vec3 expected{0, 0, 2 * f0 * std::cos(tilt)};
    WARN("slit, normals +-" << tilt / deg << " deg: force (" << p.force.x << ", " << p.force.y
                            << ", " << p.force.z << ") N, expected (0, 0, " << expected.z
                            << ") N; contacts kept " << p.normals.size());
    CHECK(p.normals.size() == 2);
    CHECK(off(p.force, expected, f0) <= 1e-9);
  }
  SECTION("a 32-gon hole of 2.5 mm radius under a sphere of 5 mm: 32 contacts") {
    // Centred on the axis at dist0 from every edge's middle: normals 29.9 degrees from z, the
    // neighbours' 3.3 degrees apart, opposite ones 60 degrees: F = 32 F_H cos 29.9 along z.
    const int n = 32;
    const double R = 0.0025, a = R * std::cos(pi / n);
    const Vec3 c{0, 0, std::sqrt(dist0 * dist0 - a * a)};
    int n_touching = 0;
    const Vec3 expected = rim_force_sum(n, R, c, r0, n_touching);
    const Probe p = press(orifice_plate(n, R), c, r0);
    WARN("32-gon hole under the sphere: " << n_touching << " edges touch; force (" << p.force.x
                                          << ", " << p.force.y << ", " << p.force.z
                                          << ") N, expected (0, 0, " << expected.z
                                          << ") N; contacts kept " << p.normals.size());
    CHECK(n_touching == n);
    CHECK(p.normals.size() == std::size_t(n));
    CHECK(off(p.force, expected, norm(expected)) <= 1e-9);
  }
}

TEST_CASE("wall boundary: how much of an orifice's rim a pressed sphere touches twice",
          "[dem][walls][edges]") {
  // The measure behind the corner defect: a sphere in the plate's plane at overlap delta_rim =
  // 10 um with rim edge 0 of the n-gon, moved along it from corner to corner (20000 positions;
  // near a corner it overlaps the neighbouring edge too, more than this one past the bisector).
  // Reported: the share of the edge where two edges touch, the mean ratio of the deepest
  // contact's force (what the engine applies) to the sum's there, and over the whole edge.
  // Checked at every 50th position: the engine's force is the deepest contact's (1e-9), and
  // the sum's where one edge touches.
  for (int n : {25, 32, 50, 128}) {
    const SurfaceMesh plate = orifice_plate(n, rim_radius);
    const Vec3 a = polygon_vertex(n, rim_radius, 0), b = polygon_vertex(n, rim_radius, 1);
    const Vec3 inward = normalized(-(a + b) * 0.5);
    const int m = 20000;
    int n_twice = 0, n_pressed = 0, n_pressed_twice = 0;
    double ratio_twice = 0, ratio_all = 0, worst = 0;
    for (int k = 0; k < m; ++k) {
      const Vec3 c = a + (b - a) * ((k + 0.5) / m) + inward * (r_rim - delta_rim);
      int n_touching = 0;
      const Vec3 sum = rim_force_sum(n, rim_radius, c, r_rim, n_touching);
      double deepest = 0;
      for (const Vec3& x : rim_contacts(n, rim_radius, c, r_rim))
        deepest = std::max(deepest, norm(x));
      const double ratio = deepest / norm(sum);
      ratio_all += ratio / m;
      if (n_touching > 1) {
        ++n_twice;
        ratio_twice += ratio;
      }
      if (k % 50 == 0) {
        const Vec3 f = press(plate, c, r_rim).force;
        worst = std::max(worst, off_deepest(n, rim_radius, c, r_rim, f));
        if (n_touching == 1)
          worst = std::max(worst, off(f, sum, norm(sum)));
        ++n_pressed;
        n_pressed_twice += n_touching > 1;
      }
    }
    WARN(n << "-gon rim (edge " << norm(b - a) * 1e3 << " mm), sphere r = " << r_rim * 1e3
           << " mm at overlap " << delta_rim * 1e6 << " um: " << 100.0 * n_twice / m
           << " % of the edge touched by two edges, where the engine gives "
           << (n_twice ? ratio_twice / n_twice : 1.0) << " of the sum; mean over the edge "
           << ratio_all);
    INFO(n << "-gon: pressed " << n_pressed << " times (" << n_pressed_twice
           << " on two edges), engine off the deepest contact by " << worst);
    CHECK(worst <= 1e-9);
    CHECK(n_pressed_twice > 0);
  }
}

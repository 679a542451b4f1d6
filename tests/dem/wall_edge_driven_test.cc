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
// Driven at a constant velocity (the sphere 1e15 kg/m^3 heavy, so the contacts deflect it by
// 1e-11 m; restitution 1, no damping), 1 um a step, across a plate of 32 triangles and off
// its corner: face -> shared edges -> free edge -> vertex. Frictionless, the force at every
// step is the analytic one to 1e-9 F_H (so no jump beyond the analytic change of a step);
// sliding with friction 0.5, |F_t| = 0.5 F_n to 1e-9 F_H at every step (the tangential
// history goes along from face to edge to vertex); rolling with a slip of 1e-3 across 5
// triangles, the same force and torque as on one triangle to 1e-9, the spring's load
// k_t x slip to 1e-6.
#include "tests/dem/wall_edge_probes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

// The probes' namespace brings the engine's, the fixtures' and the vector names along.
using namespace wall_edge;

namespace {

/// A sphere driven along a straight line at constant velocity over a wall: so heavy that its
/// contacts do not deflect it (1e15 kg/m^3: 1.7e-9 m/s^2 under F_H), restitution 1 (no
/// damping), friction mu; the time step 10 us (1 um of travel at 0.1 m/s).
struct Driven {
  System s;
  explicit Driven(const SurfaceMesh& wall, const Vec3& start, const Vec3& velocity, double mu,
                  const Vec3& spin = {}) {
    s.settings.gravity = {0, 0, 0};
    s.settings.time_step = 1e-5;
    const int g = add_gravel(s, 1.0, mu, 0);
    s.add_wall(MeshWall(wall, g, {}, false, "plate"));
    s.particles.add(start, velocity, r0, 1e15, g);
    s.particles.angular_velocity[0] = spin;
    s.setup();
  }
  const Vec3& x() const { return s.particles.position[0]; }
  const Vec3& f() const { return s.particles.force[0]; }
};

} // namespace

TEST_CASE("wall boundary: the force is continuous from face to shared edge, free edge, vertex",
          "[dem][walls][edges]") {
  // Over the 20 mm plate of 32 triangles (5 mm squares) at the height dist0 (delta = 50 um)
  // from (7, 6.8) mm along (1, 1): over 5 triangles (across 4 shared edges, 0.14 mm beside
  // three diagonals and two vertices of six faces), it leaves the plate over its edge x = 20 mm
  // at y = 19.8 mm, passes over the corner (20, 20) mm and loses the contact 0.71 mm past it.
  // Frictionless: the force is F_H(r - |c - p|) along c - p, p the closest point of the square (the
  // centre clamped to it), at every step.
  const OneThread one;
  const double L = 0.02;
  const Vec3 v = normalized(Vec3{1, 1, 0}) * 0.1;
  Driven run(grid_plate(0, 0, L / 4, 4), {0.007, 0.0068, dist0}, v, 0.0);
  int n_face = 0, n_edge = 0, n_vertex = 0, n_after = 0;
  double worst = 0, jump = 0, expected_jump = 0;
  Vec3 f_before = run.f(), expected_before = Vec3{0, 0, f0};
  for (int step = 0; step < 25000 && n_after < 100; ++step) {
    run.s.step();
    const Vec3 c = run.x();
    const Vec3 p{std::clamp(c.x, 0.0, L), std::clamp(c.y, 0.0, L), 0};
    const int clamped = (c.x != p.x) + (c.y != p.y);
    const double d = norm(c - p);
    const Vec3 expected = (c - p) / d * hertz(r0 - d, r0);
    if (d >= r0)
      ++n_after;
    else
      (clamped == 0 ? n_face : clamped == 1 ? n_edge : n_vertex)++;
    worst = std::max(worst, off(run.f(), expected, f0));
    jump = std::max(jump, norm(run.f() - f_before));
    expected_jump = std::max(expected_jump, norm(expected - expected_before));
    f_before = run.f();
    expected_before = expected;
  }
  INFO("steps over face " << n_face << ", edge " << n_edge << ", vertex " << n_vertex
                          << "; largest error " << worst << " F_H; largest change in one step "
                          << jump << " N, analytic " << expected_jump << " N");
  CHECK(n_face > 10000);
  CHECK(n_edge > 100);
  CHECK(n_vertex > 100);
  CHECK(n_after == 100);
  CHECK(worst <= 1e-9);
  CHECK(jump <= expected_jump + 1e-9 * f0);
  CHECK(jump < 0.05 * f0); // 1 um of travel: nothing near a jump
}

TEST_CASE("wall boundary: a sliding sphere keeps its friction from face to edge to vertex",
          "[dem][walls][edges]") {
  // The same path with friction 0.5: once the spring has reached the Coulomb limit (19 um of
  // sliding, 20 steps), the sphere slides at every step, on the face at constant overlap, over the
  // free edge and the corner at a falling one (the limit falls with it). |F_t| = 0.5 F_n at every
  // step; a tangential history dropped where the contact passes from one feature to the next
  // would restart the spring from zero (|F_t| of one step's 1 um, 0.02 N against 0.44).
  const OneThread one;
  const double L = 0.02, mu = 0.5;
  const Vec3 v = normalized(Vec3{1, 1, 0}) * 0.1;
  Driven run(grid_plate(0, 0, L / 4, 4), {0.007, 0.0068, dist0}, v, mu);
  int n_checked = 0, n_edge = 0, n_vertex = 0;
  double worst = 0, worst_normal = 0;
  for (int step = 1; step < 25000; ++step) {
    run.s.step();
    const Vec3 c = run.x();
    const Vec3 p{std::clamp(c.x, 0.0, L), std::clamp(c.y, 0.0, L), 0};
    const double d = norm(c - p);
    if (d >= r0)
      break;
    const Vec3 n = (c - p) / d;
    const double fn = dot(run.f(), n);
    const double ft = norm(run.f() - n * fn);
    worst_normal = std::max(worst_normal, std::abs(fn - hertz(r0 - d, r0)) / f0);
    if (step > 100) {
      worst = std::max(worst, std::abs(ft - mu * fn) / f0);
      ++n_checked;
      n_edge += (c.x > L) != (c.y > L);
      n_vertex += c.x > L && c.y > L;
    }
  }
  INFO("steps " << n_checked << " (edge " << n_edge << ", vertex " << n_vertex
                << "): largest | |F_t| - mu F_n | " << worst << " F_H, normal force off by "
                << worst_normal << " F_H");
  CHECK(n_edge > 100);
  CHECK(n_vertex > 100);
  CHECK(worst <= 1e-9);
  CHECK(worst_normal <= 1e-9);
}

TEST_CASE("wall boundary: shared edges of a flat plate change nothing for a rolling sphere",
          "[dem][walls][edges]") {
  // A sphere rolling with a slip of 1e-3 of its speed (0.1 mm/s: its spring loads by 1 nm a
  // step, to 9.7 um over the path, half the Coulomb limit's 19 um) from (3, 4) to (11, 9.5) mm
  // on the 20 mm plate of 32 triangles, over 5 of them (across two grid lines, a diagonal and
  // a third grid line), and on one triangle that holds the same path in its interior: the same
  // force and torque at every step to 1e-9, and at the end |F_t| = k_t x slip x time with
  // k_t = 8 G* sqrt(r delta) (1e-6: a history lost on the way would restart the spring).
  const OneThread one;
  const Vec3 v = Vec3{0.08, 0.055, 0} * (0.1 / norm(Vec3{0.08, 0.055, 0}));
  const double slip = 1e-3;
  const Vec3 spin = cross(Vec3{0, 0, 1}, v) * ((1 - slip) / r0);
  const Vec3 start{0.003, 0.004, dist0};
  Driven grid(grid_plate(0, 0, 0.005, 4), start, v, 0.5, spin);
  Driven one_face(mesh_of({{-0.1, -0.1, 0}, {0.2, -0.1, 0}, {-0.1, 0.2, 0}}, {{0, 1, 2}}), start, v,
                  0.5, spin);
  const int n_steps = 9700;
  double worst = 0, worst_torque = 0;
  std::vector<int> visited; // triangles of the grid under the centre, in order
  for (int step = 0; step < n_steps; ++step) {
    grid.s.step();
    one_face.s.step();
    worst = std::max(worst, off(grid.f(), one_face.f(), norm(one_face.f())));
    worst_torque =
        std::max(worst_torque, off(grid.s.particles.torque[0], one_face.s.particles.torque[0],
                                   norm(one_face.s.particles.torque[0])));
    const Vec3 c = grid.x();
    const int i = int(c.x / 0.005), j = int(c.y / 0.005);
    const int tri = 2 * (4 * j + i) + (c.y - 0.005 * j > c.x - 0.005 * i);
    if (visited.empty() || visited.back() != tri)
      visited.push_back(tri);
  }
  const double g_star = youngs / (2 * (1 + poisson)) / (2 * (2 - poisson));
  // The spring's load: the slip over the setup's evaluation and every step.
  const double ft_expected =
      8 * g_star * std::sqrt(r0 * delta0) * slip * norm(v) * (n_steps + 1) * 1e-5;
  const double ft = norm(Vec3{grid.f().x, grid.f().y, 0});
  INFO("triangles under the centre " << visited.size() << "; largest difference: force " << worst
                                     << ", torque " << worst_torque << "; |F_t| at the end " << ft
                                     << " N, expected " << ft_expected << " N");
  CHECK(visited.size() == 5);
  CHECK(ft == Approx(ft_expected).epsilon(1e-6));
  CHECK(worst <= 1e-9);
  CHECK(worst_torque <= 1e-9);
}

// Revolution walls on their own: the exact closest point of each kind against brute force over
// a fine sampling of the bounded surface, the angle's frame, the accounting face, and clear
// refusals of bad input.
#include "dem/engine/revolution_wall.h"
#include "dem/engine/system.h"
#include "meshes/constants.h"
#include "meshes/tester_walls.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace wear::dem;
using wear::pi;
using wear::meshes::cross;
using wear::meshes::dot;
using wear::meshes::norm;
using wear::meshes::normalized;
using wear::meshes::Vec3;

namespace {

/// The frame of revolution_wall.h: e1 = x projected normal to the axis (y when the axis lies
/// within 25 degrees of x), e2 = axis x e1.
void frame(const Vec3& axis, Vec3& a, Vec3& e1, Vec3& e2) {
  a = normalized(axis);
  const Vec3 ref = std::abs(a.x) > std::cos(25 * pi / 180) ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  e1 = normalized(ref - a * dot(ref, a));
  e2 = cross(a, e1);
}

/// A fine parametric sampling of the bounded surface (edges included) and the largest distance
/// from any surface point to its nearest sample, half the diagonal of a sampling cell.
struct Sampling {
  std::vector<Vec3> points;
  double half_diagonal = 0; ///< [m]
};

Sampling sample(const RevolutionSurface& s, int n_around, int n_across) {
  Vec3 a, e1, e2;
  frame(s.axis, a, e1, e2);
  Sampling out;
  const bool cyl = s.kind == RevolutionKind::cylinder, cone = s.kind == RevolutionKind::cone;
  const bool round = cyl || cone; // along the axis, all the way round
  const double th0 = round ? 0 : s.theta_min, th1 = round ? 2 * pi : s.theta_max;
  const double u0 = round ? s.axial_min : s.inner_radius;
  const double u1 = round ? s.axial_max : s.outer_radius;
  const double r_max = cyl ? s.radius : cone ? std::max(s.radius, s.radius_top) : s.outer_radius;
  // A cone's generator: the radius at u (linear from radius at axial_min to radius_top).
  const auto r_cone = [&](double u) {
    return s.radius + (s.radius_top - s.radius) * (u - s.axial_min) / (s.axial_max - s.axial_min);
  };
  for (int i = 0; i <= n_around; ++i) {
    const double th = th0 + (th1 - th0) * i / n_around;
    const Vec3 radial = e1 * std::cos(th) + e2 * std::sin(th);
    for (int j = 0; j <= n_across; ++j) {
      const double u = u0 + (u1 - u0) * j / n_across;
      out.points.push_back(cyl    ? s.axis_point + a * u + radial * s.radius
                           : cone ? s.axis_point + a * u + radial * r_cone(u)
                                  : s.axis_point + a * s.height + radial * u);
    }
  }
  // A cone's generator is longer than its axial extent by 1 / cos of its half-angle.
  const double slant = cone ? std::hypot(u1 - u0, s.radius_top - s.radius) : u1 - u0;
  const double d_around = r_max * (th1 - th0) / n_around, d_across = slant / n_across;
  out.half_diagonal = 0.5 * std::hypot(d_around, d_across);
  return out;
}

/// True when p lies on the bounded surface (to 1e-12 m).
bool on_surface(const RevolutionSurface& s, const Vec3& p) {
  Vec3 a, e1, e2;
  frame(s.axis, a, e1, e2);
  const Vec3 d = p - s.axis_point;
  const double along = dot(d, a);
  const Vec3 q = d - a * along;
  const double rho = norm(q), tol = 1e-12;
  if (s.kind == RevolutionKind::cylinder)
    return std::abs(rho - s.radius) < tol && along > s.axial_min - tol && along < s.axial_max + tol;
  if (s.kind == RevolutionKind::cone) {
    const double f = (along - s.axial_min) / (s.axial_max - s.axial_min);
    return std::abs(rho - (s.radius + (s.radius_top - s.radius) * f)) < tol &&
           along > s.axial_min - tol && along < s.axial_max + tol;
  }
  if (std::abs(along - s.height) > tol || rho < s.inner_radius - tol || rho > s.outer_radius + tol)
    return false;
  if (rho < tol || s.theta_max - s.theta_min >= 2 * pi)
    return true;
  // The angle from theta_min, counter-clockwise, within the range (an arc of 1e-12 m).
  double from = std::atan2(dot(q, e2), dot(q, e1)) - s.theta_min;
  from -= 2 * pi * std::floor(from / (2 * pi));
  const double width = s.theta_max - s.theta_min, slack = tol / rho;
  return from <= width + slack || from >= 2 * pi - slack;
}

/// Random points in the surface's box widened by half its size on every side (a flat box
/// first thickened to half its largest extent).
std::vector<Vec3> query_points(const Sampling& smp, int n, unsigned seed) {
  Vec3 lo = smp.points[0], hi = lo;
  for (const auto& p : smp.points)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  Vec3 ext = hi - lo;
  const double size = std::max({ext.x, ext.y, ext.z});
  for (int k = 0; k < 3; ++k)
    if (ext[k] < 0.5 * size) {
      lo[k] -= 0.25 * size - 0.5 * ext[k];
      ext[k] = 0.5 * size;
    }
  lo = lo - ext * 0.5;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 2);
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k)
    points.push_back({lo.x + ext.x * u(rng), lo.y + ext.y * u(rng), lo.z + ext.z * u(rng)});
  return points;
}

void check_against_brute_force(const RevolutionSurface& surface, const std::string& what) {
  const RevolutionWall wall(surface, 0, {}, false, what);
  const Sampling smp = sample(surface, 2400, 240);
  INFO(what << ": sampling half-diagonal " << smp.half_diagonal << " m");
  int n_bad_surface = 0, n_beaten = 0, n_far = 0;
  double worst = 0;
  for (const Vec3& c : query_points(smp, 150, 2030)) {
    const Vec3 p = wall.closest(c);
    const double d = norm(c - p);
    double brute2 = std::numeric_limits<double>::infinity();
    for (const Vec3& s : smp.points)
      brute2 = std::min(brute2, wear::meshes::norm2(c - s));
    const double brute = std::sqrt(brute2);
    n_bad_surface += !on_surface(surface, p);
    n_beaten += brute < d - 1e-12; // no surface point may be closer than the exact one
    n_far += brute > d + smp.half_diagonal;
    worst = std::max(worst, brute - d);
    CHECK(wall.distance(c) == d);
  }
  INFO("largest brute-force excess " << worst << " m");
  CHECK(n_bad_surface == 0);
  CHECK(n_beaten == 0);
  CHECK(n_far == 0);
}
} // namespace

TEST_CASE("revolution walls: exact closest points against brute force", "[dem][walls]") {
  // Tolerance: the exact distance is never beaten by a sample (1e-12 m), exceeds the nearest
  // sample by at most the sampling cell's half-diagonal (about 1 mm at these sizes), and the
  // point lies on the bounded surface (1e-12 m). Points up to half the surface's size beyond
  // its box: beyond the rims, the radii and the angular range.
  RevolutionSurface tilted = RevolutionSurface::cylinder(0.3, -0.1, 0.25);
  tilted.axis_point = {0.1, -0.2, 0.3};
  tilted.axis = {1, 2, 2};
  check_against_brute_force(tilted, "cylinder, tilted axis");
  check_against_brute_force(RevolutionSurface::annulus(0.05, 0.29, 0.5), "full annulus");
  RevolutionSurface disc = RevolutionSurface::annulus(-0.1, 0, 0.2);
  disc.axis = {1, 0.1, 0}; // within 25 degrees of x: e1 from y
  check_against_brute_force(disc, "disc about an axis near x");
  check_against_brute_force(
      RevolutionSurface::annulus(0.13, 0.29, 0.5, 130 * pi / 180, 140 * pi / 180),
      "consolidator-like sector");
  check_against_brute_force(RevolutionSurface::annulus(0, 0.1, 0.4, -0.3, 0.4),
                            "sector across theta = 0");
  RevolutionSurface wide = RevolutionSurface::annulus(0.02, 0.1, 0.4, -1, 3.5);
  wide.axis = {0.2, -0.3, 1};
  check_against_brute_force(wide, "sector wider than pi, tilted axis");
  RevolutionSurface hopper = RevolutionSurface::cone(0.025, 0.1, 0, 0.13); // widening upwards
  hopper.axis_point = {0.05, 0, -0.1};
  hopper.axis = {0.1, -0.2, 1};
  check_against_brute_force(hopper, "hopper cone, tilted axis");
  check_against_brute_force(RevolutionSurface::cone(0.3, 0, -0.05, 0.25), "pointed cone");
  RevolutionSurface steep = RevolutionSurface::cone(0.2, 0.19, 0, 0.4); // almost a cylinder
  steep.axis = {1, 0.1, 0};
  check_against_brute_force(steep, "steep frustum about an axis near x");
}

TEST_CASE("revolution walls: a cone's closest point in its meridional plane", "[dem][walls]") {
  // The frustum r = 0.1 at z = 0 to r = 0.2 at z = 0.1 (45 degrees): from (0.1, 0, 0.1), above
  // the generator line r = 0.1 + z, the foot is at t = 0.5 on the generator, (0.15, 0, 0.05),
  // 0.0707 m away; beyond the top rim (0.3, 0, 0.3) it is the rim point (0.2, 0, 0.1); on the
  // axis below (0, 0, -1) the nearest generator end is the bottom rim, at every angle: e1.
  const RevolutionWall w(RevolutionSurface::cone(0.1, 0.2, 0, 0.1), 0, {}, false, "hopper");
  CHECK(norm(w.closest(Vec3{0.1, 0, 0.1}) - Vec3{0.15, 0, 0.05}) < 1e-15);
  CHECK(w.distance(Vec3{0.1, 0, 0.1}) == Approx(std::sqrt(2) * 0.05).epsilon(1e-14));
  CHECK(norm(w.closest(Vec3{0.3, 0, 0.3}) - Vec3{0.2, 0, 0.1}) < 1e-15);
  CHECK(norm(w.closest(Vec3{0, 0, -1}) - Vec3{0.1, 0, 0}) < 1e-15);
  // The same in another meridional plane: turned by 2 rad about z.
  const double c = std::cos(2.0), s = std::sin(2.0);
  CHECK(norm(w.closest(Vec3{0.1 * c, 0.1 * s, 0.1}) - Vec3{0.15 * c, 0.15 * s, 0.05}) < 1e-15);
}

TEST_CASE("revolution walls: a point beyond an angular edge projects onto the edge segment",
          "[dem][walls]") {
  // Sector 0 <= theta <= 0.5 at z = 0, r in [0.29, 0.5]; a point at theta = -1, r = 0.4: the
  // projection onto the theta = 0 ray is 0.4 cos 1 = 0.216, clamped to r = 0.29, closer
  // (0.345 m) than the polar clamp to (0.4, theta = 0) (0.383 m).
  const RevolutionWall w(RevolutionSurface::annulus(0, 0.29, 0.5, 0, 0.5), 0, {}, false, "s");
  const Vec3 c{0.4 * std::cos(-1.0), 0.4 * std::sin(-1.0), 0.01};
  const Vec3 p = w.closest(c);
  CHECK(norm(p - Vec3{0.29, 0, 0}) < 1e-15);
  // On the theta axis for the z axis: atan2(y, x), so the same sector turned by +1 rad holds
  // the point's rotation image at its own angle.
  const RevolutionWall turned(RevolutionSurface::annulus(0, 0.29, 0.5, 1, 1.5), 0, {}, false, "t");
  const Vec3 inside{0.4 * std::cos(1.2), 0.4 * std::sin(1.2), 0.01};
  CHECK(norm(turned.closest(inside) - Vec3{inside.x, inside.y, 0}) < 1e-15);
}

TEST_CASE("revolution walls: the accounting face is the face nearest to the point",
          "[dem][walls][wear]") {
  wear::meshes::TesterGeometry t;
  t.sector_angle_deg = 40;
  t.wall_height = 0.1;
  t.wall_mesh_size = 0.01;
  const auto meshes = wear::meshes::generate_tester_walls(t);
  const RevolutionWall outer(RevolutionSurface::cylinder(0.5, 0, 0.1), 0, {}, true, "outer",
                             &meshes.outer);
  REQUIRE(outer.n_faces() == meshes.outer.n_faces());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> th(-0.2, 0.9), z(-0.02, 0.12);
  int n_differ = 0;
  for (int k = 0; k < 400; ++k) { // on the surface, some beyond the triangulated part
    const double a = th(rng);
    const Vec3 p{0.5 * std::cos(a), 0.5 * std::sin(a), z(rng)};
    std::uint32_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::uint32_t f = 0; f < meshes.outer.n_faces(); ++f) {
      const double d = norm(outer.accounting()->closest(f, p).point - p);
      if (d < best_d) {
        best_d = d;
        best = f;
      }
    }
    n_differ += outer.accounting_face(p) != best;
  }
  CHECK(n_differ == 0);
}

TEST_CASE("revolution walls: bad input is refused naming the wall", "[dem][walls][errors]") {
  using Catch::Contains;
  CHECK_THROWS_WITH(RevolutionWall(RevolutionSurface::annulus(0, 0.3, 0.2), 0, {}, false, "floor"),
                    Contains("'floor'") && Contains("radii"));
  CHECK_THROWS_WITH(RevolutionWall(RevolutionSurface::cylinder(0, 0, 1), 0, {}, false, "inner"),
                    Contains("'inner'") && Contains("radius"));
  CHECK_THROWS_WITH(RevolutionWall(RevolutionSurface::cone(0, 0, 0, 1), 0, {}, false, "cone"),
                    Contains("'cone'") && Contains("not both 0"));
  CHECK_THROWS_WITH(RevolutionWall(RevolutionSurface::cone(-0.1, 0.2, 0, 1), 0, {}, false, "cone"),
                    Contains("'cone'") && Contains("not negative"));
  CHECK_THROWS_WITH(RevolutionWall(RevolutionSurface::cone(0.1, 0.2, 1, 1), 0, {}, false, "cone"),
                    Contains("'cone'") && Contains("axial extent"));
  CHECK_THROWS_WITH(
      RevolutionWall(RevolutionSurface::annulus(0, 0.1, 0.2, 1, 0.5), 0, {}, false, "plate"),
      Contains("'plate'") && Contains("angular range"));
  CHECK_THROWS_WITH(RevolutionWall(RevolutionSurface::annulus(0, 0.29, 0.5), 0, {}, true, "floor"),
                    Contains("'floor'") && Contains("accounting mesh"));
  wear::meshes::TesterGeometry t;
  t.consolidator = false;
  const auto meshes = wear::meshes::generate_tester_walls(t);
  // The inner cylinder's triangulation is not the outer cylinder.
  CHECK_THROWS_WITH(RevolutionWall(RevolutionSurface::cylinder(0.5, 0, t.wall_height), 0, {}, true,
                                   "outer", &meshes.inner),
                    Contains("'outer'") && Contains("off the surface"));

  System s;
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  const int floor = s.add_wall(RevolutionWall(RevolutionSurface::annulus(0, 0.29, 0.5), g, {}, true,
                                              "floor", &meshes.floor));
  const int box = s.add_wall(MeshWall(meshes.inner, g, {}, false, "inner mesh"));
  CHECK(s.n_walls() == 2);
  CHECK(s.wall_kind(floor) == WallKind::revolution);
  CHECK(s.wall_kind(box) == WallKind::mesh);
  CHECK(s.revolution_wall(floor).name() == "floor");
  CHECK(s.wall(box).name() == "inner mesh");
  CHECK_THROWS_WITH(s.wall(floor), Contains("'floor'") && Contains("revolution wall"));
  CHECK_THROWS_WITH(s.revolution_wall(box), Contains("'inner mesh'") && Contains("mesh wall"));
  CHECK_THROWS_WITH(s.replace_wall_mesh(floor, meshes.floor), Contains("'floor'"));
  CHECK_THROWS_WITH(s.set_wall_vertices(floor, meshes.floor.vertices), Contains("'floor'"));
  CHECK_THROWS_WITH(
      s.add_wall(RevolutionWall(RevolutionSurface::annulus(0, 0.29, 0.5), g + 1, {}, false, "lid")),
      Contains("'lid'") && Contains("material"));
}

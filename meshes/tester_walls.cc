// Tester walls: structured triangulations of an annular sector (floor, consolidator) and of
// cylinder sectors (inner and outer walls). The angular resolution follows the target edge
// length at the outer radius, so no triangle edge exceeds it; vertices lie exactly on the
// analytic surfaces and the sector's cut planes at theta = 0 and theta = Theta.
#include "meshes/tester_walls.h"

#include "meshes/structured_grid.h"

#include <algorithm>
#include <cmath>

namespace wear::meshes {

namespace {
constexpr double pi = 3.14159265358979323846;
int divisions(double length, double size) {
  return std::max(1, static_cast<int>(std::ceil(length / size - 1e-9)));
}

} // namespace

TesterWalls generate_tester_walls(const TesterGeometry& t) {
  const double Th = t.sector_angle_deg * pi / 180, ri = t.inner_radius, ro = t.outer_radius;
  const double H = t.wall_height, h = t.wall_mesh_size;
  const int n_th = divisions(ro * Th, h), n_r = divisions(ro - ri, h), n_z = divisions(H, h);
  TesterWalls w;
  // (u, v) = (radius, angle): d/du x d/dv points along +z, the floor's normal.
  w.floor = structured_grid(
      n_r, n_th,
      [&](double u, double v) {
        const double r = ri + u * (ro - ri), th = v * Th;
        return Vec3{r * std::cos(th), r * std::sin(th), 0.0};
      },
      false, label::wall);
  // (u, v) = (angle, height): d/du x d/dv = e_theta x e_z = +e_r.
  const auto cylinder = [&](double r, bool flip) {
    return structured_grid(
        n_th, n_z,
        [&](double u, double v) {
          const double th = u * Th;
          return Vec3{r * std::cos(th), r * std::sin(th), v * H};
        },
        flip, label::wall);
  };
  w.inner = cylinder(ri, false);
  w.outer = cylinder(ro, true);
  if (t.consolidator) {
    const double e = t.consolidator_extent_deg * pi / 180;
    const double th0 = t.consolidator_angle_deg * pi / 180 - e / 2;
    w.consolidator = structured_grid(
        n_r, divisions(ro * e, h),
        [&](double u, double v) {
          const double r = ri + u * (ro - ri), th = th0 + v * e;
          return Vec3{r * std::cos(th), r * std::sin(th), t.consolidator_height};
        },
        true, label::wall);
  }
  return w;
}

SurfaceMesh widen_sector(const SurfaceMesh& wall, double angle, double margin) {
  SurfaceMesh e = wall;
  const double scale = (angle + 2 * margin) / angle;
  for (auto& v : e.vertices) {
    const double r = std::hypot(v.x, v.y), th = std::atan2(v.y, v.x);
    const double th_full = th < -1e-12 ? th + 2 * pi : th;
    const double th2 = th_full * scale - margin;
    v = {r * std::cos(th2), r * std::sin(th2), v.z};
  }
  e.bump_revision();
  return e;
}

} // namespace wear::meshes

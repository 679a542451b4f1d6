// Tester walls: structured triangulations of an annular sector (floor, consolidator) and of
// cylinder sectors (inner and outer walls). The angular resolution follows the target edge
// length at the outer radius, so no triangle edge exceeds it; vertices lie exactly on the
// analytic surfaces and the sector's cut planes at theta = 0 and theta = Theta.
//
// The sample holder: the box [-W/2 - w, W/2 + w] x [-L/2 - w, L/2 + w] x [-w, T] less the
// pocket [-W/2, W/2] x [-L/2, L/2] x [0, T] the sample fills (w the rim width, T the sample
// thickness), open at the top, so the rim top lies in the wear face's plane. All its faces
// are axis-aligned rectangles on one tensor grid: per axis the break points (outer wall,
// pocket wall, pocket wall, outer wall) with each interval split into equal parts no longer
// than the mesh size. Every rectangle takes the grid cells it covers, so two rectangles
// meeting at an edge share its vertices bit for bit and the surface is closed and conforming
// without a search.
#include "meshes/tester_walls.h"

#include "meshes/constants.h"
#include "meshes/structured_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace wear::meshes {

namespace {
int divisions(double length, double size) {
  return std::max(1, static_cast<int>(std::ceil(length / size - 1e-9)));
}

/// Coordinates from b[0] to b.back() through every break point, each interval split into
/// equal parts no longer than `size`.
std::vector<double> axis_points(const std::vector<double>& b, double size) {
  std::vector<double> x{b[0]};
  for (std::size_t k = 0; k + 1 < b.size(); ++k) {
    const int n = divisions(b[k + 1] - b[k], size);
    for (int i = 1; i < n; ++i)
      x.push_back(b[k] + (b[k + 1] - b[k]) * i / n);
    x.push_back(b[k + 1]);
  }
  return x;
}

/// Index of the coordinate equal to `value` (a break point, stored exactly).
int index_of(const std::vector<double>& x, double value) {
  return int(std::find(x.begin(), x.end(), value) - x.begin());
}

/// Builds a surface from axis-aligned rectangles on the grid of three axis point lists,
/// sharing grid vertices.
class GridSurface {
public:
  explicit GridSurface(std::array<std::vector<double>, 3> axes) : axes_(std::move(axes)) {}

  /// The rectangle at coordinate index `at` of axis `normal_axis`, over the index ranges
  /// [a0, a1] and [b0, b1] of the other two axes (in cyclic order), facing +normal_axis when
  /// `positive`.
  void rectangle(int normal_axis, int at, int a0, int a1, int b0, int b1, bool positive,
                 int label_id) {
    const int ua = (normal_axis + 1) % 3, ub = (normal_axis + 2) % 3;
    for (int i = a0; i < a1; ++i)
      for (int j = b0; j < b1; ++j) {
        const auto corner = [&](int di, int dj) {
          std::array<int, 3> idx{};
          idx[normal_axis] = at;
          idx[ua] = i + di;
          idx[ub] = j + dj;
          return vertex(idx);
        };
        // (e_ua, e_ub, e_normal) is right-handed: counter-clockwise in (a, b) faces +normal.
        const std::uint32_t v00 = corner(0, 0), v10 = corner(1, 0), v11 = corner(1, 1),
                            v01 = corner(0, 1);
        if (positive) {
          add({v00, v10, v11}, label_id);
          add({v00, v11, v01}, label_id);
        } else {
          add({v00, v11, v10}, label_id);
          add({v00, v01, v11}, label_id);
        }
      }
  }
  SurfaceMesh take() { return std::move(mesh_); }

private:
  std::array<std::vector<double>, 3> axes_;
  std::map<std::array<int, 3>, std::uint32_t> index_;
  SurfaceMesh mesh_;
  std::uint32_t vertex(const std::array<int, 3>& idx) {
    const auto [it, inserted] = index_.emplace(idx, std::uint32_t(mesh_.vertices.size()));
    if (inserted)
      mesh_.vertices.push_back({axes_[0][idx[0]], axes_[1][idx[1]], axes_[2][idx[2]]});
    return it->second;
  }
  void add(const Triangle& t, int label_id) {
    mesh_.triangles.push_back(t);
    mesh_.face_labels.push_back(label_id);
  }
};

} // namespace

SurfaceMesh generate_holder(const SampleGeometry& s, const TesterGeometry& t) {
  const double w = t.holder_rim_width, hx = s.width / 2, hy = s.length / 2, T = s.thickness;
  const double h = std::min(t.wall_mesh_size, w);
  const std::vector<double> bx{-hx - w, -hx, hx, hx + w}, by{-hy - w, -hy, hy, hy + w},
      bz{-w, 0.0, T};
  const std::array<std::vector<double>, 3> axes{axis_points(bx, h), axis_points(by, h),
                                                axis_points(bz, h)};
  GridSurface g(axes);
  // Grid indices of the break points per axis: outer low, pocket low, pocket high, outer high.
  std::array<std::array<int, 4>, 3> k{};
  const std::array<const std::vector<double>*, 3> breaks{&bx, &by, &bz};
  for (int a = 0; a < 3; ++a)
    for (std::size_t m = 0; m < breaks[a]->size(); ++m)
      k[a][m] = index_of(axes[a], (*breaks[a])[m]);
  const int x0 = k[0][0], x1 = k[0][1], x2 = k[0][2], x3 = k[0][3];
  const int y0 = k[1][0], y1 = k[1][1], y2 = k[1][2], y3 = k[1][3];
  const int zb = k[2][0], zp = k[2][1], zt = k[2][2];
  using label::pocket;
  using label::wall;
  // Outer faces: underside (-z), the four outer sides, the rim top (+z) as four strips around
  // the pocket. Axis cycles: normal x -> (y, z), normal y -> (z, x), normal z -> (x, y).
  g.rectangle(2, zb, x0, x3, y0, y3, false, wall);
  g.rectangle(0, x0, y0, y3, zb, zt, false, wall);
  g.rectangle(0, x3, y0, y3, zb, zt, true, wall);
  g.rectangle(1, y0, zb, zt, x0, x3, false, wall);
  g.rectangle(1, y3, zb, zt, x0, x3, true, wall);
  g.rectangle(2, zt, x0, x1, y0, y3, true, wall);
  g.rectangle(2, zt, x2, x3, y0, y3, true, wall);
  g.rectangle(2, zt, x1, x2, y0, y1, true, wall);
  g.rectangle(2, zt, x1, x2, y2, y3, true, wall);
  // The pocket: its floor faces up into the pocket, its walls face the pocket's centre.
  g.rectangle(2, zp, x1, x2, y1, y2, true, pocket);
  g.rectangle(0, x1, y1, y2, zp, zt, true, pocket);
  g.rectangle(0, x2, y1, y2, zp, zt, false, pocket);
  g.rectangle(1, y1, zp, zt, x1, x2, true, pocket);
  g.rectangle(1, y2, zp, zt, x1, x2, false, pocket);
  return g.take();
}

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

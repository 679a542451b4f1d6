// Mass properties of a clump: the union of overlapping spheres as one rigid body.
//
// The union's volume V, first moments m_i = int x_i dV and second moments S_ij =
// int x_i x_j dV are integrated over columns parallel to z on a regular grid of spacing
// (h_x, h_y) covering the members' bounding box. Along a column at (x, y) each member whose disc
// holds the point covers the interval z_c -+ sqrt(r^2 - rho^2); the intervals are merged, so a
// point inside several members counts once, and each merged interval [a, b] adds exactly
//   int dz = b - a,   int z dz = (b^2 - a^2) / 2,   int z^2 dz = (b^3 - a^3) / 3
// times h_x h_y (midpoint rule in x and y). The integrand of the column sum has a square-root
// edge at each disc's rim, so the relative error falls as h^1.5 (h the spacing over the
// smallest radius), about 2e-5 at 200 columns per radius for a sphere.
//
// With c = m / V the centre of mass, the central second moments are C = S - V c c^T and the
// inertia tensor over density I = tr(C) 1 - C. Its eigenvectors (cyclic Jacobi) are the body
// axes; the members are given in that frame.
#include "dem/engine/clump_shape.h"

#include "meshes/constants.h"
#include "meshes/symmetric_eigen.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace wear::dem {

double ClumpShape::equivalent_diameter() const {
  return std::cbrt(6.0 * volume / pi);
}

double ClumpShape::reach() const {
  double r = 0;
  for (const auto& m : members)
    r = std::max(r, meshes::norm(m.centre) + m.radius);
  return r;
}

ClumpShape ClumpShape::scaled(double factor) const {
  ClumpShape s = *this;
  for (auto& m : s.members)
    m.centre *= factor, m.radius *= factor;
  s.volume *= factor * factor * factor;
  s.moments *= std::pow(factor, 5);
  s.centre *= factor;
  return s;
}

ClumpShape clump_shape(const ClumpTemplate& t, int cells_per_radius) {
  const std::string what = "clump template '" + t.name + "'";
  if (t.members.empty())
    throw std::invalid_argument(what + " has no member spheres");
  if (cells_per_radius < 4)
    throw std::invalid_argument(what + ": at least 4 columns per radius are needed, not " +
                                std::to_string(cells_per_radius));
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  double r_min = 1e300;
  for (std::size_t k = 0; k < t.members.size(); ++k) {
    const ClumpMember& m = t.members[k];
    if (!(m.radius > 0) || !std::isfinite(m.radius))
      throw std::invalid_argument(what + ": member " + std::to_string(k + 1) + " has the radius " +
                                  std::to_string(m.radius) +
                                  " m; a positive finite radius is needed");
    if (!std::isfinite(m.centre.x) || !std::isfinite(m.centre.y) || !std::isfinite(m.centre.z))
      throw std::invalid_argument(what + ": member " + std::to_string(k + 1) +
                                  " has a centre that is not finite");
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], m.centre[d] - m.radius);
      hi[d] = std::max(hi[d], m.centre[d] + m.radius);
    }
    r_min = std::min(r_min, m.radius);
  }
  const double h = r_min / cells_per_radius;
  const long nx = std::max(1L, long(std::ceil((hi.x - lo.x) / h)));
  const long ny = std::max(1L, long(std::ceil((hi.y - lo.y) / h)));
  const double hx = (hi.x - lo.x) / double(nx), hy = (hi.y - lo.y) / double(ny);
  // Moments about the bounding box's centre (smaller numbers than about a far origin).
  const Vec3 o = (lo + hi) * 0.5;
  double vol = 0, m1[3] = {0, 0, 0}, s2[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  std::vector<std::pair<double, double>> run;
  run.reserve(t.members.size());
  for (long i = 0; i < nx; ++i) {
    const double x = lo.x + (double(i) + 0.5) * hx;
    // One row's sums, added to the totals once (round-off grows with the row, not the grid).
    double row_v = 0, row_z = 0, row_zz = 0, row_y = 0, row_yy = 0, row_yz = 0;
    for (long j = 0; j < ny; ++j) {
      const double y = lo.y + (double(j) + 0.5) * hy;
      run.clear();
      for (const ClumpMember& m : t.members) {
        const double rho2 =
            (x - m.centre.x) * (x - m.centre.x) + (y - m.centre.y) * (y - m.centre.y);
        if (rho2 < m.radius * m.radius) {
          const double s = std::sqrt(m.radius * m.radius - rho2);
          run.emplace_back(m.centre.z - o.z - s, m.centre.z - o.z + s);
        }
      }
      if (run.empty())
        continue;
      std::sort(run.begin(), run.end());
      double len = 0, z1 = 0, z2 = 0;
      double a = run[0].first, b = run[0].second;
      auto close = [&] {
        len += b - a;
        z1 += 0.5 * (b * b - a * a);
        z2 += (b * b * b - a * a * a) / 3.0;
      };
      for (std::size_t k = 1; k < run.size(); ++k)
        if (run[k].first > b) {
          close();
          a = run[k].first, b = run[k].second;
        } else {
          b = std::max(b, run[k].second);
        }
      close();
      const double yc = y - o.y;
      row_v += len, row_z += z1, row_zz += z2;
      row_y += yc * len, row_yy += yc * yc * len, row_yz += yc * z1;
    }
    const double xc = x - o.x, w = hx * hy;
    vol += w * row_v;
    m1[0] += w * xc * row_v, m1[1] += w * row_y, m1[2] += w * row_z;
    s2[0][0] += w * xc * xc * row_v, s2[1][1] += w * row_yy, s2[2][2] += w * row_zz;
    s2[0][1] += w * xc * row_y, s2[0][2] += w * xc * row_z, s2[1][2] += w * row_yz;
  }
  ClumpShape s;
  s.name = t.name;
  s.volume = vol;
  const Vec3 c{m1[0] / vol, m1[1] / vol, m1[2] / vol};
  double inertia[3][3];
  const double c_arr[3] = {c.x, c.y, c.z};
  double central[3][3];
  for (int p = 0; p < 3; ++p)
    for (int q = p; q < 3; ++q)
      central[p][q] = central[q][p] = s2[p][q] - vol * c_arr[p] * c_arr[q];
  const double trace = central[0][0] + central[1][1] + central[2][2];
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q)
      inertia[p][q] = (p == q ? trace : 0.0) - central[p][q];
  meshes::symmetric_eigen(inertia, s.moments, s.axis);
  s.centre = c + o;
  for (const ClumpMember& m : t.members) {
    const Vec3 d = m.centre - s.centre;
    s.members.push_back(
        {{meshes::dot(s.axis[0], d), meshes::dot(s.axis[1], d), meshes::dot(s.axis[2], d)},
         m.radius});
  }
  return s;
}

} // namespace wear::dem

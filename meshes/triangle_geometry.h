#pragma once
// Closest point of a triangle to a point (Ericson, Real-Time Collision Detection 5.1.5), with
// the feature (face interior, edge, vertex) that holds it. Shared by the DEM contact search
// and the surface locator; inline because it sits in the DEM inner loop.
#include "meshes/vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace wear::meshes {

enum class TriangleFeature : std::uint8_t { face = 0, edge = 1, vertex = 2 };

struct TrianglePoint {
  Vec3 point;
  TriangleFeature feature = TriangleFeature::face;
  int local = 0; ///< edge k (vertices k, k+1) or vertex k of the triangle
};

/// The point of the segment ab closest to p.
inline Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return a + ab * t;
}

/// The face region needs strictly positive barycentric coordinates, so a point on a shared
/// edge is an edge point for both triangles.
inline TrianglePoint closest_point_on_triangle(const Vec3& a, const Vec3& b, const Vec3& c,
                                               const Vec3& p) {
  using F = TriangleFeature;
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
    return {a, F::vertex, 0};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
    return {b, F::vertex, 1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
    return {a + ab * (d1 / (d1 - d3)), F::edge, 0};
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
    return {c, F::vertex, 2};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
    return {a + ac * (d2 / (d2 - d6)), F::edge, 2};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return {b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), F::edge, 1};
  const double denom = 1 / (va + vb + vc);
  return {a + ab * (vb * denom) + ac * (vc * denom), F::face, 0};
}

/// True when triangle abc and the axis-aligned box [lo, hi] share a point: no separating axis
/// among the box's three, the triangle's normal and the nine edge-axis cross products
/// (Akenine-Moeller's test).
inline bool triangle_intersects_box(Vec3 a, Vec3 b, Vec3 c, const Vec3& lo, const Vec3& hi) {
  const Vec3 centre = (lo + hi) * 0.5, h = (hi - lo) * 0.5;
  a = a - centre;
  b = b - centre;
  c = c - centre;
  const auto separated = [&](const Vec3& axis) {
    const double p0 = dot(axis, a), p1 = dot(axis, b), p2 = dot(axis, c);
    const double lo_p = std::fmin(p0, std::fmin(p1, p2)), hi_p = std::fmax(p0, std::fmax(p1, p2));
    const double r = h.x * std::fabs(axis.x) + h.y * std::fabs(axis.y) + h.z * std::fabs(axis.z);
    return lo_p > r || hi_p < -r;
  };
  const Vec3 units[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const Vec3& u : units)
    if (separated(u))
      return false;
  const Vec3 edges[3] = {b - a, c - b, a - c};
  if (separated(cross(edges[0], edges[1])))
    return false;
  for (const Vec3& e : edges)
    for (const Vec3& u : units)
      if (separated(cross(u, e)))
        return false;
  return true;
}

/// True when triangle abc and the solid cylinder of radius r around the segment from `base`
/// along the unit vector `u` for `length` share a point. The triangle is clipped to the slab
/// 0 <= (x - base) . u <= length; the clipped polygon meets the cylinder when its projection
/// onto the plane normal to u comes within r of the axis (or covers it). With `r_inner`, the
/// cylinder has a coaxial hole: the polygon, connected, must also reach r_inner from the axis
/// (its farthest point from the axis is a vertex).
inline bool triangle_intersects_cylinder(const Vec3& a, const Vec3& b, const Vec3& c,
                                         const Vec3& base, const Vec3& u, double length, double r,
                                         double r_inner = 0) {
  // Sutherland-Hodgman against s >= 0 and s <= length; at most 5 vertices remain.
  Vec3 poly[8] = {a - base, b - base, c - base};
  int n = 3;
  const auto clip = [&](double sign, double offset) { // keep sign * s <= offset
    Vec3 out[8];
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3 &p = poly[i], &q = poly[(i + 1) % n];
      const double dp = sign * dot(p, u) - offset, dq = sign * dot(q, u) - offset;
      if (dp <= 0)
        out[m++] = p;
      if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0))
        out[m++] = p + (q - p) * (dp / (dp - dq));
    }
    n = m;
    for (int i = 0; i < m; ++i)
      poly[i] = out[i];
  };
  clip(-1, 0);
  clip(1, length);
  if (n == 0)
    return false;
  // Projections onto the plane normal to u; the axis is the origin there.
  Vec3 q[8];
  for (int i = 0; i < n; ++i)
    q[i] = poly[i] - u * dot(poly[i], u);
  double nearest = std::numeric_limits<double>::infinity(), farthest = 0, area = 0, scale = 0;
  bool all_left = true, all_right = true;
  for (int i = 0; i < n; ++i) {
    area += dot(cross(q[i], q[(i + 1) % n]), u);
    scale = std::fmax(scale, dot(q[i], q[i]));
    farthest = std::fmax(farthest, norm(q[i]));
    const Vec3 &p = q[i], &e = q[(i + 1) % n] - q[i];
    const double ee = dot(e, e);
    const double t = ee > 0 ? std::fmin(1.0, std::fmax(0.0, -dot(p, e) / ee)) : 0.0;
    nearest = std::fmin(nearest, norm(p + e * t));
    const double side = dot(cross(p, e), u); // the origin's side of the edge
    all_left = all_left && side >= 0;
    all_right = all_right && side <= 0;
  }
  // A polygon parallel to the axis projects to a segment: no area, nothing to cover.
  const bool covers = std::fabs(area) > 1e-12 * scale && (all_left || all_right);
  return (nearest <= r || covers) && farthest >= r_inner;
}

} // namespace wear::meshes

// A closed surface's solid as a fill region (solid_region.h).
//
// Inside: the winding number w(p) = (1 / 4 pi) sum_f Omega_f(p), Omega_f the signed solid
// angle of face f seen from p, tan(Omega / 2) = a . (b x c) / (|a||b||c| + (a . b)|c| +
// (b . c)|a| + (c . a)|b|) with a, b, c the face's vertices relative to p (Van Oosterom and
// Strackee 1983); w is 1 inside a closed outward surface and 0 outside, so w > 1/2 decides.
// Segment through triangle: Moeller-Trumbore, the segment's parameter in [0, 1].
#include "meshes/solid_region.h"

#include "meshes/constants.h"

#include <cmath>
#include <stdexcept>

namespace wear::meshes {

namespace {

/// Whether segment pq passes through triangle abc (touching counts).
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                            const Vec3& c) {
  const Vec3 d = q - p, e1 = b - a, e2 = c - a;
  const Vec3 h = cross(d, e2);
  const double det = dot(e1, h);
  const double scale = norm(d) * norm(e1) * norm(e2);
  if (std::fabs(det) <= 1e-14 * scale) // parallel: a coplanar graze is left to the vertex tests
    return false;
  const Vec3 s = p - a;
  const double u = dot(s, h) / det;
  if (u < 0 || u > 1)
    return false;
  const Vec3 k = cross(s, e1);
  const double v = dot(d, k) / det;
  if (v < 0 || u + v > 1)
    return false;
  const double t = dot(e2, k) / det;
  return t >= 0 && t <= 1;
}

bool boxes_overlap(const BoundingBox& x, const BoundingBox& y) {
  return x.min.x <= y.max.x && y.min.x <= x.max.x && x.min.y <= y.max.y && y.min.y <= x.max.y &&
         x.min.z <= y.max.z && y.min.z <= x.max.z;
}

} // namespace

SolidRegion::SolidRegion(const SurfaceMesh& surface, const std::string& what)
    : surface_(surface), locator_(surface_) {
  const auto closed = check_closed(surface_);
  if (!closed.closed())
    throw std::invalid_argument(what +
                                ": a fill region from a mesh must be a closed solid; its "
                                "surface has " +
                                std::to_string(closed.n_boundary_edges) + " boundary and " +
                                std::to_string(closed.n_nonmanifold_edges) + " non-manifold edges");
  volume_ = enclosed_volume(surface_);
  if (!(volume_ > 0))
    throw std::invalid_argument(what + ": the mesh encloses no volume (" + std::to_string(volume_) +
                                " m^3: turned inside out?)");
  box_ = bounding_box(surface_);
}

bool SolidRegion::contains(const Vec3& p) const {
  if (p.x < box_.min.x || p.y < box_.min.y || p.z < box_.min.z || p.x > box_.max.x ||
      p.y > box_.max.y || p.z > box_.max.z)
    return false;
  double omega = 0;
  for (const auto& t : surface_.triangles) {
    const Vec3 a = surface_.vertices[t[0]] - p, b = surface_.vertices[t[1]] - p,
               c = surface_.vertices[t[2]] - p;
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    omega += 2 * std::atan2(numerator, denominator);
  }
  return omega > 2 * pi; // winding number above 1/2
}

double SolidRegion::distance(const Vec3& p) const {
  return locator_.nearest(p).distance;
}

bool SolidRegion::cuts(const Vec3& a, const Vec3& b, const Vec3& c) const {
  const Vec3 corners[3] = {a, b, c};
  const BoundingBox tri = bounding_box(corners, 3);
  if (!boxes_overlap(tri, box_))
    return false;
  for (const Vec3& x : corners)
    if (contains(x))
      return true;
  for (const auto& t : surface_.triangles) {
    const Vec3 &p = surface_.vertices[t[0]], &q = surface_.vertices[t[1]],
               &r = surface_.vertices[t[2]];
    const Vec3 face[3] = {p, q, r};
    if (!boxes_overlap(tri, bounding_box(face, 3)))
      continue;
    if (segment_meets_triangle(a, b, p, q, r) || segment_meets_triangle(b, c, p, q, r) ||
        segment_meets_triangle(c, a, p, q, r) || segment_meets_triangle(p, q, a, b, c) ||
        segment_meets_triangle(q, r, a, b, c) || segment_meets_triangle(r, p, a, b, c))
      return true;
  }
  return false;
}

} // namespace wear::meshes

// Surface quality metrics.
//
// Aspect ratio of a triangle: l_max / (2 sqrt(3) r_in), r_in = 2A / perimeter; it is 1 for
// an equilateral triangle. Self-intersection: each face's bounding box is binned into a
// uniform grid with a cell size of twice the mean edge length; a pair is tested only in the
// grid cell that holds the lower corner of the overlap of their boxes, so every pair is
// tested once. The pair test is segment-triangle (Moller-Trumbore) for every edge of each
// face against the other face, with strict interiors so shared vertices do not count.
#include "meshes/mesh_quality.h"

#include "meshes/constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace wear::meshes {

namespace {

bool segment_hits_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                           const Vec3& c) {
  const double eps = 1e-12;
  const Vec3 d = q - p, e1 = b - a, e2 = c - a;
  const Vec3 h = cross(d, e2);
  const double det = dot(e1, h);
  const double scale = norm(d) * norm(e1) * norm(e2);
  if (std::abs(det) <= eps * scale)
    return false; // parallel or coplanar
  const double inv = 1.0 / det;
  const Vec3 s = p - a;
  const double u = dot(s, h) * inv;
  if (u <= eps || u >= 1 - eps)
    return false;
  const Vec3 qv = cross(s, e1);
  const double v = dot(d, qv) * inv;
  if (v <= eps || u + v >= 1 - eps)
    return false;
  const double t = dot(e2, qv) * inv;
  return t > eps && t < 1 - eps;
}

bool faces_intersect(const SurfaceMesh& m, std::uint32_t f, std::uint32_t g) {
  const auto& A = m.triangles[f];
  const auto& B = m.triangles[g];
  int n_shared = 0;
  for (auto a : A)
    for (auto b : B)
      n_shared += (a == b);
  if (n_shared >= 2)
    return false;
  const auto test = [&](const Triangle& s, const Triangle& t) {
    for (int k = 0; k < 3; ++k) {
      const auto i = s[k], j = s[(k + 1) % 3];
      if (n_shared == 1 && (std::find(t.begin(), t.end(), i) != t.end() ||
                            std::find(t.begin(), t.end(), j) != t.end()))
        continue;
      if (segment_hits_triangle(m.vertices[i], m.vertices[j], m.vertices[t[0]], m.vertices[t[1]],
                                m.vertices[t[2]]))
        return true;
    }
    return false;
  };
  return test(A, B) || test(B, A);
}

} // namespace

double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double l2 = norm2(b - a) + norm2(c - b) + norm2(a - c);
  return l2 > 0 ? 2 * std::sqrt(3.0) * norm(cross(b - a, c - a)) / l2 : 0;
}

double min_triangle_quality(const SurfaceMesh& m) {
  double q = std::numeric_limits<double>::infinity();
  for (const auto& t : m.triangles)
    q = std::min(q, triangle_quality(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]));
  return q;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>>
find_self_intersections(const SurfaceMesh& m, std::size_t max_pairs) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> hits;
  if (m.n_faces() < 2)
    return hits;
  double mean_edge = 0;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      mean_edge += norm(m.vertices[t[k]] - m.vertices[t[(k + 1) % 3]]);
  mean_edge /= 3.0 * m.n_faces();
  const BoundingBox box = bounding_box(m);
  const double h = std::max(2 * mean_edge, 1e-300);
  const auto cell = [&](const Vec3& p, int d) {
    return static_cast<long>(std::floor((p[d] - box.min[d]) / h));
  };
  struct Key {
    long i, j, k;
    bool operator==(const Key& o) const { return i == o.i && j == o.j && k == o.k; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k.i) * 73856093u ^ std::size_t(k.j) * 19349663u ^
             std::size_t(k.k) * 83492791u;
    }
  };
  std::vector<BoundingBox> fb(m.n_faces());
  std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> grid;
  for (std::uint32_t f = 0; f < m.n_faces(); ++f) {
    BoundingBox b{m.vertices[m.triangles[f][0]], m.vertices[m.triangles[f][0]]};
    for (auto v : m.triangles[f])
      for (int d = 0; d < 3; ++d) {
        b.min[d] = std::min(b.min[d], m.vertices[v][d]);
        b.max[d] = std::max(b.max[d], m.vertices[v][d]);
      }
    fb[f] = b;
    for (long i = cell(b.min, 0); i <= cell(b.max, 0); ++i)
      for (long j = cell(b.min, 1); j <= cell(b.max, 1); ++j)
        for (long k = cell(b.min, 2); k <= cell(b.max, 2); ++k)
          grid[{i, j, k}].push_back(f);
  }
  // Deterministic order: visit faces, then their cells.
  for (std::uint32_t f = 0; f < m.n_faces() && hits.size() < max_pairs; ++f) {
    const auto& b = fb[f];
    for (long i = cell(b.min, 0); i <= cell(b.max, 0); ++i)
      for (long j = cell(b.min, 1); j <= cell(b.max, 1); ++j)
        for (long k = cell(b.min, 2); k <= cell(b.max, 2); ++k)
          for (auto g : grid[{i, j, k}]) {
            if (g <= f || hits.size() >= max_pairs)
              continue;
            const auto& c = fb[g];
            Vec3 lo;
            bool overlap = true;
            for (int d = 0; d < 3; ++d) {
              lo[d] = std::max(b.min[d], c.min[d]);
              overlap = overlap && lo[d] <= std::min(b.max[d], c.max[d]);
            }
            if (!overlap || cell(lo, 0) != i || cell(lo, 1) != j || cell(lo, 2) != k)
              continue;
            if (faces_intersect(m, f, g))
              hits.push_back({f, g});
          }
  }
  return hits;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> find_folded_edges(const SurfaceMesh& m,
                                                                       double fold_cos) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> folds;
  for (const auto& [edge, faces] : edge_faces(m)) {
    if (faces.size() != 2)
      continue;
    const Vec3 a = face_normal_unnormalized(m, faces[0]), b = face_normal_unnormalized(m, faces[1]);
    const double na = norm(a), nb = norm(b);
    if (na > 0 && nb > 0 && dot(a, b) < fold_cos * na * nb)
      folds.emplace_back(std::uint32_t(faces[0]), std::uint32_t(faces[1]));
  }
  return folds;
}

SurfaceQuality surface_quality(const SurfaceMesh& m, const std::vector<Vec3>* reference_normals,
                               double relative_area_tolerance, double folded_edge_cos) {
  SurfaceQuality q;
  double mean_edge2 = 0;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      mean_edge2 += norm2(m.vertices[t[k]] - m.vertices[t[(k + 1) % 3]]);
  mean_edge2 /= std::max<std::size_t>(1, 3 * m.n_faces());
  const auto mark = [&](std::size_t f) {
    if (q.first_bad_face < 0)
      q.first_bad_face = long(f);
    q.bad_faces.push_back(std::uint32_t(f));
  };
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const auto& t = m.triangles[f];
    const Vec3 p[3] = {m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    double l[3];
    for (int k = 0; k < 3; ++k)
      l[k] = norm(p[(k + 1) % 3] - p[k]);
    const Vec3 n2 = face_normal_unnormalized(m, f);
    const double area = 0.5 * norm(n2);
    if (area <= relative_area_tolerance * mean_edge2) {
      ++q.n_degenerate;
      mark(f);
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
      const double c = std::clamp(dot(u, v) / (norm(u) * norm(v)), -1.0, 1.0);
      q.min_angle_deg = std::min(q.min_angle_deg, std::acos(c) * 180 / pi);
    }
    const double perimeter = l[0] + l[1] + l[2];
    const double r_in = 2 * area / perimeter;
    q.max_aspect_ratio =
        std::max(q.max_aspect_ratio, std::max({l[0], l[1], l[2]}) / (2 * std::sqrt(3.0) * r_in));
    if (reference_normals && dot(n2, (*reference_normals)[f]) <= 0) {
      ++q.n_inverted;
      mark(f);
    }
  }
  const auto folds = find_folded_edges(m, folded_edge_cos);
  q.n_folded_edges = folds.size();
  for (const auto& [i, j] : folds) {
    mark(i);
    mark(j);
  }
  const auto hits = find_self_intersections(m);
  q.n_self_intersections = hits.size();
  for (const auto& [i, j] : hits) {
    mark(i);
    mark(j);
  }
  return q;
}

} // namespace wear::meshes

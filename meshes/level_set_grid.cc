// A part as an implicit function on a uniform grid (docs/theory.md, "Wear to the end").
//
// Signed distance: the unsigned distance to the nearest triangle is exact within a band of
// the surface (every face visits the nodes of its bounding box grown by the band); its sign
// comes from the parity of the crossings of a vertical ray per grid column, the ray moved by
// 1e-7 spacing off the column so that it misses the edges and vertices of grid-aligned faces.
// Receding front: the material a surface removes when it recedes by a depth d(y) along its
// normals, with crests receding rather than folding, is the union of the balls of radius d(y)
// about its points y (the Hopf-Lax solution of phi_t = d |grad phi| with characteristics from
// the surface). g(x) = min_f (|x - y_f| - d(y_f)), y_f the point of face f closest to x and d
// linear over f from its vertices, is negative on the union of the balls about those closest
// points: the exact union for a uniform depth, and to second order in the depth's gradient
// otherwise, always a union of balls, so it cannot fold.
// Interpolant: each cubic cell is cut into six tetrahedra along its main diagonal (Kuhn), the
// same diagonal on every shared face, and the node values are interpolated linearly on each.
// The volume of {f < 0} in a tetrahedron has a closed form; the zero set in a tetrahedron is
// one triangle or one planar quadrilateral, so the zero surface of the whole grid is closed
// and manifold where no node value is zero (level_value keeps them off zero).
#include "meshes/level_set_grid.h"

#include "meshes/triangle_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace wear::meshes {

const int kuhn_tetrahedra[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                   {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

LevelSetGrid::LevelSetGrid(const BoundingBox& box, double spacing, double margin,
                           std::size_t max_nodes)
    : h_(spacing) {
  if (!(spacing > 0) || !std::isfinite(spacing))
    throw std::invalid_argument("level set grid: the spacing must be positive, got " +
                                std::to_string(spacing));
  double count = 1;
  for (int d = 0; d < 3; ++d) {
    const double lo = box.min[d] - margin, hi = box.max[d] + margin;
    if (!(hi >= lo) || !std::isfinite(lo) || !std::isfinite(hi))
      throw std::invalid_argument("level set grid: an empty or infinite box");
    // An odd fraction of a spacing off the box, so that a face of the box falls between
    // nodes (a node on a face would sit at a zero crossing).
    origin_[d] = lo - 0.377 * spacing;
    const double cells = std::ceil((hi - origin_[d]) / spacing) + 1;
    count *= cells + 1;
    if (count > double(max_nodes))
      throw std::invalid_argument("level set grid: a spacing of " + std::to_string(spacing * 1e3) +
                                  " mm over a box of " + std::to_string((hi - lo) * 1e3) +
                                  " mm would need more than " + std::to_string(max_nodes) +
                                  " nodes; choose a coarser spacing");
    n_[d] = int(cells) + 1;
  }
  value.assign(n_nodes(), 0.0);
}

Vec3 LevelSetGrid::node(std::size_t index) const {
  const std::size_t i = index % n_[0], jk = index / n_[0];
  return node(int(i), int(jk % n_[1]), int(jk / n_[1]));
}

void LevelSetGrid::node_range(const Vec3& lo, const Vec3& hi, int first[3], int last[3]) const {
  for (int d = 0; d < 3; ++d) {
    first[d] = std::max(0, int(std::ceil((lo[d] - origin_[d]) / h_)));
    last[d] = std::min(n_[d] - 1, int(std::floor((hi[d] - origin_[d]) / h_)));
  }
}

namespace {

// Calls visit(node index, node position) for the nodes within the bounding box of face f grown
// by `reach` whose k lies in [k_begin, k_end).
template <typename Visit>
void visit_face_nodes(const SurfaceMesh& s, std::size_t f, double reach, const LevelSetGrid& grid,
                      int k_begin, int k_end, Visit&& visit) {
  const auto& t = s.triangles[f];
  const Vec3 a = s.vertices[t[0]], b = s.vertices[t[1]], c = s.vertices[t[2]];
  Vec3 lo, hi;
  for (int d = 0; d < 3; ++d) {
    lo[d] = std::min({a[d], b[d], c[d]}) - reach;
    hi[d] = std::max({a[d], b[d], c[d]}) + reach;
  }
  int first[3], last[3];
  grid.node_range(lo, hi, first, last);
  first[2] = std::max(first[2], k_begin);
  last[2] = std::min(last[2], k_end - 1);
  for (int k = first[2]; k <= last[2]; ++k)
    for (int j = first[1]; j <= last[1]; ++j)
      for (int i = first[0]; i <= last[0]; ++i) {
        const Vec3 p = grid.node(i, j, k);
        visit(grid.index(i, j, k), p);
      }
}

// Runs body(k_begin, k_end) on disjoint slabs of the grid's z layers, one per thread, so that
// the nodes a thread writes are its own.
template <typename Body>
void for_each_slab(const LevelSetGrid& grid, Body&& body) {
  const int nz = grid.n(2);
#pragma omp parallel
  {
#ifdef _OPENMP
    const int n_threads = omp_get_num_threads(), id = omp_get_thread_num();
#else
    const int n_threads = 1, id = 0;
#endif
    body(int(std::int64_t(nz) * id / n_threads), int(std::int64_t(nz) * (id + 1) / n_threads));
  }
}

// Twice the signed area of (a, b, p) projected on the xy plane.
double orient_xy(const Vec3& a, const Vec3& b, double px, double py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

// Per grid column (i, j), the heights where a vertical line just off the column crosses the
// surface, sorted (CSR: offsets per column).
void column_crossings(const SurfaceMesh& s, const LevelSetGrid& grid,
                      std::vector<std::size_t>& offsets, std::vector<double>& heights) {
  const std::size_t n_columns = std::size_t(grid.n(0)) * grid.n(1);
  const double dx = 1.234567e-7 * grid.spacing(), dy = 2.718281e-7 * grid.spacing();
  offsets.assign(n_columns + 1, 0);
  heights.clear();
  // Two passes over the faces: count, then fill.
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::size_t> fill;
    if (pass == 1) {
      for (std::size_t c = 0; c < n_columns; ++c)
        offsets[c + 1] += offsets[c];
      heights.resize(offsets.back());
      fill.assign(offsets.begin(), offsets.end() - 1);
    }
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
      const auto& t = s.triangles[f];
      const Vec3 a = s.vertices[t[0]], b = s.vertices[t[1]], c = s.vertices[t[2]];
      const Vec3 lo{std::min({a.x, b.x, c.x}) - dx, std::min({a.y, b.y, c.y}) - dy, 0};
      const Vec3 hi{std::max({a.x, b.x, c.x}) - dx, std::max({a.y, b.y, c.y}) - dy, 0};
      int first[3], last[3];
      grid.node_range(lo, hi, first, last);
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i) {
          const Vec3 p = grid.node(i, j, 0);
          const double px = p.x + dx, py = p.y + dy;
          const double w0 = orient_xy(b, c, px, py), w1 = orient_xy(c, a, px, py),
                       w2 = orient_xy(a, b, px, py);
          if (!((w0 > 0 && w1 > 0 && w2 > 0) || (w0 < 0 && w1 < 0 && w2 < 0)))
            continue;
          const std::size_t col = std::size_t(i) + std::size_t(grid.n(0)) * j;
          if (pass == 0)
            ++offsets[col + 1];
          else
            heights[fill[col]++] = (w0 * a.z + w1 * b.z + w2 * c.z) / (w0 + w1 + w2);
        }
    }
  }
  for (std::size_t c = 0; c < n_columns; ++c)
    std::sort(heights.begin() + std::ptrdiff_t(offsets[c]),
              heights.begin() + std::ptrdiff_t(offsets[c + 1]));
}

} // namespace

void signed_distance(const SurfaceMesh& s, LevelSetGrid& grid, double band) {
  std::fill(grid.value.begin(), grid.value.end(), band);
  for_each_slab(grid, [&](int k0, int k1) {
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
      const auto& t = s.triangles[f];
      const Vec3 a = s.vertices[t[0]], b = s.vertices[t[1]], c = s.vertices[t[2]];
      visit_face_nodes(s, f, band, grid, k0, k1, [&](std::size_t n, const Vec3& p) {
        grid.value[n] =
            std::min(grid.value[n], norm(p - closest_point_on_triangle(a, b, c, p).point));
      });
    }
  });
  std::vector<std::size_t> offsets;
  std::vector<double> heights;
  column_crossings(s, grid, offsets, heights);
  for (int j = 0; j < grid.n(1); ++j)
    for (int i = 0; i < grid.n(0); ++i) {
      const std::size_t col = std::size_t(i) + std::size_t(grid.n(0)) * j;
      std::size_t below = offsets[col];
      for (int k = 0; k < grid.n(2); ++k) {
        const double z = grid.node(i, j, k).z;
        while (below < offsets[col + 1] && heights[below] < z)
          ++below;
        if ((below - offsets[col]) % 2 == 1)
          grid.value[grid.index(i, j, k)] *= -1;
      }
    }
}

namespace {
// The point of triangle abc closest to x and its barycentric weights.
struct Closest {
  Vec3 point;
  double w[3];
};
Closest closest_with_weights(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) {
  Closest out;
  out.point = closest_point_on_triangle(a, b, c, x).point;
  const Vec3 e0 = b - a, e1 = c - a, ep = out.point - a;
  const double d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1), d20 = dot(ep, e0),
               d21 = dot(ep, e1), det = d00 * d11 - d01 * d01;
  const double v = det > 0 ? (d11 * d20 - d01 * d21) / det : 0,
               w = det > 0 ? (d00 * d21 - d01 * d20) / det : 0;
  out.w[0] = 1 - v - w, out.w[1] = v, out.w[2] = w;
  return out;
}

// The distance from x to face f and the front's value there (front_value).
struct FrontPoint {
  double distance, value;
};
// The point of face f closest to x, with its barycentric weights.
Closest closest_on_face(const SurfaceMesh& s, std::size_t f, const Vec3& x) {
  const auto& t = s.triangles[f];
  return closest_with_weights(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]], x);
}

// A per-vertex value (a depth, a normal) of face f interpolated at the closest point c.
template <class T>
T at_closest(const SurfaceMesh& s, std::size_t f, const Closest& c, const std::vector<T>& value) {
  const auto& t = s.triangles[f];
  return value[t[0]] * c.w[0] + value[t[1]] * c.w[1] + value[t[2]] * c.w[2];
}

FrontPoint front_point(const SurfaceMesh& s, const std::vector<double>& vertex_depth, std::size_t f,
                       const Vec3& x) {
  const Closest c = closest_on_face(s, f, x);
  const double d = norm(x - c.point);
  return {d, d - at_closest(s, f, c, vertex_depth)};
}
} // namespace

double front_value(const SurfaceMesh& s, const std::vector<double>& vertex_depth, std::size_t f,
                   const Vec3& x) {
  return front_point(s, vertex_depth, f, x).value;
}

Vec3 inward_front_point(const SurfaceMesh& s, const std::vector<double>& vertex_depth,
                        const std::vector<Vec3>& vertex_normal, std::size_t f, const Vec3& x) {
  const Closest c = closest_on_face(s, f, x);
  const Vec3 n = at_closest(s, f, c, vertex_normal);
  const double depth = at_closest(s, f, c, vertex_depth);
  const Vec3 r = x - c.point;
  const double distance = norm(r);
  // Nearer to y than a millionth of its depth: x lies on the old surface, and the front
  // stands under it along the old normal.
  if (!(distance > 1e-6 * depth)) {
    const double length = norm(n);
    return length > 0 ? c.point - n * (depth / length) : c.point;
  }
  const double side = dot(r, n) > 0 ? -1.0 : 1.0; // outside: turned into the part
  return c.point + r * (side * depth / distance);
}

FrontSample front_at(const SurfaceMesh& s, const std::vector<double>& vertex_depth,
                     const LevelSetGrid& grid, const std::vector<std::int32_t>& source,
                     const Vec3& x) {
  const double h = grid.spacing();
  int cell[3];
  for (int d = 0; d < 3; ++d)
    cell[d] = std::clamp(int(std::floor((x[d] - grid.origin()[d]) / h)), 0, grid.n(d) - 2);
  FrontSample best{std::numeric_limits<double>::infinity(), -1};
  for (int corner = 0; corner < 8; ++corner) {
    const auto f = source[grid.index(cell[0] + (corner & 1), cell[1] + ((corner >> 1) & 1),
                                     cell[2] + ((corner >> 2) & 1))];
    if (f < 0)
      continue;
    const double g = front_value(s, vertex_depth, std::size_t(f), x);
    if (g < best.value)
      best = {g, f};
  }
  return best;
}

void receding_front(const SurfaceMesh& s, const std::vector<double>& vertex_depth,
                    const std::vector<char>& receding, LevelSetGrid& grid, double band,
                    std::vector<std::int32_t>& source, std::vector<std::int32_t>& owner) {
  if (vertex_depth.size() != s.n_vertices() || receding.size() != s.n_faces())
    throw std::invalid_argument("receding front: depths or flags of the wrong size");
  std::fill(grid.value.begin(), grid.value.end(), band);
  source.assign(grid.n_nodes(), -1);
  owner.assign(grid.n_nodes(), -1);
  std::vector<double> nearest(grid.n_nodes(), std::numeric_limits<double>::infinity());
  for_each_slab(grid, [&](int k0, int k1) {
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
      if (!receding[f])
        continue;
      const auto& t = s.triangles[f];
      const double reach =
          std::max({vertex_depth[t[0]], vertex_depth[t[1]], vertex_depth[t[2]]}) + band;
      visit_face_nodes(s, f, reach, grid, k0, k1, [&](std::size_t n, const Vec3& p) {
        const FrontPoint q = front_point(s, vertex_depth, f, p);
        if (q.value < grid.value[n]) {
          grid.value[n] = q.value;
          source[n] = std::int32_t(f);
        }
        if (q.distance < nearest[n]) {
          nearest[n] = q.distance;
          owner[n] = std::int32_t(f);
        }
      });
    }
  });
}

double tetrahedron_negative_volume(const Vec3 corners[4], const double values[4]) {
  const auto tet = [](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return std::abs(dot(b - a, cross(c - a, d - a))) / 6;
  };
  int neg[4], pos[4], n_neg = 0, n_pos = 0;
  for (int v = 0; v < 4; ++v)
    (values[v] < 0 ? neg[n_neg++] : pos[n_pos++]) = v;
  if (n_neg == 0)
    return 0;
  const double whole = tet(corners[0], corners[1], corners[2], corners[3]);
  if (n_neg == 4)
    return whole;
  const auto corner_fraction = [&](int apex, const int* others) {
    const double va = values[apex];
    return va * va * va /
           ((va - values[others[0]]) * (va - values[others[1]]) * (va - values[others[2]]));
  };
  if (n_neg == 1)
    return whole * corner_fraction(neg[0], pos);
  if (n_neg == 3)
    return whole * (1 - corner_fraction(pos[0], neg));
  // Two and two: the convex hull of a, b and the crossings P (a-c), Q (a-d), R (b-c), S (b-d),
  // fanned from a over the faces that do not hold it.
  const auto cut = [&](int u, int w) {
    const double t = values[u] / (values[u] - values[w]);
    return corners[u] + (corners[w] - corners[u]) * t;
  };
  const int a = neg[0], b = neg[1], c = pos[0], d = pos[1];
  const Vec3 P = cut(a, c), Q = cut(a, d), R = cut(b, c), S = cut(b, d);
  const Vec3 A = corners[a], B = corners[b];
  return tet(A, B, R, S) + tet(A, P, R, S) + tet(A, P, S, Q);
}

namespace {
// Calls visit(corners, values, node indices, corner offset bits) for every tetrahedron of the
// cells of layer k.
template <typename Visit>
void for_each_tetrahedron(const LevelSetGrid& grid, int k, Visit&& visit) {
  const double h = grid.spacing();
  for (int j = 0; j + 1 < grid.n(1); ++j)
    for (int i = 0; i + 1 < grid.n(0); ++i) {
      std::size_t node[8];
      double value[8];
      for (int c = 0; c < 8; ++c) {
        node[c] = grid.index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        value[c] = level_value(grid.value[node[c]], h);
      }
      const Vec3 o = grid.node(i, j, k);
      for (const auto& t : kuhn_tetrahedra) {
        Vec3 x[4];
        double v[4];
        std::size_t n[4];
        for (int m = 0; m < 4; ++m) {
          const int c = t[m];
          x[m] = o + Vec3(h * (c & 1), h * ((c >> 1) & 1), h * ((c >> 2) & 1));
          v[m] = value[c];
          n[m] = node[c];
        }
        visit(x, v, n, t);
      }
    }
}
} // namespace

double negative_volume(const LevelSetGrid& grid) {
  double total = 0;
#pragma omp parallel for reduction(+ : total) schedule(static)
  for (int k = 0; k < grid.n(2) - 1; ++k)
    for_each_tetrahedron(grid, k,
                         [&](const Vec3* x, const double* v, const std::size_t*, const int*) {
                           total += tetrahedron_negative_volume(x, v);
                         });
  return total;
}

SurfaceMesh zero_surface(const LevelSetGrid& grid) {
  SurfaceMesh out;
  // The corners of a Kuhn tetrahedron are nested (each one's offset bits hold the previous
  // one's), so every edge runs from a lower node to a higher one: it is keyed by the lower
  // node and the offset bits between them (1 ... 7), the same in every cell that shares it.
  std::unordered_map<std::uint64_t, std::uint32_t> vertex_of_edge;
  vertex_of_edge.reserve(grid.n_nodes() / 8);
  const auto vertex = [&](const Vec3* x, const double* v, const std::size_t* n, const int* code,
                          int lo, int hi) {
    if (code[hi] < code[lo])
      std::swap(lo, hi);
    const std::uint64_t key = std::uint64_t(n[lo]) * 8 + std::uint64_t(code[hi] ^ code[lo]);
    const auto [it, added] = vertex_of_edge.try_emplace(key, std::uint32_t(out.vertices.size()));
    if (added) {
      const double t = v[lo] / (v[lo] - v[hi]);
      out.vertices.push_back(x[lo] + (x[hi] - x[lo]) * t);
    }
    return it->second;
  };
  // A triangle of the zero set, turned so that its normal points from node `in` (negative) to
  // node `out_node` (positive).
  const auto add = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r, const Vec3& in,
                       const Vec3& out_node) {
    const Vec3 normal = cross(out.vertices[q] - out.vertices[p], out.vertices[r] - out.vertices[p]);
    if (dot(normal, out_node - in) < 0)
      std::swap(q, r);
    out.triangles.push_back({p, q, r});
  };
  for (int k = 0; k + 1 < grid.n(2); ++k)
    for_each_tetrahedron(
        grid, k, [&](const Vec3* x, const double* v, const std::size_t* n, const int* code) {
          int neg[4], pos[4], n_neg = 0, n_pos = 0;
          for (int m = 0; m < 4; ++m)
            (v[m] < 0 ? neg[n_neg++] : pos[n_pos++]) = m;
          if (n_neg == 0 || n_neg == 4)
            return;
          const auto at = [&](int a, int b) { return vertex(x, v, n, code, a, b); };
          if (n_neg == 1) {
            const int a = neg[0];
            add(at(a, pos[0]), at(a, pos[1]), at(a, pos[2]), x[a], x[pos[0]]);
          } else if (n_neg == 3) {
            const int d = pos[0];
            add(at(neg[0], d), at(neg[1], d), at(neg[2], d), x[neg[0]], x[d]);
          } else {
            const int a = neg[0], b = neg[1], c = pos[0], d = pos[1];
            // The quadrilateral P (a-c), Q (a-d), S (b-d), R (b-c).
            const auto P = at(a, c), Q = at(a, d), S = at(b, d), R = at(b, c);
            add(P, Q, S, x[a], x[c]);
            add(P, S, R, x[a], x[c]);
          }
        });
  out.face_labels.assign(out.triangles.size(), label::unlabelled);
  return out;
}

} // namespace wear::meshes

// Coarsening a fine triangle surface by half-edge collapses (Garland and Heckbert 1997,
// "Surface simplification using quadric error metrics", with the vertex kept in place).
//
// Every input face adds its plane (n . x + d = 0, unit n) to the quadric of its three
// vertices, Q(x) = sum (n . x + d)^2, and every edge between two labels adds the plane through
// it perpendicular to its faces, so that a boundary vertex is held near its boundary curve. A
// collapse u -> v removes u, hands its faces to v and adds Q_u to Q_v; its cost is the mean
// squared distance of v to the planes now in Q_v, and collapses are taken cheapest first
// while that stays below max_error^2. The vertex is not moved, so a region of one plane
// stays in that plane exactly. A collapse is refused when it would break the closed manifold
// (the link condition: u and v share exactly the two vertices opposite their edge), turn a
// face over or by more than the normal limit, leave a face worse than the quality limit (unless
// better than the worst it replaces) or an edge longer than max_edge, remove a vertex where
// three labels meet or a boundary turns, or move a boundary vertex off its boundary. Rounds
// of collapses alternate with Delaunay flips of edges between faces within 0.5 deg of one
// plane (meshes/planar_flip.h), which move the surface by less than the error limit.
#include "meshes/surface_decimation.h"

#include "meshes/mesh_quality.h"

#include "meshes/planar_flip.h"
#include "meshes/stopwatch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <stdexcept>

namespace wear::meshes {

namespace {

struct Quadric {
  std::array<double, 10> q{}; // xx xy xz yy yz zz  x y z  c
  double n_planes = 0;
  void add_plane(const Vec3& n, double d) {
    q[0] += n.x * n.x, q[1] += n.x * n.y, q[2] += n.x * n.z;
    q[3] += n.y * n.y, q[4] += n.y * n.z, q[5] += n.z * n.z;
    q[6] += d * n.x, q[7] += d * n.y, q[8] += d * n.z, q[9] += d * d;
    n_planes += 1;
  }
  void add(const Quadric& o) {
    for (int i = 0; i < 10; ++i)
      q[i] += o.q[i];
    n_planes += o.n_planes;
  }
  double eval(const Vec3& x) const {
    return q[0] * x.x * x.x + 2 * q[1] * x.x * x.y + 2 * q[2] * x.x * x.z + q[3] * x.y * x.y +
           2 * q[4] * x.y * x.z + q[5] * x.z * x.z + 2 * (q[6] * x.x + q[7] * x.y + q[8] * x.z) +
           q[9];
  }
};

struct Candidate {
  double cost; // order: relative error plus relative squared length
  std::uint32_t u, v, stamp_u, stamp_v;
  bool operator<(const Candidate& o) const { return cost > o.cost; } // cheapest on top
};

class Decimator {
public:
  Decimator(SurfaceMesh& m, const DecimationParameters& p) : m_(m), p_(p) {
    faces_of_.resize(m.n_vertices());
    for (std::uint32_t f = 0; f < m.n_faces(); ++f)
      for (const auto v : m.triangles[f])
        faces_of_[v].push_back(f);
    alive_face_.assign(m.n_faces(), 1);
    stamp_.assign(m.n_vertices(), 0);
    quadric_.resize(m.n_vertices());
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
      const Vec3 n = normalized(face_normal_unnormalized(m, f));
      const double d = -dot(n, m.vertices[m.triangles[f][0]]);
      for (const auto v : m.triangles[f])
        quadric_[v].add_plane(n, d);
    }
    for (const auto& [edge, faces] : edge_faces(m)) {
      if (faces.size() != 2 || m.face_labels[faces[0]] == m.face_labels[faces[1]])
        continue;
      const Vec3 a = m.vertices[edge.first], b = m.vertices[edge.second];
      const Vec3 along =
          face_normal_unnormalized(m, faces[0]) + face_normal_unnormalized(m, faces[1]);
      const Vec3 n = normalized(cross(b - a, normalized(along)));
      for (const auto v : {edge.first, edge.second})
        quadric_[v].add_plane(n, -dot(n, a));
    }
  }

  DecimationReport run() {
    DecimationReport r;
    r.n_faces_before = m_.n_faces();
    for (std::uint32_t f = 0; f < m_.n_faces(); ++f)
      for (int k = 0; k < 3; ++k) {
        push(m_.triangles[f][k], m_.triangles[f][(k + 1) % 3]);
        push(m_.triangles[f][(k + 1) % 3], m_.triangles[f][k]);
      }
    while (!queue_.empty()) {
      const Candidate c = queue_.top();
      queue_.pop();
      if (stamp_[c.u] != c.stamp_u || stamp_[c.v] != c.stamp_v || faces_of_[c.u].empty())
        continue;
      if (!collapsible(c.u, c.v))
        continue;
      collapse(c.u, c.v);
      ++r.n_collapses;
    }
    compact();
    r.n_faces_after = m_.n_faces();
    return r;
  }

private:
  SurfaceMesh& m_;
  const DecimationParameters& p_;
  std::vector<std::vector<std::uint32_t>> faces_of_;
  std::vector<char> alive_face_;
  std::vector<std::uint32_t> stamp_;
  std::vector<Quadric> quadric_;
  std::priority_queue<Candidate> queue_;
  std::vector<std::uint32_t> scratch_a_, scratch_b_;

  double cost(std::uint32_t u, std::uint32_t v) const {
    Quadric q = quadric_[u];
    q.add(quadric_[v]);
    return std::max(0.0, q.eval(m_.vertices[v])) / q.n_planes;
  }
  // Collapses are taken in the order of their error relative to the limit plus their edge's
  // length relative to the longest: among the many of no error (a plane), short edges go
  // first, so the vertices thin out evenly instead of leaving clusters no collapse can clear.
  void push(std::uint32_t u, std::uint32_t v) {
    const double c = cost(u, v), limit = p_.max_error * p_.max_error;
    if (c <= limit)
      queue_.push({c / limit + norm2(m_.vertices[u] - m_.vertices[v]) / (p_.max_edge * p_.max_edge),
                   u, v, stamp_[u], stamp_[v]});
  }
  void neighbours(std::uint32_t u, std::vector<std::uint32_t>& out) const {
    out.clear();
    for (const auto f : faces_of_[u])
      for (const auto w : m_.triangles[f])
        if (w != u)
          out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
  // The faces holding both a and b.
  int shared_faces(std::uint32_t a, std::uint32_t b, std::uint32_t out[2]) const {
    int n = 0;
    for (const auto f : faces_of_[a]) {
      const auto& t = m_.triangles[f];
      if (t[0] == b || t[1] == b || t[2] == b) {
        if (n < 2)
          out[n] = f;
        ++n;
      }
    }
    return n;
  }
  bool boundary_edge(std::uint32_t a, std::uint32_t b) const {
    std::uint32_t f[2];
    return shared_faces(a, b, f) == 2 && m_.face_labels[f[0]] != m_.face_labels[f[1]];
  }
  // 0: inside one label; 1: on a boundary curve that runs straight through (two boundary
  // edges, two labels); 2: anything else (kept).
  int kind(std::uint32_t u) {
    const int label = m_.face_labels[faces_of_[u][0]];
    bool one_label = true;
    for (const auto f : faces_of_[u])
      one_label &= m_.face_labels[f] == label;
    if (one_label)
      return 0;
    neighbours(u, scratch_b_);
    int n_boundary = 0;
    for (const auto w : scratch_b_)
      n_boundary += boundary_edge(u, w);
    std::vector<int> labels;
    for (const auto f : faces_of_[u])
      labels.push_back(m_.face_labels[f]);
    std::sort(labels.begin(), labels.end());
    return n_boundary == 2 && std::unique(labels.begin(), labels.end()) - labels.begin() == 2 ? 1
                                                                                              : 2;
  }

  bool collapsible(std::uint32_t u, std::uint32_t v) {
    const int k = kind(u);
    if (k == 2 || (k == 1 && !boundary_edge(u, v)))
      return false;
    std::uint32_t across[2];
    if (shared_faces(u, v, across) != 2)
      return false;
    // Link condition.
    neighbours(u, scratch_a_);
    neighbours(v, scratch_b_);
    std::size_t n_common = 0;
    for (std::size_t i = 0, j = 0; i < scratch_a_.size() && j < scratch_b_.size();) {
      if (scratch_a_[i] < scratch_b_[j])
        ++i;
      else if (scratch_b_[j] < scratch_a_[i])
        ++j;
      else
        ++n_common, ++i, ++j;
    }
    if (n_common != 2)
      return false;
    const Vec3 x = m_.vertices[v];
    for (const auto w : scratch_a_)
      if (w != v && norm(m_.vertices[w] - x) > p_.max_edge)
        return false;
    Vec3 around;
    double worst_old = 1;
    for (const auto f : faces_of_[u]) {
      const auto& t = m_.triangles[f];
      around += face_normal_unnormalized(m_, f);
      worst_old = std::min(
          worst_old, triangle_quality(m_.vertices[t[0]], m_.vertices[t[1]], m_.vertices[t[2]]));
    }
    around = normalized(around);
    for (const auto f : faces_of_[u]) {
      const auto& t = m_.triangles[f];
      if (t[0] == v || t[1] == v || t[2] == v)
        continue;
      Vec3 p[3];
      for (int i = 0; i < 3; ++i)
        p[i] = t[i] == u ? x : m_.vertices[t[i]];
      const Vec3 n_new = cross(p[1] - p[0], p[2] - p[0]);
      if (!(norm(n_new) > 0))
        return false;
      const Vec3 n_old = face_normal_unnormalized(m_, f);
      const double q_old =
          triangle_quality(m_.vertices[t[0]], m_.vertices[t[1]], m_.vertices[t[2]]);
      // A sliver's own normal says little; it is held to the normal around u instead.
      const Vec3 reference = q_old >= p_.min_quality ? normalized(n_old) : around;
      if (dot(normalized(n_new), reference) < p_.min_normal_cos)
        return false;
      const double q_new = triangle_quality(p[0], p[1], p[2]);
      if (q_new < p_.min_quality && q_new <= worst_old)
        return false;
    }
    return cost(u, v) <= p_.max_error * p_.max_error;
  }

  void collapse(std::uint32_t u, std::uint32_t v) {
    for (const auto f : faces_of_[u]) {
      auto& t = m_.triangles[f];
      if (t[0] == v || t[1] == v || t[2] == v) {
        alive_face_[f] = 0;
        for (const auto w : t)
          if (w != u) {
            auto& list = faces_of_[w];
            list.erase(std::find(list.begin(), list.end(), f));
          }
        continue;
      }
      for (auto& w : t)
        if (w == u)
          w = v;
      faces_of_[v].push_back(f);
    }
    faces_of_[u].clear();
    quadric_[v].add(quadric_[u]);
    neighbours(v, scratch_a_);
    ++stamp_[v];
    for (const auto w : scratch_a_)
      ++stamp_[w];
    for (const auto w : scratch_a_) {
      push(v, w);
      push(w, v);
    }
  }

  void compact() {
    keep_faces(m_, alive_face_);
    m_.bump_revision();
  }
};

} // namespace

DecimationParameters flat_region_coarsening(double max_edge, double max_error) {
  DecimationParameters p;
  p.max_edge = max_edge;
  p.max_error = max_error;
  p.min_quality = 0.3;
  return p;
}

DecimationReport
coarsen_flat_regions(SurfaceMesh& m,
                     const std::vector<std::pair<std::uint32_t, std::uint32_t>>& curves,
                     double max_edge, double max_error) {
  // Regions: faces joined across edges that are neither label boundaries nor curves; each
  // becomes a label of its own for the decimation, which keeps label boundaries (a boundary
  // vertex moves only along its boundary, a corner never).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cut(curves);
  for (auto& e : cut)
    e = std::minmax(e.first, e.second);
  std::sort(cut.begin(), cut.end());
  const auto patch = face_patches(m, [&](std::uint32_t f, std::uint32_t g, const auto& edge) {
    return m.face_labels[f] == m.face_labels[g] &&
           !std::binary_search(cut.begin(), cut.end(), edge);
  });
  // Dense region ids in the order of the regions' first faces.
  std::vector<int> region(m.n_faces()), id_of_patch(m.n_faces(), -1), label_of_region;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    int& id = id_of_patch[std::size_t(patch[f])];
    if (id < 0) {
      id = int(label_of_region.size());
      label_of_region.push_back(m.face_labels[f]);
    }
    region[f] = id;
  }
  m.face_labels = region;
  const DecimationReport r = decimate(m, flat_region_coarsening(max_edge, max_error));
  for (auto& l : m.face_labels)
    l = label_of_region[std::size_t(l)];
  return r;
}

DecimationReport decimate(SurfaceMesh& m, const DecimationParameters& p) {
  const Stopwatch clock;
  if (!(p.max_error > 0) || !(p.max_edge > 0) || !(p.min_normal_cos > -1 && p.min_normal_cos < 1) ||
      !(p.min_quality >= 0 && p.min_quality < 1))
    throw std::invalid_argument("surface decimation: an error, edge, normal or quality limit "
                                "out of range");
  // Half-edge collapses alone stall where the kept vertices leave only collapses that would
  // make a bad face; Delaunay flips in the flat regions between rounds open them again
  // (a cube's zero set: 42,480 faces, 12,988 after one round, 1,848 after four).
  DecimationReport r;
  r.n_faces_before = m.n_faces();
  for (int round = 0; round < 6; ++round) {
    const DecimationReport once = Decimator(m, p).run();
    r.n_collapses += once.n_collapses;
    if (once.n_collapses < once.n_faces_before / 20)
      break;
    flip_flat_edges(m, 0.5);
  }
  r.n_faces_after = m.n_faces();
  r.seconds = clock.seconds();
  return r;
}

} // namespace wear::meshes

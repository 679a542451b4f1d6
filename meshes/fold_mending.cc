// Local mending of folded edges of a closed triangle surface.
//
// An edge folds when its two faces' unit normals n_f, n_g have n_f . n_g < fold_cos: the
// surface turns back on itself there, and no volume mesher accepts it. The remesher makes
// such edges where a vertex of valence 3 sits beside a nearly straight boundary between two
// labels (the foot of a worn element, the rim of a worn top against a side): its three faces
// span a link triangle of almost no width, and one of them must turn over.
//
// Three local operations mend them, each keeping the closed, oriented surface and its labels:
// - the flip of an edge (a, b) between f = (a, b, c) and g = (b, a, d), both of one label, to
//   (a, d, c) and (d, b, c); the surface moves by the distance between the lines ab and cd,
//   6 V / |(b - a) x (d - c)| with V the volume of the tetrahedron a b c d;
// - the collapse of a vertex v, whose faces all have one label, into a neighbour u: the two
//   faces on the edge uv go, v is replaced by u in the others. It is allowed when the common
//   neighbours of u and v are exactly the two vertices opposite uv (the link condition: the
//   surface stays a manifold); the surface moves by the distance of v from its new faces;
// - the move of such a vertex a quarter, half, three quarters or all the way to the centroid
//   of its neighbours; the surface moves by at most the length of the move.
// Each candidate is judged on the faces it makes: none degenerate (quality below 1e-3), the
// cosine across each of their edges above fold_cos, and the shift within max_shift. Of the
// admissible candidates the one with the largest smallest cosine plus worst quality is taken.
// The candidates of one pass touch disjoint vertex rings, so each is judged on a surface its
// predecessors in the pass did not change; the passes repeat while folds are left and mended.
#include "meshes/fold_mending.h"

#include "meshes/mesh_quality.h"
#include "meshes/triangle_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace wear::meshes {

namespace {

double cosine(const Vec3& a, const Vec3& b) {
  const double na = norm(a), nb = norm(b);
  return na > 0 && nb > 0 ? dot(a, b) / (na * nb) : -1.0;
}

// The surface being mended: faces are marked dead rather than erased, new ones appended, so
// that face and vertex indices hold during a pass.
struct Work {
  SurfaceMesh& m;
  std::vector<char> dead;
  std::vector<std::vector<std::uint32_t>> faces_of; ///< live faces per vertex, per pass
  Vec3 normal(const Triangle& t) const {
    return cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
  }
  void index() {
    faces_of.assign(m.n_vertices(), {});
    for (std::uint32_t f = 0; f < m.n_faces(); ++f)
      if (!dead[f])
        for (const auto v : m.triangles[f])
          faces_of[v].push_back(f);
  }
  // The live face other than `skip` that holds the edge b -> a (across a -> b), or -1.
  long across(std::uint32_t a, std::uint32_t b, std::uint32_t skip) const {
    for (const auto f : faces_of[a]) {
      if (f == skip)
        continue;
      const auto& t = m.triangles[f];
      for (int k = 0; k < 3; ++k)
        if (t[k] == b && t[(k + 1) % 3] == a)
          return long(f);
    }
    return -1;
  }
  std::set<std::uint32_t> neighbours(std::uint32_t v) const {
    std::set<std::uint32_t> n;
    for (const auto f : faces_of[v])
      for (const auto w : m.triangles[f])
        if (w != v)
          n.insert(w);
    return n;
  }
};

// A change of the surface: faces removed and faces added (with their labels); a move also
// puts `vertex` at `to`, a collapse removes `vertex` into `into`.
struct Candidate {
  enum class Kind { flip, collapse, move } kind = Kind::flip;
  std::vector<std::uint32_t> removed;
  std::vector<Triangle> added;
  std::vector<int> labels;
  double shift = 0;
  std::uint32_t vertex = 0, into = 0;
  Vec3 to{};
  double min_cos = -1, min_quality = 0;
  Vec3 position(const SurfaceMesh& m, std::uint32_t v) const {
    return kind == Kind::move && v == vertex ? to : m.vertices[v];
  }
  Vec3 normal(const SurfaceMesh& m, const Triangle& t) const {
    const Vec3 a = position(m, t[0]);
    return cross(position(m, t[1]) - a, position(m, t[2]) - a);
  }
};

// The smallest cosine across the edges of the added faces, and their worst quality.
void judge(const Work& w, Candidate& c) {
  c.min_cos = 1;
  c.min_quality = 1;
  for (std::size_t i = 0; i < c.added.size(); ++i) {
    const auto& t = c.added[i];
    const Vec3 n = c.normal(w.m, t);
    c.min_quality =
        std::min(c.min_quality, triangle_quality(c.position(w.m, t[0]), c.position(w.m, t[1]),
                                                 c.position(w.m, t[2])));
    for (int k = 0; k < 3; ++k) {
      const auto a = t[k], b = t[(k + 1) % 3];
      Vec3 other{};
      bool found = false;
      for (std::size_t j = 0; j < c.added.size() && !found; ++j)
        for (int l = 0; l < 3; ++l)
          if (c.added[j][l] == b && c.added[j][(l + 1) % 3] == a) {
            other = c.normal(w.m, c.added[j]);
            found = true;
          }
      for (const auto f : w.faces_of[a]) {
        if (found)
          break;
        if (std::find(c.removed.begin(), c.removed.end(), f) != c.removed.end())
          continue;
        const auto& s = w.m.triangles[f];
        for (int l = 0; l < 3; ++l)
          if (s[l] == b && s[(l + 1) % 3] == a) {
            other = c.normal(w.m, s);
            found = true;
          }
      }
      c.min_cos = std::min(c.min_cos, found ? cosine(n, other) : -1.0);
    }
  }
}

bool flip(const Work& w, std::uint32_t f, int k, Candidate& c) {
  const auto& t = w.m.triangles[f];
  const auto a = t[k], b = t[(k + 1) % 3], cc = t[(k + 2) % 3];
  const long g = w.across(a, b, f);
  if (g < 0 || w.m.face_labels[std::size_t(g)] != w.m.face_labels[f])
    return false;
  std::uint32_t d = 0;
  for (const auto v : w.m.triangles[std::size_t(g)])
    if (v != a && v != b)
      d = v;
  if (d == cc || w.neighbours(cc).count(d))
    return false; // the new edge exists already
  const auto& x = w.m.vertices;
  const Vec3 across = cross(x[b] - x[a], x[d] - x[cc]);
  const double six_volume = std::abs(dot(x[cc] - x[a], cross(x[b] - x[a], x[d] - x[a])));
  c.shift = norm(across) > 0 ? six_volume / norm(across) : (six_volume > 0 ? 1e300 : 0.0);
  c.removed = {f, std::uint32_t(g)};
  c.added = {Triangle{a, d, cc}, Triangle{d, b, cc}};
  c.labels = {w.m.face_labels[f], w.m.face_labels[f]};
  c.kind = Candidate::Kind::flip;
  return true;
}

bool collapse(const Work& w, std::uint32_t v, std::uint32_t u, Candidate& c) {
  std::vector<std::uint32_t> on_edge;
  for (const auto f : w.faces_of[v]) {
    const auto& t = w.m.triangles[f];
    if (t[0] == u || t[1] == u || t[2] == u)
      on_edge.push_back(f);
  }
  if (on_edge.size() != 2)
    return false;
  std::set<std::uint32_t> opposite;
  for (const auto f : on_edge)
    for (const auto x : w.m.triangles[f])
      if (x != u && x != v)
        opposite.insert(x);
  const auto nv = w.neighbours(v), nu = w.neighbours(u);
  std::size_t n_common = 0;
  for (const auto x : nv)
    n_common += nu.count(x);
  if (opposite.size() != 2 || n_common != 2)
    return false;
  c.removed = w.faces_of[v];
  c.added.clear();
  c.labels.clear();
  c.shift = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto f : w.faces_of[v]) {
    if (std::find(on_edge.begin(), on_edge.end(), f) != on_edge.end())
      continue;
    auto t = w.m.triangles[f];
    for (auto& x : t)
      if (x == v)
        x = u;
    c.added.push_back(t);
    c.labels.push_back(w.m.face_labels[f]);
    const auto& x = w.m.vertices;
    nearest = std::min(
        nearest, norm(x[v] - closest_point_on_triangle(x[t[0]], x[t[1]], x[t[2]], x[v]).point));
  }
  if (c.added.empty())
    return false;
  c.shift = nearest;
  c.vertex = v;
  c.into = u;
  c.kind = Candidate::Kind::collapse;
  return true;
}

// v moved a fraction t of the way to the centroid of its neighbours.
void move(const Work& w, std::uint32_t v, double t, Candidate& c) {
  const auto around = w.neighbours(v);
  Vec3 centroid{};
  for (const auto u : around)
    centroid = centroid + w.m.vertices[u];
  centroid = centroid / double(around.size());
  c.kind = Candidate::Kind::move;
  c.vertex = v;
  c.to = w.m.vertices[v] + t * (centroid - w.m.vertices[v]);
  c.shift = norm(c.to - w.m.vertices[v]);
  c.removed = w.faces_of[v];
  c.added.clear();
  c.labels.clear();
  for (const auto f : c.removed) {
    c.added.push_back(w.m.triangles[f]);
    c.labels.push_back(w.m.face_labels[f]);
  }
}

// Faces with a folded edge, and faces of low quality the mending made (`made`).
std::vector<std::uint32_t> faces_to_mend(const Work& w, double fold_cos,
                                         const std::set<std::uint32_t>& made) {
  std::vector<std::uint32_t> bad;
  for (std::uint32_t f = 0; f < w.m.n_faces(); ++f) {
    if (w.dead[f])
      continue;
    const auto& t = w.m.triangles[f];
    bool is_bad = made.count(f) && triangle_quality(w.m.vertices[t[0]], w.m.vertices[t[1]],
                                                    w.m.vertices[t[2]]) < 0.1;
    for (int k = 0; k < 3 && !is_bad; ++k) {
      const long g = w.across(t[k], t[(k + 1) % 3], f);
      is_bad = g >= 0 && cosine(w.normal(t), w.normal(w.m.triangles[std::size_t(g)])) < fold_cos;
    }
    if (is_bad)
      bad.push_back(f);
  }
  return bad;
}

} // namespace

FoldMending mend_folds(SurfaceMesh& m, const std::vector<char>& removable,
                       const FoldMendingParameters& p) {
  FoldMending r;
  r.new_index.resize(m.n_vertices());
  for (std::uint32_t v = 0; v < m.n_vertices(); ++v)
    r.new_index[v] = v;
  r.n_folds_before = find_folded_edges(m, p.fold_cos).size();
  r.n_folds_after = r.n_folds_before;
  if (r.n_folds_before == 0)
    return r;
  Work w{m, std::vector<char>(m.n_faces(), 0), {}};
  std::set<std::uint32_t> made;
  for (int pass = 0; pass < p.max_passes; ++pass) {
    w.index();
    const auto bad = faces_to_mend(w, p.fold_cos, made);
    if (bad.empty())
      break;
    std::vector<char> touched(m.n_vertices(), 0);
    std::size_t n_changed = 0;
    for (const auto f : bad) {
      const auto t = m.triangles[f];
      if (w.dead[f] || touched[t[0]] || touched[t[1]] || touched[t[2]])
        continue;
      // The present state of f's edges, which a candidate must improve on.
      Candidate present;
      present.added = {t};
      present.removed = {f};
      judge(w, present);
      Candidate best, c;
      bool found = false;
      const auto consider = [&](Candidate& x) {
        judge(w, x);
        if (x.shift > p.max_shift || x.min_quality < 1e-3 || x.min_cos <= p.fold_cos)
          return;
        for (const auto g : x.removed)
          for (const auto v : m.triangles[g])
            if (touched[v])
              return;
        if (x.min_cos + x.min_quality <= present.min_cos + present.min_quality)
          return;
        if (!found || x.min_cos + x.min_quality > best.min_cos + best.min_quality) {
          best = x;
          found = true;
        }
      };
      for (int k = 0; k < 3; ++k)
        if (flip(w, f, k, c))
          consider(c);
      for (const auto v : t) {
        if (!removable[v])
          continue;
        bool one_label = true;
        for (const auto g : w.faces_of[v])
          one_label &= m.face_labels[g] == m.face_labels[f];
        if (!one_label)
          continue;
        for (const auto u : w.neighbours(v))
          if (collapse(w, v, u, c))
            consider(c);
        for (const double fraction : {0.25, 0.5, 0.75, 1.0}) {
          move(w, v, fraction, c);
          consider(c);
        }
      }
      if (!found)
        continue;
      for (const auto g : best.removed) {
        w.dead[g] = 1;
        for (const auto v : m.triangles[g])
          for (const auto x : w.neighbours(v))
            touched[x] = 1;
      }
      for (std::size_t i = 0; i < best.added.size(); ++i) {
        made.insert(std::uint32_t(m.n_faces()));
        m.triangles.push_back(best.added[i]);
        m.face_labels.push_back(best.labels[i]);
        w.dead.push_back(0);
      }
      if (best.kind == Candidate::Kind::collapse) {
        r.new_index[best.vertex] = best.into;
        ++r.n_collapses;
      } else if (best.kind == Candidate::Kind::move) {
        m.vertices[best.vertex] = best.to;
        ++r.n_moves;
      } else
        ++r.n_flips;
      ++n_changed;
    }
    if (n_changed == 0)
      break;
  }
  if (r.n_flips + r.n_collapses + r.n_moves == 0)
    return r;
  // Dead faces and collapsed vertices go; the rest keep their order.
  const auto into = r.new_index;
  std::vector<char> live(m.n_faces());
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    live[f] = !w.dead[f];
  const auto kept = keep_faces(m, live);
  for (std::uint32_t v = 0; v < into.size(); ++v) {
    auto target = v;
    while (kept[target] == no_vertex && into[target] != target) // collapsed, maybe in turn
      target = into[target];
    r.new_index[v] = kept[target];
  }
  m.bump_revision();
  r.n_folds_after = find_folded_edges(m, p.fold_cos).size();
  return r;
}

} // namespace wear::meshes

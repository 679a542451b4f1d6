// Shape and hole cuts of a patch of a triangulated surface (fem/discrete_patches.h).
//
// gmsh 4.8 reparametrises a discrete patch either by projection onto its least-squares plane
// (when every corner lies within Geometry.MatchMeshTolerance x the bounding-box diagonal of
// that plane) or by a mean-value (harmonic) map whose longest boundary loop is pinned to the
// unit circle and whose other loops are left free. For a disk the harmonic map cannot fold
// (Floater: convex boundary, positive weights); with holes it can, and the mesh gmsh builds
// in the parameter plane then folds too. The shape below says which map a patch gets and
// whether projection is safe: with every face normal within 90 deg of the plane normal
// (min_normal_cos > 0), the patch is a graph over the plane. The cuts make pieces without
// holes: two vertex-disjoint shortest paths (Dijkstra over the patch's interior edges) from a
// hole to the outer loop or to an earlier cut; then the loops and cuts form one connected
// plane graph in which each path lies on a cycle, so every piece it bounds is a disk.
#include "fem/discrete_patches.h"

#include "meshes/symmetric_eigen.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace wear::fem {

namespace {

// The patch's edges with the number of its faces on each, and its boundary loops: the
// vertices of each loop and the loop's length [m].
struct PatchTopology {
  std::map<Edge, int> edge_count;
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<double> loop_length;
};

PatchTopology patch_topology(const meshes::SurfaceMesh& m,
                             const std::vector<std::uint32_t>& faces) {
  PatchTopology t;
  for (const auto f : faces)
    for (int k = 0; k < 3; ++k) {
      const auto a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
      ++t.edge_count[{std::min(a, b), std::max(a, b)}];
    }
  // Loops: the components of the boundary edges (union-find over their vertices).
  std::unordered_map<std::uint32_t, std::uint32_t> parent;
  const std::function<std::uint32_t(std::uint32_t)> root = [&](std::uint32_t v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& [e, n] : t.edge_count)
    if (n == 1) {
      for (const auto v : {e.first, e.second})
        parent.emplace(v, v);
      parent[root(e.first)] = root(e.second);
    }
  std::map<std::uint32_t, std::size_t> loop_of;
  for (const auto& [v, p] : parent) {
    const auto r = root(v);
    if (!loop_of.count(r)) {
      loop_of[r] = t.loops.size();
      t.loops.emplace_back();
      t.loop_length.push_back(0);
    }
    t.loops[loop_of[r]].push_back(v);
  }
  for (const auto& [e, n] : t.edge_count)
    if (n == 1)
      t.loop_length[loop_of[root(e.first)]] +=
          meshes::norm(m.vertices[e.first] - m.vertices[e.second]);
  return t;
}

} // namespace

PatchShape patch_shape(const meshes::SurfaceMesh& m, const std::vector<std::uint32_t>& faces) {
  PatchShape s;
  s.n_faces = faces.size();
  if (faces.empty())
    return s;
  s.n_loops = static_cast<int>(patch_topology(m, faces).loops.size());
  // The least-squares plane through the faces' corners, a corner counted once per face
  // (as gmsh's planarity test does).
  meshes::Vec3 mean{0, 0, 0}, area_vector{0, 0, 0};
  for (const auto f : faces) {
    for (const auto v : m.triangles[f])
      mean += m.vertices[v];
    area_vector += meshes::face_normal_unnormalized(m, f);
  }
  mean *= 1.0 / (3.0 * faces.size());
  double a[3][3] = {};
  meshes::Vec3 lo = m.vertices[m.triangles[faces[0]][0]], hi = lo;
  for (const auto f : faces)
    for (const auto v : m.triangles[f]) {
      const auto d = m.vertices[v] - mean;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
          a[i][j] += d[i] * d[j];
        lo[i] = std::min(lo[i], m.vertices[v][i]);
        hi[i] = std::max(hi[i], m.vertices[v][i]);
      }
    }
  meshes::Vec3 values, vectors[3];
  meshes::symmetric_eigen(a, values, vectors);
  auto n = vectors[0]; // the smallest eigenvalue's
  if (meshes::dot(n, area_vector) < 0)
    n = -n;
  double deviation = 0;
  for (const auto f : faces)
    for (const auto v : m.triangles[f])
      deviation = std::max(deviation, std::abs(meshes::dot(n, m.vertices[v] - mean)));
  const double diagonal = meshes::norm(hi - lo);
  s.relative_deviation = diagonal > 0 ? deviation / diagonal : 0;
  for (const auto f : faces) {
    const auto nf = meshes::face_normal_unnormalized(m, f);
    const double length = meshes::norm(nf);
    s.min_normal_cos = std::min(s.min_normal_cos, length > 0 ? meshes::dot(nf, n) / length : -1.0);
  }
  return s;
}

namespace {

// Shortest path over the patch's interior edges from `sources` to the nearest vertex with
// state `target`, through vertices of state `free` only; vertex indices from the source to
// the target, empty when none is reachable.
enum class VertexState : char { free, blocked, target };
std::vector<std::uint32_t>
shortest_path(const meshes::SurfaceMesh& m,
              const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& neighbours,
              const std::vector<std::uint32_t>& sources,
              const std::unordered_map<std::uint32_t, VertexState>& state) {
  std::unordered_map<std::uint32_t, double> dist;
  std::unordered_map<std::uint32_t, std::uint32_t> from;
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (const auto s : sources) {
    dist[s] = 0;
    queue.push({0, s});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v])
      continue;
    const auto sv = state.find(v);
    if (sv != state.end() && sv->second == VertexState::target && d > 0) {
      std::vector<std::uint32_t> path{v};
      for (auto it = from.find(v); it != from.end(); it = from.find(it->second))
        path.push_back(it->second);
      std::reverse(path.begin(), path.end());
      return path;
    }
    const auto nb = neighbours.find(v);
    if (nb == neighbours.end())
      continue;
    for (const auto w : nb->second) {
      const auto sw = state.find(w);
      if (sw != state.end() && sw->second == VertexState::blocked)
        continue;
      const double dw = d + meshes::norm(m.vertices[v] - m.vertices[w]);
      const auto it = dist.find(w);
      if (it == dist.end() || dw < it->second) {
        dist[w] = dw;
        from[w] = v;
        queue.push({dw, w});
      }
    }
  }
  return {};
}

// Where the second path from `hole` leaves: the hole's vertex farthest from the first path's
// start `first` with an edge to a vertex that is not blocked (`first` when there is none).
std::uint32_t
second_start(const meshes::SurfaceMesh& m,
             const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& neighbours,
             const std::vector<std::uint32_t>& hole, std::uint32_t first,
             const std::unordered_map<std::uint32_t, VertexState>& state) {
  std::uint32_t start = first;
  double farthest = 0;
  for (const auto v : hole) {
    const auto nb = neighbours.find(v);
    const bool leaves =
        nb != neighbours.end() && std::any_of(nb->second.begin(), nb->second.end(), [&](auto w) {
          const auto sw = state.find(w);
          return sw == state.end() || sw->second != VertexState::blocked;
        });
    const double d = meshes::norm(m.vertices[v] - m.vertices[first]);
    if (leaves && d > farthest) {
      farthest = d;
      start = v;
    }
  }
  return start;
}

void append_path_edges(const std::vector<std::uint32_t>& path, std::vector<Edge>& cuts) {
  for (std::size_t i = 1; i < path.size(); ++i)
    cuts.push_back({std::min(path[i - 1], path[i]), std::max(path[i - 1], path[i])});
}

} // namespace

std::vector<Edge> hole_cuts(const meshes::SurfaceMesh& m, const std::vector<std::uint32_t>& faces) {
  const PatchTopology t = patch_topology(m, faces);
  if (t.loops.size() < 2)
    return {};
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> neighbours;
  for (const auto& [e, n] : t.edge_count)
    if (n == 2) {
      neighbours[e.first].push_back(e.second);
      neighbours[e.second].push_back(e.first);
    }
  // Loops by decreasing length: the first is the outer loop (gmsh pins the longest), the
  // target of the first cuts; holes not yet cut are blocked.
  std::vector<std::size_t> order(t.loops.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return t.loop_length[a] > t.loop_length[b]; });
  std::unordered_map<std::uint32_t, VertexState> state;
  for (std::size_t i = 0; i < order.size(); ++i)
    for (const auto v : t.loops[order[i]])
      state[v] = i == 0 ? VertexState::target : VertexState::blocked;
  std::vector<Edge> cuts;
  for (std::size_t i = 1; i < order.size(); ++i) {
    const auto& hole = t.loops[order[i]];
    for (const auto v : hole)
      state[v] = VertexState::free; // sources; a path never returns to them (distance 0)
    const auto first = shortest_path(m, neighbours, hole, state);
    if (first.empty()) {
      for (const auto v : hole)
        state[v] = VertexState::blocked;
      continue;
    }
    // The second path may neither run along the hole nor meet the first path: ending on
    // it, the two would leave the first path's outer part with the same piece on both sides,
    // a slit gmsh does not cut along, and the hole would stay.
    for (std::size_t k = 1; k + 1 < first.size(); ++k)
      state[first[k]] = VertexState::blocked;
    for (const auto v : hole)
      state[v] = VertexState::blocked;
    const auto start = second_start(m, neighbours, hole, first[0], state);
    state[start] = VertexState::free;
    const auto second = start == first[0] ? std::vector<std::uint32_t>{}
                                          : shortest_path(m, neighbours, {start}, state);
    append_path_edges(first, cuts);
    append_path_edges(second, cuts);
    for (const auto& path : {first, second, hole})
      for (const auto v : path)
        state[v] = VertexState::target;
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

} // namespace wear::fem

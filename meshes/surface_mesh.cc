// SurfaceMesh geometry and topology.
//
// Areas and normals: n_f A_f = (x1 - x0) x (x2 - x0) / 2. Enclosed volume by the divergence
// theorem, V = sum_f (x0 . ((x1 - x0) x (x2 - x0))) / 6, exact for a closed polyhedron.
// The volume above a plane uses the field (0, 0, z - z0): V = sum_f (zc_f - z0) n_z,f A_f,
// exact for planar triangles because z - z0 is linear over each face.
// Orientation is made consistent by a breadth-first walk over manifold edges: two faces
// sharing an edge are consistent when they traverse it in opposite directions.
#include "meshes/surface_mesh.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace wear::meshes {

namespace label {
int part_surface(FaceRole role, int n) {
  switch (role) {
  case FaceRole::wearing:
    return 1000 + n;
  case FaceRole::free:
    return 2000 + n;
  case FaceRole::clamped:
    return 3000 + n;
  case FaceRole::held:
    return 4000 + n;
  }
  throw std::logic_error("label::part_surface: an unknown role");
}

std::string name(int id) {
  switch (id) {
  case unlabelled:
    return "unlabelled";
  case bottom:
    return "bottom";
  case side:
    return "side";
  case base:
    return "base";
  case wall:
    return "wall";
  case pocket:
    return "pocket";
  default:
    if (is_convex_element(id))
      return "C" + std::to_string(column_of(id)) + std::to_string(element_of(id));
    if (is_part_surface(id)) {
      const std::string n = "S" + std::to_string(part_surface_number(id));
      return id < 2000 ? n : id < 3000 ? n + "-free" : id < 4000 ? n + "-clamped" : n + "-held";
    }
    return "L" + std::to_string(id);
  }
}

int from_name(const std::string& n) {
  for (int id : {unlabelled, bottom, side, base, wall, pocket})
    if (n == name(id))
      return id;
  if (n.size() == 3 && n[0] == 'C' && n[1] >= '1' && n[1] <= '9' && n[2] >= '1' && n[2] <= '9')
    return convex_element(n[1] - '0', n[2] - '0');
  if (n.size() > 1 && n[0] == 'S') {
    const auto dash = n.find('-');
    const std::string suffix = dash == std::string::npos ? "" : n.substr(dash);
    const bool known =
        suffix.empty() || suffix == "-free" || suffix == "-clamped" || suffix == "-held";
    const FaceRole role = suffix.empty()         ? FaceRole::wearing
                          : suffix == "-free"    ? FaceRole::free
                          : suffix == "-clamped" ? FaceRole::clamped
                                                 : FaceRole::held;
    try {
      const int number = std::stoi(n.substr(1, dash == std::string::npos ? n.npos : dash - 1));
      if (known && number >= 1 && number <= max_part_surfaces)
        return part_surface(role, number);
    } catch (const std::exception&) {
    }
  }
  if (n.size() > 1 && n[0] == 'L') {
    try {
      return std::stoi(n.substr(1));
    } catch (const std::exception&) {
    }
  }
  throw std::invalid_argument("unknown face label name '" + n + "'");
}
} // namespace label

void SurfaceMesh::validate(const std::string& what) const {
  if (face_labels.size() != triangles.size())
    throw std::runtime_error(what + ": " + std::to_string(face_labels.size()) +
                             " face labels for " + std::to_string(triangles.size()) + " triangles");
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const Vec3& p = vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::runtime_error(what + ": vertex " + std::to_string(v) +
                               " has a non-finite coordinate");
  }
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (auto i : triangles[f])
      if (i >= vertices.size())
        throw std::runtime_error(what + ": triangle " + std::to_string(f) + " refers to vertex " +
                                 std::to_string(i) + " of " + std::to_string(vertices.size()));
}

std::vector<int> SurfaceMesh::labels() const {
  std::set<int> s(face_labels.begin(), face_labels.end());
  return {s.begin(), s.end()};
}

Vec3 face_normal_unnormalized(const SurfaceMesh& m, std::size_t f) {
  const auto& t = m.triangles[f];
  const Vec3& a = m.vertices[t[0]];
  return cross(m.vertices[t[1]] - a, m.vertices[t[2]] - a);
}

std::vector<double> face_areas(const SurfaceMesh& m) {
  std::vector<double> a(m.n_faces());
  for (std::size_t f = 0; f < a.size(); ++f)
    a[f] = 0.5 * norm(face_normal_unnormalized(m, f));
  return a;
}

std::vector<Vec3> face_normals(const SurfaceMesh& m) {
  std::vector<Vec3> n(m.n_faces());
  for (std::size_t f = 0; f < n.size(); ++f)
    n[f] = normalized(face_normal_unnormalized(m, f));
  return n;
}

std::vector<Vec3> face_centroids(const SurfaceMesh& m) {
  std::vector<Vec3> c(m.n_faces());
  for (std::size_t f = 0; f < c.size(); ++f) {
    const auto& t = m.triangles[f];
    c[f] = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
  }
  return c;
}

std::vector<Vec3> vertex_normals(const SurfaceMesh& m) {
  std::vector<Vec3> n(m.n_vertices());
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const Vec3 w = face_normal_unnormalized(m, f); // |w| = 2 A: area weighting for free
    for (auto v : m.triangles[f])
      n[v] += w;
  }
  for (auto& v : n)
    v = normalized(v);
  return n;
}

BoundingBox bounding_box(const SurfaceMesh& m) {
  return bounding_box(m.vertices.data(), m.vertices.size());
}

BoundingBox bounding_box(const Vec3* points, std::size_t n) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  BoundingBox b{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      b.min[d] = std::min(b.min[d], points[i][d]);
      b.max[d] = std::max(b.max[d], points[i][d]);
    }
  return b;
}

double total_area(const SurfaceMesh& m) {
  double s = 0;
  for (double a : face_areas(m))
    s += a;
  return s;
}

std::map<int, double> area_per_label(const SurfaceMesh& m) {
  std::map<int, double> r;
  const auto a = face_areas(m);
  for (std::size_t f = 0; f < a.size(); ++f)
    r[m.face_labels[f]] += a[f];
  return r;
}

long euler_characteristic(const SurfaceMesh& m) {
  // closed: every edge has two faces, E = 3 F / 2
  return long(m.n_vertices()) - long(m.n_faces()) * 3 / 2 + long(m.n_faces());
}

double enclosed_volume(const SurfaceMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) {
    const Vec3& a = m.vertices[t[0]];
    v += dot(a, cross(m.vertices[t[1]] - a, m.vertices[t[2]] - a));
  }
  return v / 6.0;
}

double volume_above_plane(const SurfaceMesh& m, int label_id, double z0) {
  double v = 0;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    if (m.face_labels[f] != label_id)
      continue;
    const auto& t = m.triangles[f];
    const double zc = (m.vertices[t[0]].z + m.vertices[t[1]].z + m.vertices[t[2]].z) / 3.0;
    v += (zc - z0) * 0.5 * face_normal_unnormalized(m, f).z;
  }
  return v;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>>
edge_faces(const SurfaceMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> e;
  for (std::uint32_t f = 0; f < m.n_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
      e[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  return e;
}

std::vector<int>
face_patches(const SurfaceMesh& m,
             const std::function<bool(std::uint32_t, std::uint32_t,
                                      std::pair<std::uint32_t, std::uint32_t>)>& joined) {
  std::vector<int> parent(m.n_faces());
  for (std::size_t f = 0; f < parent.size(); ++f)
    parent[f] = int(f);
  const auto root = [&](int f) {
    while (parent[std::size_t(f)] != f)
      f = parent[std::size_t(f)] = parent[std::size_t(parent[std::size_t(f)])];
    return f;
  };
  for (const auto& [edge, faces] : edge_faces(m))
    if (faces.size() == 2 && joined(faces[0], faces[1], edge))
      parent[std::size_t(root(int(faces[0])))] = root(int(faces[1]));
  std::vector<int> patch(m.n_faces());
  for (std::size_t f = 0; f < patch.size(); ++f)
    patch[f] = root(int(f));
  return patch;
}

VertexFaces vertex_faces(const SurfaceMesh& m) {
  VertexFaces vf;
  vf.offsets.assign(m.n_vertices() + 1, 0);
  for (const auto& t : m.triangles)
    for (auto v : t)
      ++vf.offsets[v + 1];
  for (std::size_t i = 0; i < m.n_vertices(); ++i)
    vf.offsets[i + 1] += vf.offsets[i];
  vf.faces.resize(vf.offsets.back());
  std::vector<std::uint32_t> fill(vf.offsets.begin(), vf.offsets.end() - 1);
  for (std::uint32_t f = 0; f < m.n_faces(); ++f)
    for (auto v : m.triangles[f])
      vf.faces[fill[v]++] = f;
  return vf;
}

// Sorting the half-edges by their vertices pairs each edge's two uses.
std::vector<std::array<std::uint32_t, 3>> face_neighbours(const SurfaceMesh& m) {
  struct HalfEdge {
    std::uint32_t lo, hi, face, slot;
  };
  std::vector<HalfEdge> e;
  e.reserve(3 * m.n_faces());
  for (std::uint32_t f = 0; f < m.n_faces(); ++f)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const auto a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
      e.push_back({std::min(a, b), std::max(a, b), f, k});
    }
  std::sort(e.begin(), e.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi;
  });
  std::vector<std::array<std::uint32_t, 3>> across(m.n_faces());
  if (e.size() % 2 != 0)
    throw std::runtime_error("face_neighbours: the surface is not a closed manifold (" +
                             std::to_string(m.n_faces()) + " faces, an odd number)");
  for (std::size_t i = 0; i + 1 < e.size(); i += 2) {
    if (e[i].lo != e[i + 1].lo || e[i].hi != e[i + 1].hi)
      throw std::runtime_error("face_neighbours: the surface is not a closed manifold (edge " +
                               std::to_string(e[i].lo) + "-" + std::to_string(e[i].hi) + ")");
    across[e[i].face][e[i].slot] = e[i + 1].face;
    across[e[i + 1].face][e[i + 1].slot] = e[i].face;
  }
  return across;
}

namespace {
// Directed use of edge (a, b) in face f: +1 when f traverses a -> b with a < b.
int edge_direction(const Triangle& t, std::uint32_t a, std::uint32_t b) {
  for (int k = 0; k < 3; ++k) {
    if (t[k] == a && t[(k + 1) % 3] == b)
      return +1;
    if (t[k] == b && t[(k + 1) % 3] == a)
      return -1;
  }
  return 0;
}
} // namespace

ClosednessReport check_closed(const SurfaceMesh& m) {
  ClosednessReport r;
  for (const auto& [edge, faces] : edge_faces(m)) {
    if (faces.size() == 1)
      ++r.n_boundary_edges;
    else if (faces.size() > 2)
      ++r.n_nonmanifold_edges;
    else if (edge_direction(m.triangles[faces[0]], edge.first, edge.second) ==
             edge_direction(m.triangles[faces[1]], edge.first, edge.second))
      ++r.n_misoriented_edges;
  }
  return r;
}

std::size_t orient_outward(SurfaceMesh& m) {
  const auto ef = edge_faces(m);
  // Face adjacency through manifold edges only.
  std::vector<std::vector<std::pair<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>>>> adj(
      m.n_faces());
  for (const auto& [edge, faces] : ef)
    if (faces.size() == 2) {
      adj[faces[0]].push_back({faces[1], edge});
      adj[faces[1]].push_back({faces[0], edge});
    }
  std::vector<int> component(m.n_faces(), -1);
  std::vector<char> flip(m.n_faces(), 0);
  int n_components = 0;
  for (std::uint32_t seed = 0; seed < m.n_faces(); ++seed) {
    if (component[seed] >= 0)
      continue;
    std::deque<std::uint32_t> queue{seed};
    component[seed] = n_components;
    while (!queue.empty()) {
      const auto f = queue.front();
      queue.pop_front();
      for (const auto& [g, e] : adj[f]) {
        if (component[g] >= 0)
          continue;
        component[g] = n_components;
        const int df = edge_direction(m.triangles[f], e.first, e.second) * (flip[f] ? -1 : 1);
        const int dg = edge_direction(m.triangles[g], e.first, e.second);
        flip[g] = (df == dg);
        queue.push_back(g);
      }
    }
    ++n_components;
  }
  std::size_t n_flipped = 0;
  for (std::uint32_t f = 0; f < m.n_faces(); ++f)
    if (flip[f]) {
      std::swap(m.triangles[f][1], m.triangles[f][2]);
      ++n_flipped;
    }
  // Per component: a negative signed volume means the whole component points inward.
  std::vector<double> vol(n_components, 0.0);
  for (std::uint32_t f = 0; f < m.n_faces(); ++f) {
    const auto& t = m.triangles[f];
    const Vec3& a = m.vertices[t[0]];
    vol[component[f]] += dot(a, cross(m.vertices[t[1]] - a, m.vertices[t[2]] - a));
  }
  for (std::uint32_t f = 0; f < m.n_faces(); ++f)
    if (vol[component[f]] < 0) {
      std::swap(m.triangles[f][1], m.triangles[f][2]);
      n_flipped += flip[f] ? -1 : 1;
    }
  if (n_flipped > 0)
    m.bump_revision();
  return n_flipped;
}

std::vector<std::uint32_t> keep_faces(SurfaceMesh& m, const std::vector<char>& keep) {
  std::vector<std::uint32_t> new_index(m.n_vertices(), no_vertex);
  std::vector<Triangle> triangles;
  std::vector<int> labels;
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (keep[f]) {
      triangles.push_back(m.triangles[f]);
      labels.push_back(m.face_labels[f]);
      for (const auto v : m.triangles[f])
        new_index[v] = 0;
    }
  std::vector<Vec3> vertices;
  for (std::size_t v = 0; v < m.n_vertices(); ++v)
    if (new_index[v] != no_vertex) {
      new_index[v] = std::uint32_t(vertices.size());
      vertices.push_back(m.vertices[v]);
    }
  for (auto& t : triangles)
    for (auto& v : t)
      v = new_index[v];
  m.vertices = std::move(vertices);
  m.triangles = std::move(triangles);
  m.face_labels = std::move(labels);
  return new_index;
}

void merge_identical_vertices(SurfaceMesh& m) {
  struct Hash {
    std::size_t operator()(const Vec3& p) const {
      std::hash<double> h;
      return h(p.x) ^ (h(p.y) * 1000003u) ^ (h(p.z) * 998244353u);
    }
  };
  std::unordered_map<Vec3, std::uint32_t, Hash> index;
  std::vector<Vec3> merged;
  std::vector<std::uint32_t> remap(m.n_vertices());
  // Only referenced vertices survive, numbered in order of first use.
  std::vector<char> used(m.n_vertices(), 0);
  for (const auto& t : m.triangles)
    for (auto v : t)
      used[v] = 1;
  for (std::size_t v = 0; v < m.n_vertices(); ++v) {
    if (!used[v])
      continue;
    auto [it, inserted] = index.emplace(m.vertices[v], static_cast<std::uint32_t>(merged.size()));
    if (inserted)
      merged.push_back(m.vertices[v]);
    remap[v] = it->second;
  }
  for (auto& t : m.triangles)
    for (auto& v : t)
      v = remap[v];
  m.vertices = std::move(merged);
  m.bump_revision();
}

} // namespace wear::meshes

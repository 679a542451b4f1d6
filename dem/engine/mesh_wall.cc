// Triangle-mesh walls.
//
// One contact per physical touch: a sphere centre c has, on each triangle, a closest point p
// on a face interior, an edge or a vertex. An edge point is kept only if, for every face
// sharing the edge, d = c - p has no component along that face's in-plane inward edge
// normal (otherwise moving into that face brings the surface closer, and that face reports
// the true contact); a vertex point is kept only if d has no component along any edge
// leaving the vertex. Of the faces that then report the same edge or vertex, only the first
// (lowest index) keeps it. On a flat patch this leaves exactly the face (or shared edge or
// vertex) under the centre, with the normal of a flat wall; on a convex ridge the shared
// edge; in a concave corner one contact per face, as physics asks.
//
// Covered faces (held flush against another wall): an edge or vertex where they meet uncovered
// faces is a junction. It is tested against its uncovered faces only, reported by one of them,
// and its contact marked as such: the force pass keeps it only where no other wall's contact
// of about the same normal is as deep (the flush neighbour's face), so a flat junction of two
// walls counts once, and a worn face that sank below its holder's rim still holds a particle
// on its edge.
#include "dem/engine/mesh_wall.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace wear::dem {

using meshes::cross;
using meshes::dot;
using meshes::norm;
using meshes::normalized;

MeshWall::MeshWall(const meshes::SurfaceMesh& mesh, int material_id, const WallMotion& motion,
                   bool wearing, std::string name, std::vector<int> covered_labels)
    : mesh_(mesh), material_(material_id), motion_(motion), wearing_(wearing),
      name_(std::move(name)), covered_labels_(std::move(covered_labels)) {
  mesh_.validate("wall '" + name_ + "'");
  if (mesh_.n_faces() == 0)
    throw std::invalid_argument("wall '" + name_ + "' has no triangles");
  omega_ = normalized(motion_.axis) * motion_.angular_velocity;
  const std::size_t nf = mesh_.n_faces();
  // Edges.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_id;
  face_edge_.resize(nf);
  for (std::uint32_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto a = mesh_.triangles[f][k], b = mesh_.triangles[f][(k + 1) % 3];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto [it, inserted] = edge_id.emplace(key, static_cast<std::uint32_t>(edge_face_.size()));
      if (inserted) {
        edge_face_.push_back({f, ~0u});
        edge_vertex_.push_back({key.first, key.second});
      } else if (edge_face_[it->second][1] == ~0u)
        edge_face_[it->second][1] = f;
      face_edge_[f][k] = it->second;
    }
  // Vertices: first face, faces around, edges leaving.
  const std::size_t nv = mesh_.n_vertices();
  vertex_first_face_.assign(nv, ~0u);
  std::vector<std::vector<std::uint32_t>> vf(nv), ve(nv);
  for (std::uint32_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto v = mesh_.triangles[f][k];
      vertex_first_face_[v] = std::min(vertex_first_face_[v], f);
      vf[v].push_back(f);
    }
  for (std::uint32_t e = 0; e < edge_vertex_.size(); ++e) {
    ve[edge_vertex_[e][0]].push_back(e);
    ve[edge_vertex_[e][1]].push_back(e);
  }
  vertex_edge_offset_.assign(nv + 1, 0);
  vertex_face_offset_.assign(nv + 1, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    vertex_edge_offset_[v + 1] = vertex_edge_offset_[v] + ve[v].size();
    vertex_face_offset_[v + 1] = vertex_face_offset_[v] + vf[v].size();
    vertex_edge_.insert(vertex_edge_.end(), ve[v].begin(), ve[v].end());
    vertex_face_.insert(vertex_face_.end(), vf[v].begin(), vf[v].end());
  }
  // Junctions of covered and uncovered faces.
  auto& covered = face_covered_;
  covered.assign(nf, 0);
  for (std::size_t f = 0; f < nf; ++f)
    covered[f] = std::find(covered_labels_.begin(), covered_labels_.end(), mesh_.face_labels[f]) !=
                 covered_labels_.end();
  edge_junction_.assign(edge_face_.size(), 0);
  for (std::size_t e = 0; e < edge_face_.size(); ++e)
    edge_junction_[e] =
        edge_face_[e][1] != ~0u && covered[edge_face_[e][0]] != covered[edge_face_[e][1]];
  vertex_edge_open_.assign(vertex_edge_.size(), 0);
  for (std::size_t i = 0; i < vertex_edge_.size(); ++i)
    for (auto g : edge_face_[vertex_edge_[i]])
      if (g != ~0u && !covered[g])
        vertex_edge_open_[i] = 1;
  vertex_junction_.assign(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    bool any_covered = false, any_open = false;
    std::uint32_t first_open = ~0u;
    for (auto i = vertex_face_offset_[v]; i < vertex_face_offset_[v + 1]; ++i) {
      const auto g = vertex_face_[i];
      (covered[g] ? any_covered : any_open) = true;
      if (!covered[g])
        first_open = std::min(first_open, g);
    }
    vertex_junction_[v] = any_covered && any_open;
    if (vertex_junction_[v])
      vertex_first_face_[v] = first_open;
  }
  compute_geometry();
}

void MeshWall::set_vertices(const std::vector<Vec3>& vertices) {
  if (vertices.size() != mesh_.vertices.size())
    throw std::invalid_argument("wall '" + name_ + "': new vertex count " +
                                std::to_string(vertices.size()) + " differs from " +
                                std::to_string(mesh_.vertices.size()));
  mesh_.vertices = vertices;
  mesh_.bump_revision();
  compute_geometry();
  if (moving_)
    axis_reach_ =
        axis_reach(rigid_, mesh_.vertices.data(), mesh_.vertices.data() + mesh_.vertices.size());
  if (cell_ > 0)
    build_grid(reach_);
}

void MeshWall::set_rigid_motion(const RigidMotion& m) {
  const std::string what = "wall '" + name_ + "'";
  validate(m, what);
  if (m.moves() && (motion_.angular_velocity != 0 || motion_.surface_velocity != Vec3{}))
    throw std::invalid_argument(what + " has a surface motion already; a rigid motion of its "
                                       "geometry replaces it, give one or the other");
  rigid_ = m;
  moving_ = m.moves();
  pose_ = reference_pose_ = RigidPose{};
  axis_reach_ =
      axis_reach(rigid_, mesh_.vertices.data(), mesh_.vertices.data() + mesh_.vertices.size());
}

std::vector<Vec3> MeshWall::world_vertices() const {
  std::vector<Vec3> v(mesh_.vertices.size());
  for (std::size_t k = 0; k < v.size(); ++k)
    v[k] = to_world(mesh_.vertices[k]);
  return v;
}

void MeshWall::compute_geometry() {
  const std::size_t nf = mesh_.n_faces(), nv = mesh_.n_vertices();
  corners_.resize(nf);
  normal_.resize(nf);
  inward_.resize(nf);
  bound_.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k)
      corners_[f][k] = mesh_.vertices[mesh_.triangles[f][k]];
    const Vec3 n = meshes::face_normal_unnormalized(mesh_, f);
    if (!(norm(n) > 0))
      throw std::invalid_argument("wall '" + name_ + "': triangle " + std::to_string(f) +
                                  " is degenerate (zero area)");
    normal_[f] = normalized(n);
    // In-plane normal of edge k pointing into the triangle.
    for (int k = 0; k < 3; ++k)
      inward_[f][k] = normalized(cross(normal_[f], corners_[f][(k + 1) % 3] - corners_[f][k]));
    // Widened by a relative 1e-9 so that round-off in the test never rejects a touching face.
    const Vec3 centre = (corners_[f][0] + corners_[f][1] + corners_[f][2]) * (1.0 / 3.0);
    double r2 = 0;
    for (int k = 0; k < 3; ++k)
      r2 = std::max(r2, meshes::norm2(corners_[f][k] - centre));
    bound_[f] = {normal_[f], dot(normal_[f], corners_[f][0]), centre, std::sqrt(r2) * (1 + 1e-9)};
  }
  vertex_edge_dir_.resize(vertex_edge_.size());
  vertex_face_weight_.resize(vertex_face_.size());
  for (std::uint32_t v = 0; v < nv; ++v) {
    for (auto i = vertex_edge_offset_[v]; i < vertex_edge_offset_[v + 1]; ++i) {
      const auto& ev = edge_vertex_[vertex_edge_[i]];
      const auto other = ev[0] == v ? ev[1] : ev[0];
      vertex_edge_dir_[i] = normalized(mesh_.vertices[other] - mesh_.vertices[v]);
    }
    // Share of a vertex contact per face: the face's interior angle at v over the total,
    // i.e. the fraction of a small disc around the vertex that lies on the face; at a
    // junction vertex over the uncovered faces only.
    double total = 0;
    for (auto i = vertex_face_offset_[v]; i < vertex_face_offset_[v + 1]; ++i) {
      const auto& t = mesh_.triangles[vertex_face_[i]];
      const int k = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
      const Vec3 a = mesh_.vertices[t[(k + 1) % 3]] - mesh_.vertices[v];
      const Vec3 b = mesh_.vertices[t[(k + 2) % 3]] - mesh_.vertices[v];
      const bool skip = vertex_junction_[v] && face_covered_[vertex_face_[i]];
      vertex_face_weight_[i] = skip ? 0.0 : std::atan2(norm(cross(a, b)), dot(a, b));
      total += vertex_face_weight_[i];
    }
    for (auto i = vertex_face_offset_[v]; i < vertex_face_offset_[v + 1]; ++i)
      vertex_face_weight_[i] /= total;
  }
}

ClosestFeature MeshWall::closest(std::uint32_t f, const Vec3& p) const {
  return meshes::closest_point_on_triangle(corners_[f][0], corners_[f][1], corners_[f][2], p);
}

ContactOwnership MeshWall::contact_ownership(std::uint32_t f, const ClosestFeature& cf,
                                             const Vec3& c) const {
  using O = ContactOwnership;
  if (cf.feature == Feature::face)
    return O::owned;
  const Vec3 d = c - cf.point;
  const double tol = 1e-9 * norm(d);
  if (cf.feature == Feature::edge) {
    const auto e = face_edge_[f][cf.local];
    const bool junction = edge_junction_[e];
    for (auto g : edge_face_[e]) {
      if (g == ~0u || (junction && face_covered_[g]))
        continue;
      const int k = face_edge_[g][0] == e ? 0 : (face_edge_[g][1] == e ? 1 : 2);
      if (dot(d, inward_[g][k]) > tol)
        return O::none;
    }
    // A junction edge has one uncovered face, which reports it.
    if (junction)
      return face_covered_[f] ? O::none : O::junction;
    return f == edge_face_[e][0] ? O::owned : O::none;
  }
  const auto v = mesh_.triangles[f][cf.local];
  const bool junction = vertex_junction_[v];
  for (auto i = vertex_edge_offset_[v]; i < vertex_edge_offset_[v + 1]; ++i)
    if ((!junction || vertex_edge_open_[i]) && dot(d, vertex_edge_dir_[i]) > tol)
      return O::none;
  if (f != vertex_first_face_[v])
    return O::none;
  return junction ? O::junction : O::owned;
}

int MeshWall::faces_sharing(std::uint32_t f, const ClosestFeature& cf, std::uint32_t* out,
                            double* weight, int max_out) const {
  if (cf.feature == Feature::face) {
    out[0] = f;
    weight[0] = 1;
    return 1;
  }
  int n = 0;
  if (cf.feature == Feature::edge) {
    const auto e = face_edge_[f][cf.local];
    const auto& ef = edge_face_[e];
    if (edge_junction_[e]) { // all on the uncovered face: the covered one touches no particle
      out[0] = face_covered_[ef[0]] ? ef[1] : ef[0];
      weight[0] = 1;
      return 1;
    }
    const int n_sharing = ef[1] == ~0u ? 1 : 2;
    for (auto g : ef)
      if (g != ~0u && n < max_out) {
        weight[n] = 1.0 / n_sharing;
        out[n++] = g;
      }
    return n;
  }
  const auto v = mesh_.triangles[f][cf.local];
  for (auto i = vertex_face_offset_[v]; i < vertex_face_offset_[v + 1] && n < max_out; ++i) {
    weight[n] = vertex_face_weight_[i];
    out[n++] = vertex_face_[i];
  }
  return n;
}

void MeshWall::build_grid(double reach) {
  reach_ = reach;
  const auto bb = meshes::bounding_box(mesh_);
  const Vec3 lo = bb.min - Vec3{reach, reach, reach}, hi = bb.max + Vec3{reach, reach, reach};
  const Vec3 ext = hi - lo;
  // Cells about the contact reach, at most ~2M cells.
  cell_ = std::max(reach, 1e-6);
  while ((ext.x / cell_ + 1) * (ext.y / cell_ + 1) * (ext.z / cell_ + 1) > 2e6)
    cell_ *= 1.25;
  grid_min_ = lo;
  nx_ = int(ext.x / cell_) + 1;
  ny_ = int(ext.y / cell_) + 1;
  nz_ = int(ext.z / cell_) + 1;
  const auto range = [&](std::uint32_t f, int lo_i[3], int hi_i[3]) {
    for (int d = 0; d < 3; ++d) {
      double mn = corners_[f][0][d], mx = mn;
      for (int k = 1; k < 3; ++k) {
        mn = std::min(mn, corners_[f][k][d]);
        mx = std::max(mx, corners_[f][k][d]);
      }
      const int n = d == 0 ? nx_ : (d == 1 ? ny_ : nz_);
      lo_i[d] = std::clamp(int((mn - reach - grid_min_[d]) / cell_), 0, n - 1);
      hi_i[d] = std::clamp(int((mx + reach - grid_min_[d]) / cell_), 0, n - 1);
    }
  };
  cell_offset_.assign(std::size_t(nx_) * ny_ * nz_ + 1, 0);
  int lo_i[3], hi_i[3];
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      for (std::size_t c = 1; c < cell_offset_.size(); ++c)
        cell_offset_[c] += cell_offset_[c - 1];
      cell_face_.assign(cell_offset_.back(), 0);
      fill.assign(cell_offset_.begin(), cell_offset_.end() - 1);
    }
    for (std::uint32_t f = 0; f < n_faces(); ++f) {
      range(f, lo_i, hi_i);
      for (int k = lo_i[2]; k <= hi_i[2]; ++k)
        for (int j = lo_i[1]; j <= hi_i[1]; ++j)
          for (int i = lo_i[0]; i <= hi_i[0]; ++i) {
            const std::size_t c = (std::size_t(k) * ny_ + j) * nx_ + i;
            if (pass == 0)
              ++cell_offset_[c + 1];
            else
              cell_face_[fill[c]++] = f;
          }
    }
  }
}

std::pair<const std::uint32_t*, const std::uint32_t*> MeshWall::candidates(const Vec3& c) const {
  const double fx = (c.x - grid_min_.x) / cell_, fy = (c.y - grid_min_.y) / cell_,
               fz = (c.z - grid_min_.z) / cell_;
  if (!(fx >= 0 && fy >= 0 && fz >= 0) || fx >= nx_ || fy >= ny_ || fz >= nz_)
    return {nullptr, nullptr};
  const std::size_t cell = (std::size_t(fz) * ny_ + std::size_t(fy)) * nx_ + std::size_t(fx);
  const std::uint32_t* base = cell_face_.data();
  return {base + cell_offset_[cell], base + cell_offset_[cell + 1]};
}

} // namespace wear::dem

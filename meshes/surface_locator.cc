// Nearest-face queries on a triangle surface.
//
// Grid: cubic cells of about twice the mean edge length over the surface's bounding box;
// each face is listed in every cell its bounding box touches. A query visits shells of cells
// at Chebyshev distance 0, 1, 2, ... around the point's cell; once a face at distance d is
// found, shells farther than d (shell k is at least (k - 1) cells away) cannot hold a closer
// one and the search stops. Points outside the box are clamped to it first, which keeps the
// shell bound valid because the box holds every face.
#include "meshes/surface_locator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wear::meshes {

SurfaceLocator::SurfaceLocator(const SurfaceMesh& mesh) : mesh_(mesh), revision_(mesh.revision()) {
  if (mesh.n_faces() == 0)
    throw std::invalid_argument("SurfaceLocator: the surface has no faces");
  const auto box = bounding_box(mesh);
  double edge_sum = 0;
  for (const auto& t : mesh.triangles)
    edge_sum += norm(mesh.vertices[t[1]] - mesh.vertices[t[0]]);
  const Vec3 extent = box.extent();
  cell_ = std::max(2 * edge_sum / static_cast<double>(mesh.n_faces()),
                   1e-9 * std::max({extent.x, extent.y, extent.z, 1e-12}));
  // Cap the cell count for very flat or very fine surfaces.
  while ((extent.x / cell_ + 1) * (extent.y / cell_ + 1) * (extent.z / cell_ + 1) >
         8.0 * static_cast<double>(mesh.n_faces()) + 1000)
    cell_ *= 1.5;
  origin_ = box.min;
  const double e[3] = {extent.x, extent.y, extent.z};
  for (int d = 0; d < 3; ++d)
    n_[d] = std::max(1, static_cast<int>(std::ceil(e[d] / cell_)) + (e[d] == 0 ? 1 : 0));
  const std::size_t n_cells = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
  auto cell_range = [&](std::size_t f, int lo[3], int hi[3]) {
    Vec3 mn = mesh.vertices[mesh.triangles[f][0]], mx = mn;
    for (int k = 1; k < 3; ++k) {
      const Vec3& v = mesh.vertices[mesh.triangles[f][k]];
      mn = {std::min(mn.x, v.x), std::min(mn.y, v.y), std::min(mn.z, v.z)};
      mx = {std::max(mx.x, v.x), std::max(mx.y, v.y), std::max(mx.z, v.z)};
    }
    const double a[3] = {mn.x - origin_.x, mn.y - origin_.y, mn.z - origin_.z};
    const double b[3] = {mx.x - origin_.x, mx.y - origin_.y, mx.z - origin_.z};
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::clamp(static_cast<int>(std::floor(a[d] / cell_)), 0, n_[d] - 1);
      hi[d] = std::clamp(static_cast<int>(std::floor(b[d] / cell_)), 0, n_[d] - 1);
    }
  };
  std::vector<std::uint32_t> count(n_cells + 1, 0);
  int lo[3], hi[3];
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
      cell_range(f, lo, hi);
      for (int i = lo[0]; i <= hi[0]; ++i)
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int k = lo[2]; k <= hi[2]; ++k) {
            const std::size_t c = (static_cast<std::size_t>(k) * n_[1] + j) * n_[0] + i;
            if (pass == 0)
              ++count[c + 1];
            else
              faces_[offset_[c] + count[c]++] = static_cast<std::uint32_t>(f);
          }
    }
    if (pass == 0) {
      offset_.assign(n_cells + 1, 0);
      for (std::size_t c = 0; c < n_cells; ++c)
        offset_[c + 1] = offset_[c] + count[c + 1];
      faces_.resize(offset_.back());
      std::fill(count.begin(), count.end(), 0);
    }
  }
}

NearestFace SurfaceLocator::nearest(const Vec3& p, int label) const {
  if (mesh_.revision() != revision_)
    throw std::logic_error("SurfaceLocator: the surface changed after the locator was built");
  const double rel[3] = {p.x - origin_.x, p.y - origin_.y, p.z - origin_.z};
  int home[3];
  for (int d = 0; d < 3; ++d)
    home[d] = std::clamp(static_cast<int>(std::floor(rel[d] / cell_)), 0, n_[d] - 1);
  NearestFace best;
  double best_d2 = std::numeric_limits<double>::infinity();
  const int max_shell = std::max({n_[0], n_[1], n_[2]});
  for (int s = 0; s <= max_shell; ++s) {
    if (best.face >= 0 && (s - 1) * cell_ > std::sqrt(best_d2))
      break;
    for (int k = home[2] - s; k <= home[2] + s; ++k) {
      if (k < 0 || k >= n_[2])
        continue;
      for (int j = home[1] - s; j <= home[1] + s; ++j) {
        if (j < 0 || j >= n_[1])
          continue;
        for (int i = home[0] - s; i <= home[0] + s; ++i) {
          if (i < 0 || i >= n_[0])
            continue;
          if (std::max({std::abs(i - home[0]), std::abs(j - home[1]), std::abs(k - home[2])}) != s)
            continue;
          const std::size_t c = (static_cast<std::size_t>(k) * n_[1] + j) * n_[0] + i;
          for (auto q = offset_[c]; q < offset_[c + 1]; ++q) {
            const auto f = faces_[q];
            if (label >= 0 && mesh_.face_labels[f] != label)
              continue;
            const auto& t = mesh_.triangles[f];
            const auto cp = closest_point_on_triangle(mesh_.vertices[t[0]], mesh_.vertices[t[1]],
                                                      mesh_.vertices[t[2]], p);
            const double d2 = norm2(cp.point - p);
            if (d2 < best_d2 || (d2 == best_d2 && static_cast<long>(f) < best.face)) {
              best_d2 = d2;
              best.face = f;
              best.point = cp.point;
            }
          }
        }
      }
    }
  }
  if (best.face >= 0)
    best.distance = std::sqrt(best_d2);
  return best;
}

double one_sided_distance(const SurfaceMesh& from, const SurfaceMesh& to) {
  return farthest_point(from, to).distance;
}

SurfaceGap farthest_point(const SurfaceMesh& from, const SurfaceMesh& to) {
  const SurfaceLocator locator(to);
  std::vector<int> vertex_label(from.n_vertices(), 0);
  for (std::size_t f = 0; f < from.n_faces(); ++f)
    for (const auto v : from.triangles[f])
      vertex_label[v] = from.face_labels[f];
  SurfaceGap g;
  double sum = 0;
  const auto visit = [&](const Vec3& x, int label) {
    const double d = locator.nearest(x).distance;
    sum += d;
    if (d > g.distance) {
      g.distance = d;
      g.at = x;
      g.label = label;
    }
  };
  for (std::size_t v = 0; v < from.n_vertices(); ++v)
    visit(from.vertices[v], vertex_label[v]);
  const auto centroid = face_centroids(from);
  for (std::size_t f = 0; f < from.n_faces(); ++f)
    visit(centroid[f], from.face_labels[f]);
  const std::size_t n = from.n_vertices() + from.n_faces();
  g.mean = n > 0 ? sum / double(n) : 0;
  return g;
}

UnwornOffset farthest_unworn_face(const SurfaceMesh& moved, const SurfaceMesh& original) {
  const SurfaceLocator locator(original);
  const auto centroid = face_centroids(moved);
  UnwornOffset o;
  for (std::size_t f = 0; f < moved.n_faces(); ++f)
    if (!moved.face_wears(f))
      if (const double d = locator.nearest(centroid[f]).distance; d > o.distance) {
        o.distance = d;
        o.face = std::int64_t(f);
        o.centroid = centroid[f];
        o.label = moved.face_labels[f];
      }
  return o;
}

} // namespace wear::meshes

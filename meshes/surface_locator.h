#pragma once
// Nearest face of a triangle surface to a point, through a uniform grid of the faces'
// bounding boxes searched in growing shells (not all faces). Used to transfer face fields
// between two triangulations of one surface, to measure the distance between them, and to
// find points that a moved surface would enclose.
#include "meshes/surface_mesh.h"
#include "meshes/triangle_geometry.h"

#include <cstdint>
#include <vector>

namespace wear::meshes {

struct NearestFace {
  long face = -1;      ///< -1 when no face qualifies
  Vec3 point;          ///< [m] closest point on that face
  double distance = 0; ///< [m]
};

class SurfaceLocator {
public:
  /// Keeps a reference to `mesh`, which must outlive the locator and stay unchanged.
  explicit SurfaceLocator(const SurfaceMesh& mesh);

  /// The face closest to p; with `label` >= 0 only faces of that label qualify.
  NearestFace nearest(const Vec3& p, int label = -1) const;

  std::uint64_t revision() const { return revision_; }

private:
  const SurfaceMesh& mesh_;
  std::uint64_t revision_;
  Vec3 origin_;
  double cell_ = 1; ///< [m]
  int n_[3] = {1, 1, 1};
  std::vector<std::uint32_t> offset_; ///< CSR: faces of cell c at offset_[c] .. offset_[c + 1]
  std::vector<std::uint32_t> faces_;
};

/// Largest distance from the points of `from` (vertices and face centroids) to the surface
/// `to`: the one-sided Hausdorff distance sampled at those points. [m]
double one_sided_distance(const SurfaceMesh& from, const SurfaceMesh& to);

/// The same with where it is reached, and the mean over the sampled points.
struct SurfaceGap {
  double distance = 0; ///< [m] the largest
  Vec3 at{0, 0, 0};    ///< [m] the point of `from` where it is reached
  int label = 0;       ///< of a face of `from` at that point
  double mean = 0;     ///< [m] over the vertices and face centroids of `from`
};
SurfaceGap farthest_point(const SurfaceMesh& from, const SurfaceMesh& to);

/// The face of `moved` that does not wear (FaceRole other than wearing) whose centroid lies
/// farthest from the surface `original`: how far an evolution of the worn surface moved what
/// must stay where it was. distance 0 and face -1 when every face wears.
struct UnwornOffset {
  double distance = 0; ///< [m]
  std::int64_t face = -1;
  Vec3 centroid; ///< [m] of that face
  int label = 0; ///< of that face
};
UnwornOffset farthest_unworn_face(const SurfaceMesh& moved, const SurfaceMesh& original);

} // namespace wear::meshes

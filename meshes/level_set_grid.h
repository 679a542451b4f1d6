#pragma once
// A part as an implicit function on a uniform grid: the signed distance to its closed surface,
// the distance to a receding front, the zero set as a triangle surface and the volume it
// encloses. The pieces of the implicit recession (meshes/implicit_recession.h).
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <vector>

namespace wear::meshes {

/// Node values on a uniform grid of `spacing` over [origin, origin + (n - 1) spacing]. The
/// node (i, j, k) sits at origin + spacing (i, j, k) and is stored at i + n[0] (j + n[1] k).
class LevelSetGrid {
public:
  /// A grid that covers `box` with `margin` [m] to spare on every side. Throws when the
  /// spacing is not positive or the grid would hold more than `max_nodes` nodes.
  LevelSetGrid(const BoundingBox& box, double spacing, double margin,
               std::size_t max_nodes = 200'000'000);

  Vec3 origin() const { return origin_; }
  double spacing() const { return h_; } ///< [m]
  int n(int axis) const { return n_[axis]; }
  std::size_t n_nodes() const { return std::size_t(n_[0]) * n_[1] * n_[2]; }
  std::size_t index(int i, int j, int k) const {
    return std::size_t(i) + std::size_t(n_[0]) * (std::size_t(j) + std::size_t(n_[1]) * k);
  }
  Vec3 node(int i, int j, int k) const {
    return {origin_.x + h_ * i, origin_.y + h_ * j, origin_.z + h_ * k};
  }
  Vec3 node(std::size_t index) const;
  /// The nodes whose positions lie within [lo, hi], clipped to the grid: first and last
  /// index per axis (empty when last < first).
  void node_range(const Vec3& lo, const Vec3& hi, int first[3], int last[3]) const;

  std::vector<double> value; ///< [m] one per node

private:
  Vec3 origin_;
  double h_ = 0;
  int n_[3] = {0, 0, 0};
};

/// Fills grid.value with the signed distance to the closed, outward surface `s`: exact within
/// `band` [m] of it, +-band beyond; negative inside (by the parity of a ray's crossings).
void signed_distance(const SurfaceMesh& s, LevelSetGrid& grid, double band);

/// The receding front's value at x from face f: |x - y| - depth(y), y the point of f closest to
/// x and depth(y) interpolated linearly over f from `vertex_depth` [m].
double front_value(const SurfaceMesh& s, const std::vector<double>& vertex_depth, std::size_t f,
                   const Vec3& x);

/// The point of face f's receded front nearest x on the part's side of the old surface:
/// y + depth(y) u, y the point of f closest to x and u the unit vector from y to x, turned
/// into the part where x lies outside it (the side told by `vertex_normal`, the old surface's
/// vertex normals, interpolated at y), or -n(y) where x lies on y. [m]
Vec3 inward_front_point(const SurfaceMesh& s, const std::vector<double>& vertex_depth,
                        const std::vector<Vec3>& vertex_normal, std::size_t f, const Vec3& x);

/// The receding front of a union of balls: node value g(x) = min_f front_value(f, x) over the
/// faces marked in `receding` (balls of radius depth(y) about the points y of those faces),
/// clamped to `band` where no face comes closer; the material with g < 0 is removed. `source`
/// receives the minimising face per node, `owner` the nearest receding face among those that
/// reach the node (-1 beyond every face's reach).
void receding_front(const SurfaceMesh& s, const std::vector<double>& vertex_depth,
                    const std::vector<char>& receding, LevelSetGrid& grid, double band,
                    std::vector<std::int32_t>& source, std::vector<std::int32_t>& owner);

/// The front's value at any point x and the face it comes from: the least front_value over
/// the faces that minimise it at the corners of x's grid cell (`source` of receding_front);
/// value +infinity and face -1 where no face reaches that cell.
struct FrontSample {
  double value; ///< [m]
  long face;
};
FrontSample front_at(const SurfaceMesh& s, const std::vector<double>& vertex_depth,
                     const LevelSetGrid& grid, const std::vector<std::int32_t>& source,
                     const Vec3& x);

/// Volume of {value < 0} of the piecewise-linear interpolant on the grid's tetrahedra (each
/// cube cut into six along its main diagonal). [m^3]
double negative_volume(const LevelSetGrid& grid);

/// Volume of {f < 0} in the tetrahedron `corners` for the linear f with `values` at its
/// corners (exact, closed form). [m^3]
double tetrahedron_negative_volume(const Vec3 corners[4], const double values[4]);

/// The six tetrahedra of the cell with lower corner (i, j, k): for tetrahedron t, its corners'
/// offsets as bits (x 1, y 2, z 4) of the cell's corner.
extern const int kuhn_tetrahedra[6][4];

/// A node value as the grid's interpolants read it: values within 1e-9 spacing of zero count
/// as that much positive, so that no zero crossing falls on a node.
inline double level_value(double v, double spacing) {
  const double eps = 1e-9 * spacing;
  return v < eps && v > -eps ? eps : v;
}

/// The zero set of the interpolant as a closed triangle surface (marching tetrahedra on the
/// same six tetrahedra per cell), oriented outward (towards positive values), unlabelled.
/// Node values within 1e-9 spacing of zero are taken as that much positive, so no vertex
/// falls on a node. Nodes on the grid's outer layer must be positive for it to be closed.
SurfaceMesh zero_surface(const LevelSetGrid& grid);

} // namespace wear::meshes

#pragma once
// The correspondence between the boundary faces of the deal.II triangulation and the
// triangles of the sample's SurfaceMesh (same triangles, matched by their vertex positions),
// tied to the surface's revision.
#include "meshes/surface_mesh.h"

#include <deal.II/grid/tria.h>

#include <cstdint>
#include <vector>

namespace wear::fem {

struct BoundaryFace {
  dealii::Triangulation<3>::active_cell_iterator cell;
  unsigned int face_no = 0;
};

/// The boundary of a tetrahedral triangulation as a SurfaceMesh: one triangle per boundary
/// face, oriented outward, labelled with the face's boundary id, vertices shared; its labels
/// take `roles` (a boundary id says nothing of its role).
meshes::SurfaceMesh extract_boundary_surface(const dealii::Triangulation<3>& tria,
                                             const meshes::LabelRoles& roles);

class BoundaryFaceMap {
public:
  /// Throws naming the first surface triangle without a boundary face (or a boundary face
  /// without a triangle), or a label that disagrees with the face's boundary id.
  BoundaryFaceMap(const dealii::Triangulation<3>& tria, const meshes::SurfaceMesh& surface);

  const meshes::SurfaceMesh& surface() const { return surface_; }
  /// After the triangulation's vertices moved (same cells): takes `moved` (same triangles,
  /// new revision) as the surface, with its vertices set to the triangulation's positions so
  /// the two agree bitwise. Throws when the face or vertex count differs.
  void follow(const dealii::Triangulation<3>& tria, meshes::SurfaceMesh moved);
  std::size_t size() const { return faces_.size(); }
  /// Boundary face of surface triangle f.
  const BoundaryFace& operator[](std::size_t f) const { return faces_[f]; }
  /// Triangulation vertex index of each surface vertex.
  const std::vector<unsigned int>& vertex_map() const { return vertex_; }

private:
  meshes::SurfaceMesh surface_;
  std::vector<BoundaryFace> faces_;
  std::vector<unsigned int> vertex_;
};

} // namespace wear::fem

#pragma once
// VTK XML unstructured-grid (.vtu) output for ParaView: surface meshes with per-face
// fields, particle clouds with per-point fields, tetrahedral meshes. Written atomically.
#include "meshes/face_field.h"
#include "meshes/surface_mesh.h"

#include <string>
#include <vector>

namespace wear::meshes {

/// A named array with n_components values per point or per cell.
struct VtuArray {
  std::string name;
  int n_components = 1;
  std::vector<double> values; ///< size = n_components * n_items
};

enum class VtkCell : int { vertex = 1, triangle = 5, tetra = 10 };

struct VtuGrid {
  std::vector<Vec3> points;
  VtkCell cell_type = VtkCell::triangle;
  std::vector<std::uint32_t> connectivity; ///< nodes_per_cell entries per cell
  std::vector<VtuArray> point_data, cell_data;
};

/// Throws when array sizes do not match the grid or the file cannot be written.
void write_vtu(const VtuGrid& grid, const std::string& path);

/// Surface mesh with its labels (cell array "label") and the given face fields.
void write_vtu(const SurfaceMesh& mesh, const std::string& path,
               const std::vector<const FaceField<double>*>& scalar_fields = {},
               const std::vector<const FaceField<Vec3>*>& vector_fields = {});

} // namespace wear::meshes

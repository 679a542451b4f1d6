// Reading the sample mesh into deal.II.
//
// GridIn<3>::read_msh(std::istream&) maps each gmsh physical tag to the boundary id of the
// faces it holds (the filename overload, which goes through the gmsh API, loses them on
// this deal.II build; see shared/notes/toolchain.md), so the stream overload is used.
// Volumes and areas are exact for straight-sided tetrahedra: |det J| / 6 and |cross| / 2.
#include "fem/sample_triangulation.h"

#include "meshes/surface_mesh.h"

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/reference_cell.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace wear::fem {

void read_sample_mesh(const std::string& path, dealii::Triangulation<3>& tria) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("mesh file '" + path + "' does not exist");
  std::ifstream in(path);
  dealii::GridIn<3> grid_in;
  grid_in.attach_triangulation(tria);
  try {
    grid_in.read_msh(in);
  } catch (const std::exception& e) {
    throw std::runtime_error("mesh file '" + path + "' cannot be read as a gmsh mesh: " +
                             std::string(e.what()).substr(0, 300));
  }
  for (const auto& cell : tria.active_cell_iterators())
    if (cell->reference_cell() != dealii::ReferenceCells::Tetrahedron)
      throw std::runtime_error("mesh file '" + path + "' holds a " +
                               cell->reference_cell().to_string() +
                               " cell; the sample mesh must be tetrahedral");
}

std::map<unsigned int, double> boundary_area(const dealii::Triangulation<3>& tria) {
  std::map<unsigned int, double> area;
  for (const auto& cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary()) {
        const auto face = cell->face(f);
        const auto a = face->vertex(1) - face->vertex(0), b = face->vertex(2) - face->vertex(0);
        area[face->boundary_id()] += 0.5 * dealii::cross_product_3d(a, b).norm();
      }
  return area;
}

double mesh_volume(const dealii::Triangulation<3>& tria) {
  double v = 0;
  for (const auto& cell : tria.active_cell_iterators()) {
    const auto a = cell->vertex(1) - cell->vertex(0), b = cell->vertex(2) - cell->vertex(0),
               c = cell->vertex(3) - cell->vertex(0);
    v += std::abs(a * dealii::cross_product_3d(b, c)) / 6.0;
  }
  return v;
}

} // namespace wear::fem

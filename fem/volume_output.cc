// Volume fields on the tetrahedral mesh as a VTU grid.
//
// Displacement is written at the mesh vertices: the vertex degrees of freedom of P1 or P2
// (deal.II numbers a cell's vertex DoFs first, component-wise per vertex), so a P2 field is
// shown by its vertex values. Stresses are the solver's cell averages.
#include "fem/volume_output.h"

#include "fem/mesh_motion.h"

#include <algorithm>
#include <stdexcept>

namespace wear::fem {

meshes::VtuGrid volume_grid(const dealii::Triangulation<3>& tria, const ElasticitySolver* solver) {
  meshes::VtuGrid g;
  g.cell_type = meshes::VtkCell::tetra;
  const auto& vertices = tria.get_vertices();
  g.points.reserve(vertices.size());
  for (const auto& p : vertices)
    g.points.push_back({p[0], p[1], p[2]});
  const std::size_t n_cells = tria.n_active_cells();
  g.connectivity.reserve(4 * n_cells);
  meshes::VtuArray label{"boundary label", 1, std::vector<double>(n_cells, 0)};
  for (const auto& cell : tria.active_cell_iterators()) {
    for (unsigned int k = 0; k < 4; ++k)
      g.connectivity.push_back(cell->vertex_index(k));
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        label.values[cell->active_cell_index()] =
            std::max(label.values[cell->active_cell_index()], double(cell->face(f)->boundary_id()));
  }
  meshes::VtuArray quality{"scaled Jacobian", 1, {}};
  volume_quality(tria, &quality.values);
  g.cell_data.push_back(std::move(quality));
  g.cell_data.push_back(std::move(label));
  if (!solver)
    return g;
  const auto& dof = solver->dof_handler();
  if (&dof.get_triangulation() != &tria || solver->von_mises().size() != n_cells)
    throw std::invalid_argument("volume output: the solver has not run on this triangulation");
  const auto& fe = dof.get_fe();
  meshes::VtuArray u{"displacement", 3, std::vector<double>(3 * g.points.size(), 0)};
  std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof.active_cell_iterators()) {
    cell->get_dof_indices(dofs);
    for (unsigned int j = 0; j < 4 * fe.n_dofs_per_vertex(); ++j) {
      const unsigned int k = j / fe.n_dofs_per_vertex();
      const unsigned int c = fe.system_to_component_index(j).first;
      u.values[3 * cell->vertex_index(k) + c] = solver->displacement()[dofs[j]];
    }
  }
  g.point_data.push_back(std::move(u));
  meshes::VtuArray vm{"von Mises", 1, std::vector<double>(n_cells)};
  meshes::VtuArray principal{"principal stress", 3, std::vector<double>(3 * n_cells)};
  for (std::size_t c = 0; c < n_cells; ++c) {
    vm.values[c] = solver->von_mises()[c];
    for (int i = 0; i < 3; ++i)
      principal.values[3 * c + i] = solver->principal_stresses()[i][c];
  }
  g.cell_data.push_back(std::move(vm));
  g.cell_data.push_back(std::move(principal));
  return g;
}

} // namespace wear::fem

#pragma once
// The sample's volume mesh and its fields for ParaView (VTU) and the HDF5 history: one
// plain grid shared by both writers.
#include "fem/elasticity.h"
#include "meshes/vtu_writer.h"

#include <deal.II/grid/tria.h>

namespace wear::fem {

/// Points = triangulation vertices [m], cells = tetrahedra; cell data "scaled Jacobian" [-]
/// and "boundary label" (largest boundary id of the cell's faces, 0 for interior cells);
/// with a solver that has run: point data "displacement" [m] (vertex values) and cell data
/// "von Mises" [Pa] and "principal stress" [Pa] (3 components, largest first).
meshes::VtuGrid volume_grid(const dealii::Triangulation<3>& tria,
                            const ElasticitySolver* solver = nullptr);

} // namespace wear::fem

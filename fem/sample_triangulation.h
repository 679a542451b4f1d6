#pragma once
// The sample's tetrahedral mesh as a deal.II triangulation, with boundary ids equal to the
// face labels of meshes/ (bottom = 1, side = 2, base = 3, convex element Cjk = 10 j + k).
#include <deal.II/grid/tria.h>

#include <map>
#include <string>

namespace wear::fem {

/// Reads a gmsh 4.1 `.msh` written by meshes::generate_sample. Throws naming the file when it
/// is missing or holds cells other than tetrahedra.
void read_sample_mesh(const std::string& path, dealii::Triangulation<3>& tria);

/// Total area of the boundary faces per boundary id [m^2].
std::map<unsigned int, double> boundary_area(const dealii::Triangulation<3>& tria);

/// Volume of the mesh from its tetrahedra [m^3].
double mesh_volume(const dealii::Triangulation<3>& tria);

} // namespace wear::fem

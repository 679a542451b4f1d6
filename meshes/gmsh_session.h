#pragma once
// RAII guard for the gmsh API: gmsh has one global model, so one session at a time.
#include "meshes/surface_mesh.h"

#include <string>

namespace wear::meshes {

class GmshSession {
public:
  /// Initialises gmsh quietly (set WEAR_GMSH_VERBOSE=1 to see its log) and adds a model.
  explicit GmshSession(const std::string& model_name);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

/// Boundary triangles of the current gmsh model from its 2D physical groups (physical tag =
/// label id), oriented outward, with only the vertices they use; optionally counts the
/// tetrahedra, sums their volume [m^3] and finds their smallest quality 6 sqrt(2) |V| / l_max^3
/// (1 for the regular tetrahedron, 0 flat; 1 when there are none).
SurfaceMesh gmsh_labelled_surface(std::size_t* n_tetrahedra = nullptr,
                                  double* tetrahedral_volume = nullptr,
                                  double* min_tetrahedron_quality = nullptr);

/// Writes the current model as a gmsh 4.1 ASCII `.msh` through a temporary file and a
/// rename, so a reader never sees a partial file. Throws naming the path.
void gmsh_write_msh(const std::string& path);

} // namespace wear::meshes

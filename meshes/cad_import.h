#pragma once
// Surfaces from the user's CAD and mesh files: STEP, IGES and BREP through gmsh's
// OpenCASCADE kernel, meshed to triangles of a stated size; STL as it is. A length unit per
// file scales the geometry to metres. Each CAD surface keeps its own label (its index in the
// file, as gmsh numbers it), so a case file can name surfaces (wearing, clamped, ...) by it.
#include "meshes/surface_mesh.h"

#include <string>
#include <vector>

namespace wear::meshes {

enum class LengthUnit { metre, millimetre };

/// "m" or "mm"; throws std::invalid_argument naming `what` otherwise.
LengthUnit parse_length_unit(const std::string& text, const std::string& what);
/// Metres per unit of the file: 1 or 1e-3.
double metres_per(LengthUnit unit);

struct CadImportOptions {
  LengthUnit unit = LengthUnit::metre; ///< unit of the file's coordinates
  double mesh_size = 0;                ///< [m] target triangle edge (CAD files; STL is as is)
};

struct CadSurface {
  /// [m] the triangles, labelled by CAD surface (1, 2, ... in the file's order; an STL file's
  /// labels as read_stl gives them), outward where the surface encloses a solid.
  SurfaceMesh mesh;
  std::vector<int> surface_labels;   ///< the labels present, ascending
  std::vector<double> surface_areas; ///< [m^2] per label above: the CAD kernel's exact area
                                     ///< (the triangles' for STL)
  std::size_t n_solids = 0;          ///< closed solids in the file (0 for STL)
  double solid_volume = 0;           ///< [m^3] their volume by the CAD kernel (0 for STL)
};

/// Reads `path` by its extension (.step/.stp, .iges/.igs, .brep, .stl; any case) and scales it
/// to metres. Throws std::runtime_error naming the file when it is missing or unreadable,
/// its extension unknown, or it holds no surface; std::invalid_argument when a CAD file is
/// given without a positive mesh size.
CadSurface read_cad_surface(const std::string& path, const CadImportOptions& options);

} // namespace wear::meshes

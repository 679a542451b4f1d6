#pragma once
// Surfaces from the user's CAD and mesh files: STEP, IGES and BREP through gmsh's
// OpenCASCADE kernel, meshed to triangles of a stated size; STL as it is. A length unit per
// file scales the geometry to metres. Each CAD surface keeps its own label (its index in the
// file, as gmsh numbers it), so a case file can name surfaces (wearing, clamped, ...) by it.
#include "meshes/surface_mesh.h"

#include <optional>
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
  /// [m] the geometry must lie inside (a CAD file checked on the kernel's bounding box before
  /// the meshing, so a file read in the wrong unit is refused at once; an STL file on its
  /// vertices); empty: no bound
  std::optional<BoundingBox> bounds;
};

/// Most triangles a CAD file or primitive may be meshed into: more would take minutes and
/// gigabytes, and says the mesh size or the unit is wrong.
constexpr double max_cad_triangles = 2e7;

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

/// The walls a scene builds without a file, in metres. Each is meshed by the CAD path below;
/// its faces are labelled by gmsh's surface tags (a cylinder's side 1; with caps, its end
/// discs 2 and 3).
enum class PrimitiveKind { plane, disc, cylinder, cone, box };

struct Primitive {
  PrimitiveKind kind = PrimitiveKind::plane;
  Vec3 origin;           ///< [m] plane: a corner; disc: centre; cylinder, cone: base centre; box:
                         ///< lower corner
  Vec3 edge_u, edge_v;   ///< [m] plane: its two edges from the corner (a parallelogram)
  Vec3 axis;             ///< [m] disc: normal (any length); cylinder, cone: base to top; box: size
  double radius = 0;     ///< [m] disc, cylinder; cone at its base
  double radius_top = 0; ///< [m] cone at its top (0: a pointed cone)
  double radius_inner = 0; ///< [m] disc: a central hole of this radius (an annulus; 0: none)
  bool caps = false;       ///< cylinder, cone: with the end discs (a closed solid)
};

/// The primitive meshed with triangles of at most `mesh_size` [m]. Throws
/// std::invalid_argument naming `what` and the dimension that is wrong (a radius not
/// positive, a zero axis or edge, parallel plane edges, a box with a side not positive, a
/// disc's hole not inside it).
CadSurface primitive_surface(const Primitive& p, double mesh_size, const std::string& what,
                             const std::optional<BoundingBox>& bounds = {});

/// Reads `path` by its extension (.step/.stp, .iges/.igs, .brep, .stl; any case) and scales it
/// to metres. Throws std::runtime_error naming the file when it is missing or unreadable,
/// its extension unknown, or it holds no surface; std::invalid_argument when a CAD file is
/// given without a positive mesh size, reaches outside `bounds` or would need more than
/// max_cad_triangles triangles.
CadSurface read_cad_surface(const std::string& path, const CadImportOptions& options);

} // namespace wear::meshes

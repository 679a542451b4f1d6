#pragma once
// Remeshing the worn sample: a new tetrahedral mesh of the volume bounded by the current
// (worn) boundary triangulation, rebuilt with gmsh from the discrete surface.
#include "meshes/geometry_parameters.h"
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace wear::fem {

/// Defaults declared here only; the FEM subsection of a case file sets the feature angle, the
/// chord tolerance and the tetrahedron quality (FemParameters, fem/fem_parameters.h).
struct RemeshParameters {
  /// Mesh sizes and grading of the new mesh (mesh_size, mesh_size_bottom, thickness,
  /// curvature_refinement are used), as for the unworn sample.
  meshes::SampleGeometry sizes;
  /// The grading's up direction (unit) and the height of the bottom's plane along it [m]: the
  /// height of x is dot(up, x) - up_offset (meshes::set_sample_size_field). The defaults are
  /// the sample's own frame; a sample placed in a scene gives its frame's.
  meshes::Vec3 up{0, 0, 1};
  double up_offset = 0;
  /// Edges between faces whose normals differ by more than this are kept as sharp edges;
  /// label boundaries are always kept (the sample's true sharp edges are 90 deg box edges
  /// and label boundaries; 40 deg failed on worn element tips). If gmsh fails, the remesh
  /// is retried at 20 deg more. [deg]
  double feature_angle_deg = 60;
  /// Largest gap between a new face and the curved input surface the size field aims at:
  /// curved regions get edges of sqrt(8 tolerance / curvature), down to mesh_size / 4. [m]
  double chord_tolerance = 0.02e-3;
  /// gmsh Mesh.Algorithm of the first attempt (6 frontal-Delaunay, 5 Delaunay, 1 MeshAdapt).
  int surface_algorithm = 6;
  /// An attempt whose smallest tetrahedron quality (6 sqrt(2) |V| / l_max^3) is below this
  /// is refused and the next one tried: a sliver spoils the stress near it, and mesh motion
  /// would ask for a remesh again at once. The last attempt, which keeps the worn
  /// triangles, refuses only flat tetrahedra (1e-8). [-]
  double min_tet_quality = 1e-3;
};

struct RemeshReport {
  std::size_t n_tetrahedra = 0;
  std::size_t n_faces_before = 0, n_faces_after = 0;
  std::size_t n_patches = 0;     ///< discrete surfaces gmsh reparametrised
  std::size_t n_mixed_faces = 0; ///< input faces in a patch of another label (0 expected)
  double volume_before = 0;      ///< [m^3] enclosed by the input surface
  double volume_after = 0;       ///< [m^3] sum of the new tetrahedra
  double volume_restored = 0;    ///< [m^3] after WornSample's volume-restoring offset
  /// vertex rings around a fold within which that offset was held still (0: nowhere)
  int restore_held_rings = 0;
  /// [m^3] enclosed volume the offset could not give back, because it folded or fell short
  /// of the target (new - worn)
  double volume_not_restored = 0;
  double surface_distance = 0;       ///< [m] largest distance of new surface points to the old
  std::map<int, double> area_before; ///< [m^2] per label
  std::map<int, double> area_after;  ///< [m^2] per label
  int surface_algorithm = 0;         ///< gmsh Mesh.Algorithm that succeeded (6 or 5)
  double feature_angle_deg = 0;      ///< [deg] the angle that succeeded
  std::string failed_attempts;       ///< errors of the attempts before, if any (the input
                                     ///< is then kept in `<msh_path>.refused-input.msh`)
  int attempt = 0; ///< 1 when the first attempt succeeded (1-based index of the one that did)
  /// input edges cut to open the holes of patches that projection could fold (0: none)
  std::size_t n_cut_edges = 0;
  /// [-] gmsh's planarity tolerance, raised so patches with holes are projected (0: kept)
  double planarity_tolerance = 0;
  std::size_t n_flat_flips = 0; ///< Delaunay flips in flat regions of the input
  double min_tet_quality = 0;   ///< [-] smallest 6 sqrt(2) |V| / l_max^3 (1 regular)
  double seconds = 0;
};

/// How the surface handed to remesh_sample came about, which decides how it is meshed.
enum class SurfaceKind {
  /// moved by the wear stages (relaxed, with sharpened crests): gmsh remeshes its patches
  worn,
  /// isotropic already (meshes::implicit_recession, a kept surface): its triangles are kept
  isotropic
};

/// Meshes the volume enclosed by `worn` (closed, outward, labelled, in the sample frame) and
/// writes it to `msh_path` (gmsh 4.1, physical groups as generate_sample writes them, so
/// read_sample_mesh reads it). The input faces of each label form separate discrete
/// surfaces, split further at feature edges and into patches gmsh can reparametrise (a patch
/// with holes is projected onto its plane when it is a graph over it, or else cut open, so
/// that gmsh's map does not fold it); every new face inherits its patch's label. Flat regions of
/// the input are first re-triangulated by Delaunay flips (same surface), and an attempt leaving a
/// flat tetrahedron (quality below 1e-8) fails like a gmsh error. Returns the new boundary surface
/// with revision worn.revision() + 1. Throws when the surface is not closed, gmsh fails, or a label
/// is lost. An `isotropic` surface is neither flipped nor remeshed: its triangles are kept and
/// only the volume is meshed (a flat tetrahedron refuses the first attempt only).
meshes::SurfaceMesh remesh_sample(const meshes::SurfaceMesh& worn, const RemeshParameters& p,
                                  const std::string& msh_path, RemeshReport* report = nullptr,
                                  SurfaceKind kind = SurfaceKind::worn);

/// Writes a labelled surface as a gmsh 4.1 `.msh` (one discrete surface and physical group
/// per label) that meshes::read_msh_surface reads back, e.g. a surface remeshing failed on.
void write_surface_msh(const meshes::SurfaceMesh& surface, const std::string& path);

} // namespace wear::fem

#pragma once
// Parametric wear samples (plain and convex pattern) built with gmsh's OpenCASCADE kernel.
#include "meshes/geometry_parameters.h"
#include "meshes/surface_mesh.h"

#include <map>
#include <string>
#include <vector>

namespace wear::meshes {

/// Centre of one convex element on the base top face, in the sample frame.
struct ElementSite {
  int column = 0, element = 0;   ///< 1-based; label id 10*column + element
  double x = 0, y = 0;           ///< [m]
  double semi_x = 0, semi_y = 0; ///< [m] footprint semi-axes along x (radial) and y (flow)
};

/// The element layout of docs/wear-tester.md (columns along the flow, k from the inner radius).
std::vector<ElementSite> element_sites(const SampleGeometry& s);

struct GeneratedSample {
  SurfaceMesh surface;              ///< closed, outward, labelled boundary
  std::size_t n_tetrahedra = 0;     ///< 0 without a volume mesh
  double tetrahedral_volume = 0;    ///< [m^3] sum of tetrahedron volumes
  std::map<int, double> exact_area; ///< [m^2] per label from the OpenCASCADE model
  double exact_volume = 0;          ///< [m^3] of the OpenCASCADE solid
  /// [m^3] the convex elements above the base top in the OpenCASCADE solid (its volume less
  /// the base block's); 0 for a plain sample
  double exact_element_volume = 0;
  double seconds = 0; ///< [s] wall time of the generation
};

/// Sets the sample's mesh size on the current gmsh model: a field growing linearly from
/// `mesh_size` at the wear face (height = thickness, and above) to `mesh_size_bottom` at
/// height 0, curvature refinement when asked, frontal-Delaunay surfaces and Delaunay volumes.
/// The height of a point x is dot(up, x) - up_offset: the sample frame's z by default, a
/// placed sample's own z with its up direction (unit) and the height of its bottom's plane.
/// Returns the tag of the field (the background field).
int set_sample_size_field(const SampleGeometry& s, const Vec3& up = {0, 0, 1},
                          double up_offset = 0);

/// Builds the sample, its surface with sample_roles(false); when msh_path is not empty, writes the
/// mesh (gmsh 4.1 format) there atomically, with physical groups: volume 1 "sample", surfaces by
/// label id and name. With `placement`, the mesh (surface and volume) is moved where it places the
/// sample in the tester (SampleFrame::point_to_tester) after meshing: the same triangles and
/// tetrahedra in the tester's frame (exact areas and volume are the solid's, unmoved).
GeneratedSample generate_sample(const SampleGeometry& s, const std::string& msh_path = "",
                                const SamplePlacement* placement = nullptr);

/// The meshed convex elements' volume above the base top against the CAD's, of a sample
/// generated in its own frame (no placement). A mesh coarser than the elements' footprint
/// without curvature refinement cuts the half-ellipsoids' flanks: on the reference pattern the
/// meshed elements lack 4.4 % of their volume at 1.5 mm, 14 % at 3 mm and 29 % at 5 mm; with
/// the refinement 3.0 % at 3 mm.
struct ElementVolume {
  double meshed = 0; ///< [m^3] sum over the element labels of the volume above the base top
  double exact = 0;  ///< [m^3] GeneratedSample::exact_element_volume
  /// 1 - meshed / exact, the fraction the mesh lacks (negative: it holds more); 0 without
  /// elements
  double deficit() const { return exact > 0 ? 1 - meshed / exact : 0; }
};
ElementVolume element_volume(const GeneratedSample& g, const SampleGeometry& s);

/// A warning naming the parameters of `s` when the meshed elements (`v`, element_volume) lack
/// more than `tolerance` of the CAD's volume (the elements' wear and life scale with their
/// volume), or "" when they do not.
std::string element_volume_warning(const ElementVolume& v, const SampleGeometry& s,
                                   double tolerance = 0.05);

/// The roles of the sample's labels: the underside clamped, the base top and every convex
/// element wearing, the sides held (in a holder) or free.
LabelRoles sample_roles(bool held_sides);

/// Reads a gmsh .msh file's labelled boundary triangles (2D physical groups) into a
/// SurfaceMesh oriented outward. Throws naming the file if it is missing or has no
/// surface physical groups.
SurfaceMesh read_msh_surface(const std::string& path, std::size_t* n_tetrahedra = nullptr,
                             double* tetrahedral_volume = nullptr);

} // namespace wear::meshes

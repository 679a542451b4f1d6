#pragma once
// Plain parameter structs for the geometry. coupling/ fills them from the Geometry
// subsection of a case file; meshes/ stays free of deal.II.
#include <string>

namespace wear::meshes {

/// Half-ellipsoid pattern on the sample (wear-tester.md, "The convex pattern sample").
struct ConvexPattern {
  double a = 8e-3;  ///< [m] semi-axis of the footprint along `orientation`
  double b = 2e-3;  ///< [m] other semi-axis of the footprint
  double c = 20e-3; ///< [m] radial spacing of elements in one column
  double d = 40e-3; ///< [m] spacing of columns of the same kind (column pitch is d/2)
  double h = 6e-3;  ///< [m] element height
  int n_columns = 5;
  int elements_per_column = 5;        ///< odd columns; even columns hold one less when staggered
  bool stagger = true;                ///< even columns offset radially by c/2
  bool major_along_flow = true;       ///< orientation: a along the flow (true) or radial (false)
  double first_column_offset = 20e-3; ///< [m] from the leading edge to column 1
};

/// The sample in its own frame: x radial (outward), y along the flow (downstream), z up;
/// origin at the centre of the bottom face. This frame maps onto the tester's cylindrical
/// (r, theta, z) frame without a reflection.
struct SampleGeometry {
  bool convex = true;       ///< convex pattern (true) or plain sample (false)
  double length = 0.120;    ///< [m] along the flow
  double width = 0.100;     ///< [m] radial
  double thickness = 0.010; ///< [m] base plate
  ConvexPattern pattern;
  double mesh_size = 1e-3;          ///< [m] on the wear face (base top and elements)
  double mesh_size_bottom = 4e-3;   ///< [m] at the clamped bottom face, graded linearly
  bool volume_mesh = true;          ///< false: surface mesh only (faster, for checks)
  bool curvature_refinement = true; ///< refine strongly curved element tips
};

/// Where the sample sits in the tester (wear-tester.md defaults).
struct SamplePlacement {
  double radius = 0.395;           ///< [m] of the sample centre
  double angle_deg = 75;           ///< [deg] polar angle of the sample centre in the sector
  double wear_face_height = 0.040; ///< [m] of the base top face centre above the floor
  double incline_deg = 2;          ///< [deg] leading (upstream) edge lower when positive
};

/// Walls of the 150-degree sector of the circular tester.
struct TesterGeometry {
  double inner_radius = 0.290;   ///< [m]
  double outer_radius = 0.500;   ///< [m]
  double sector_angle_deg = 150; ///< [deg]
  double wall_height = 0.350;    ///< [m] of the cylindrical walls (room for loose filling)
  double wall_mesh_size = 10e-3; ///< [m] target edge length of wall triangles
  bool consolidator = true;
  double consolidator_height = 0.130;  ///< [m] of the plate above the floor
  double consolidator_angle_deg = 135; ///< [deg] polar angle of the plate centre
  double consolidator_extent_deg = 10; ///< [deg] angular extent of the plate
};

struct GeometryParameters {
  SampleGeometry sample;
  SamplePlacement placement;
  TesterGeometry tester;
};

/// Throws std::invalid_argument naming the parameter (e.g. "Geometry/Sample/Pattern/c")
/// when a value is non-physical or the pattern does not fit on the base.
void validate(const GeometryParameters& p);
void validate(const SampleGeometry& s);

} // namespace wear::meshes

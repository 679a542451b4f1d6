#pragma once
// Plain parameter structs for the geometry, and the Geometry subsection of a case file that
// fills them (visit_parameters, meshes/parameter_visitor.h); meshes/ stays free of deal.II.
#include "meshes/parameter_visitor.h"

#include <string>

namespace wear::meshes {

/// Half-ellipsoid pattern on the sample (docs/wear-tester.md, "The convex pattern sample").
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

/// Where the sample sits in the tester (defaults: docs/wear-tester.md, "The reference case").
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
  /// The sample holder (docs/wear-tester.md): a steel frame around the sample's sides and
  /// underside, its rim flush with the wear-face edge and inclined with the sample
  /// (generate_holder); false: the sample stands bare in the bed.
  bool holder = true;
  double holder_rim_width = 10e-3; ///< [m] of the frame's walls beside and under the sample
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

// The Geometry subsection: Sample (with Pattern), Placement, Tester.

template <typename Visitor>
void visit_parameters(ConvexPattern& p, Visitor& v) {
  v.enter("Pattern");
  v.real("a", p.a, "[m] Semi-axis of the elliptical footprint along 'Orientation'.");
  v.real("b", p.b, "[m] Other semi-axis of the footprint.");
  v.real("c", p.c, "[m] Radial spacing of elements within a column.");
  v.real("d", p.d, "[m] Spacing of columns of the same kind; column pitch is d/2.");
  v.real("h", p.h, "[m] Element height above the base.");
  v.integer("Number of columns", p.n_columns, 1, 9,
            "Columns along the flow; column 1 meets the flow first.");
  v.integer("Elements per column", p.elements_per_column, 1, 9,
            "Elements in odd columns (even columns hold one less when staggered).");
  v.boolean("Stagger", p.stagger, "Offset even columns radially by c/2.");
  v.choice("Orientation", p.major_along_flow, "flow", "radial",
           "Direction of the semi-axis a: along the flow or radial.");
  v.real("First column offset", p.first_column_offset,
         "[m] Distance from the leading edge to the centre of column 1.");
  v.leave();
}

template <typename Visitor>
void visit_parameters(SampleGeometry& s, Visitor& v) {
  v.enter("Sample");
  v.choice("Type", s.convex, "convex", "plain",
           "Sample kind: 'convex' (half-ellipsoid pattern on the base) or 'plain' (base only).");
  v.real("Length", s.length, "[m] Base length along the flow direction.");
  v.real("Width", s.width, "[m] Base width in the radial direction.");
  v.real("Thickness", s.thickness, "[m] Base plate thickness; its bottom face is clamped.");
  v.real("Mesh size", s.mesh_size,
         "[m] Target element size on the wear face (base top and elements); 0.25e-3 to 2e-3.");
  v.real("Mesh size bottom", s.mesh_size_bottom,
         "[m] Element size at the clamped bottom face; the size grows linearly towards it.");
  v.boolean("Volume mesh", s.volume_mesh,
            "Generate the tetrahedral volume mesh (false: surface mesh only).");
  v.boolean("Curvature refinement", s.curvature_refinement,
            "Refine the surface mesh where the element surfaces are strongly curved.");
  visit_parameters(s.pattern, v);
  v.leave();
}

template <typename Visitor>
void visit_parameters(SamplePlacement& p, Visitor& v) {
  v.enter("Placement");
  v.real("Radius", p.radius, "[m] Radius of the sample centre in the tester.");
  v.real("Angle", p.angle_deg, "[deg] Polar angle of the sample centre within the sector.");
  v.real("Wear face height", p.wear_face_height,
         "[m] Height of the base top face centre above the floor.");
  v.real("Incline", p.incline_deg,
         "[deg] Incline along the flow; positive: leading (upstream) edge lower.");
  v.leave();
}

template <typename Visitor>
void visit_parameters(TesterGeometry& t, Visitor& v) {
  v.enter("Tester");
  v.real("Inner radius", t.inner_radius, "[m] Inner cylindrical wall.");
  v.real("Outer radius", t.outer_radius, "[m] Outer cylindrical wall.");
  v.real("Sector angle", t.sector_angle_deg, "[deg] Periodic sector simulated.");
  v.real("Wall height", t.wall_height, "[m] Height of the cylindrical walls.");
  v.real("Wall mesh size", t.wall_mesh_size, "[m] Edge length of wall triangles.");
  v.boolean("Consolidator", t.consolidator, "Include the leveller plate.");
  v.real("Consolidator height", t.consolidator_height, "[m] Plate height above the floor.");
  v.real("Consolidator angle", t.consolidator_angle_deg, "[deg] Polar angle of the plate centre.");
  v.real("Consolidator extent", t.consolidator_extent_deg, "[deg] Angular extent of the plate.");
  v.choice("Holder", t.holder, "frame", "none",
           "The sample holder: 'frame' (a non-wearing steel frame enclosing the sample's sides "
           "and underside, its rim top flush with the wear-face edge and inclined with it, so "
           "only the wear face meets the bed; the FEM holds the sides as the frame does) or "
           "'none' (the sample stands bare in the bed, sides and underside exposed).");
  v.real("Holder rim width", t.holder_rim_width,
         "[m] Wall thickness of the holder frame: the rim beside the sample and the plate "
         "under it (the laboratory's: 10 mm).");
  v.leave();
}

template <typename Visitor>
void visit_parameters(GeometryParameters& g, Visitor& v) {
  v.enter("Geometry");
  visit_parameters(g.sample, v);
  visit_parameters(g.placement, v);
  visit_parameters(g.tester, v);
  v.leave();
}

} // namespace wear::meshes

#pragma once
// The FEM subsection of a case file: the sample's material and stress solver, when and how
// the worn sample is remeshed, and where it counts as worn through. Each default is declared
// once, in the struct of the code that uses it (ElasticityParameters, WornSampleParameters,
// RemeshParameters); FemParameters holds those structs, and worn_sample_parameters()
// completes a worn sample's parameters with what a run adds.
#include "fem/elasticity.h"
#include "fem/worn_sample.h"
#include "meshes/geometry_parameters.h"
#include "meshes/parameter_visitor.h"

#include <string>

namespace wear::fem {

struct FemParameters {
  ElasticityParameters elasticity;
  /// The case file sets remesh_min_scaled_jacobian, worn_through_thickness and
  /// remesh.feature_angle_deg, remesh.chord_tolerance, remesh.min_tet_quality; the others
  /// keep their defaults, except remesh.sizes and mesh_directory, which are the run's
  /// (worn_sample_parameters()).
  WornSampleParameters worn_sample;
  /// worn_sample.evolution by name (surface_evolution below), as the case file spells it
  std::string surface_evolution = "explicit then implicit";
};

/// The evolution a Surface evolution value names ("explicit only", "explicit then
/// implicit", "implicit"); throws std::invalid_argument naming FEM/Surface evolution.
SurfaceEvolution surface_evolution(const std::string& name);

/// The worn sample's parameters of a run: those of `p`, remeshed with the mesh sizes and
/// grading of `sizes` (the unworn sample's), remeshes written to `mesh_directory`.
WornSampleParameters worn_sample_parameters(const FemParameters& p,
                                            const meshes::SampleGeometry& sizes,
                                            const std::string& mesh_directory);

/// Throws std::invalid_argument naming the parameter ("FEM/...").
void validate(const FemParameters& p);

/// The FEM subsection (meshes/parameter_visitor.h).
template <typename Visitor>
void visit_parameters(FemParameters& f, Visitor& v) {
  auto& e = f.elasticity;
  auto& w = f.worn_sample;
  v.enter("FEM");
  v.real("Youngs modulus", e.youngs_modulus, "[Pa] Sample material (PE1000: 700 MPa).");
  v.real("Poisson ratio", e.poisson_ratio, "[-] Sample material (PE1000: 0.40).");
  v.real("Yield stress", e.yield_stress, "[Pa] For the safety factor (PE1000: about 20 MPa).");
  v.unsigned_integer("Degree", e.degree, 1, 2, "Polynomial degree of the simplex elements.");
  v.real("Solver tolerance", e.relative_tolerance, "[-] Relative residual of the AMG-CG solve.");
  v.real("Stress averaging radius", e.averaging_radius,
         "[m] Radius of the ball the stress tensor is averaged over for the stress measures "
         "that converge under refinement (stages.csv: max_von_mises_ball_Pa) and for the "
         "stress-informed wear law; 0: the mean particle radius at the run's scaling factor "
         "(the coarse-graining width of the wall loads).");
  v.real("Remesh scaled Jacobian", w.remesh_min_scaled_jacobian,
         "[-] Remesh when mesh motion leaves a cell below this scaled Jacobian (or inverted).");
  v.real("Feature angle", w.remesh.feature_angle_deg,
         "[deg] Edges sharper than this are kept as edges when remeshing the worn surface.");
  v.real("Chord tolerance", w.remesh.chord_tolerance,
         "[m] Largest gap between the remeshed and the worn surface the size field aims at.");
  v.real("Remesh tetrahedron quality", w.remesh.min_tet_quality,
         "[-] A remesh attempt that leaves a tetrahedron of lower quality (6 sqrt(2) |V| / "
         "l_max^3, 1 for a regular one) is refused and the next attempt tried; the last one, "
         "which keeps the worn surface triangles, refuses only flat tetrahedra.");
  v.real("Worn-through thickness", w.worn_through_thickness,
         "[m] A wear face with a vertex closer than this to the sample's clamped bottom is worn "
         "through: no material is left there, so the wear asked of it is recorded "
         "(stages.csv: worn_through_volume_m3) and not removed.");
  v.selection("Surface evolution", f.surface_evolution,
              "explicit only|explicit then implicit|implicit",
              "How a stage's wear moves the worn surface (docs/theory.md section 6.3): "
              "'explicit only' (vertices recede along their normals in increments, halved and "
              "spread where the surface would fold; the run stops where it still folds); "
              "'explicit then implicit' (the same, and where it would still fold the rest of "
              "the stage is taken by the implicit recession: a grid's signed distance and a "
              "union of balls, which cannot fold, lets elements vanish and holes open); "
              "'implicit' (every stage so).");
  auto& i = w.implicit;
  v.enter("Implicit recession");
  v.real("Grid spacing", i.spacing,
         "[m] Spacing of the grid the implicit recession works on: the tolerance of the new "
         "worn shape where the wear passed (the old surface stays where it did not).");
  v.real("Vanish height", i.vanish_height,
         "[m] A convex element standing at most this far above its foot is worn away: its "
         "faces join the label around it (and Coupling/Worn out when = elements gone counts "
         "it gone).");
  v.real("Target edge", i.target_edge,
         "[m] Edge length of the new surface's triangles (isotropic remeshing), which the "
         "volume mesher keeps; at least twice the grid spacing.");
  v.real("Flat edge", i.flat_edge,
         "[m] 0: every new triangle has the target edge. Longer: the new surface is then "
         "coarsened where that changes its shape by little (each kept vertex within half the "
         "grid spacing, root mean square, of the planes it stands for), to edges up to this "
         "length where it is flat, while where it curves the target-edge triangles stay, so "
         "a worn element's remnant narrower than this is kept: fewer faces for the DEM's wall "
         "and the kept checkpoints.");
  v.real("Step depth", w.implicit_step_depth,
         "[m] 0: the implicit recession takes a stage in one step. Positive: in as many steps "
         "as make the deepest face recede at most this far in each (at most 16). One step "
         "removes a union of balls, and at a concave edge between faces of different depths "
         "(an element's foot) the deeper faces' balls reach past the shallower ones' depth, by "
         "an amount that grows with the square of the step's depth; smaller steps shrink that "
         "error in proportion, at the cost of one recession each.");
  v.real("Volume tolerance", i.volume_tolerance,
         "[-] Relative tolerance of each wearing label's removed volume.");
  v.leave();
  v.leave();
}

} // namespace wear::fem

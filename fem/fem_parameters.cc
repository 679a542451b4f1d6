// Validation of the FEM parameters and the worn sample's parameters of a run. The checks
// are physical sense (positive moduli, Poisson ratio below 1/2, angles and qualities in
// range); each failure names the case-file parameter.
#include "fem/fem_parameters.h"

#include <cmath>
#include <stdexcept>

namespace wear::fem {

WornSampleParameters worn_sample_parameters(const FemParameters& p,
                                            const meshes::SampleGeometry& sizes,
                                            const std::string& mesh_directory) {
  WornSampleParameters w = p.worn_sample;
  w.evolution = surface_evolution(p.surface_evolution);
  w.remesh.sizes = sizes;
  w.mesh_directory = mesh_directory;
  return w;
}

SurfaceEvolution surface_evolution(const std::string& name) {
  if (name == "explicit only")
    return SurfaceEvolution::explicit_only;
  if (name == "explicit then implicit")
    return SurfaceEvolution::explicit_then_implicit;
  if (name == "implicit")
    return SurfaceEvolution::implicit;
  throw std::invalid_argument("FEM/Surface evolution: '" + name +
                              "' is none of explicit only, explicit then implicit, implicit");
}

void validate(const FemParameters& p) {
  const auto require = [](bool ok, const std::string& parameter, const std::string& what) {
    if (!ok)
      throw std::invalid_argument(parameter + ": " + what);
  };
  const auto& e = p.elasticity;
  require(e.youngs_modulus > 0 && std::isfinite(e.youngs_modulus), "FEM/Youngs modulus",
          "must be positive [Pa]");
  require(e.poisson_ratio > -1 && e.poisson_ratio < 0.5, "FEM/Poisson ratio",
          "must lie in (-1, 0.5)");
  require(e.yield_stress > 0, "FEM/Yield stress", "must be positive [Pa]");
  require(e.degree == 1 || e.degree == 2, "FEM/Degree", "must be 1 or 2");
  require(e.relative_tolerance > 0 && e.relative_tolerance < 1e-2, "FEM/Solver tolerance",
          "must lie in (0, 1e-2)");
  require(e.averaging_radius >= 0 && std::isfinite(e.averaging_radius),
          "FEM/Stress averaging radius", "must be 0 (the mean particle radius) or positive [m]");
  const auto& w = p.worn_sample;
  require(w.remesh_min_scaled_jacobian > 0 && w.remesh_min_scaled_jacobian < 1,
          "FEM/Remesh scaled Jacobian", "must lie in (0, 1)");
  require(w.remesh.feature_angle_deg > 0 && w.remesh.feature_angle_deg < 180, "FEM/Feature angle",
          "must lie in (0, 180) degrees");
  require(w.remesh.chord_tolerance > 0, "FEM/Chord tolerance", "must be positive [m]");
  require(w.remesh.min_tet_quality > 0 && w.remesh.min_tet_quality < 1,
          "FEM/Remesh tetrahedron quality", "must lie in (0, 1)");
  require(w.worn_through_thickness > 0, "FEM/Worn-through thickness", "must be positive [m]");
  surface_evolution(p.surface_evolution);
  const auto& i = w.implicit;
  require(i.spacing > 0 && i.spacing < i.max_edge, "FEM/Implicit recession/Grid spacing",
          "must be positive and below the coarsening's longest edge, " +
              std::to_string(i.max_edge * 1e3) + " mm [m]");
  require(i.vanish_height >= 0 && std::isfinite(i.vanish_height),
          "FEM/Implicit recession/Vanish height", "must be >= 0 [m]");
  require(i.target_edge >= 2 * i.spacing && std::isfinite(i.target_edge),
          "FEM/Implicit recession/Target edge", "must be at least twice the grid spacing [m]");
  require(i.flat_edge == 0 || (i.flat_edge > i.target_edge && std::isfinite(i.flat_edge)),
          "FEM/Implicit recession/Flat edge", "must be 0 or longer than the target edge [m]");
  require(w.implicit_step_depth >= 0 && std::isfinite(w.implicit_step_depth),
          "FEM/Implicit recession/Step depth", "must be >= 0 [m]");
  require(i.volume_tolerance > 0 && i.volume_tolerance < 0.1,
          "FEM/Implicit recession/Volume tolerance", "must lie in (0, 0.1)");
}

} // namespace wear::fem

#pragma once
// Parameters of a coupled run (case file subsections "Coupling" and "FEM"): the stage
// schedule and its schemes, the declared wear amplification and its cap, checkpoints, the
// optional stress-informed wear law, and the FEM material and remeshing settings.
#include "fem/elasticity.h"
#include "fem/worn_sample.h"

#include <string>
#include <vector>

namespace wear::coupling {

/// How one stage changes the geometry.
enum class Scheme {
  staged,    ///< DEM, wear, FEM stress, recession, mesh motion or remeshing; new surface to DEM
  reference, ///< node-moving inside the DEM (model.md section 5), no FEM; stops at distortion
  dem_only   ///< DEM and wear evaluation on a fixed geometry (settling, steady state)
};
std::string scheme_name(Scheme s);

struct ScheduleItem {
  int n_stages = 1;
  Scheme scheme = Scheme::staged;
};

/// Stress-informed Archard law, a hypothesis to test: the wear coefficient on a face is
/// scaled by 1 + sensitivity (sigma_vM / reference stress)^exponent, sigma_vM being the von
/// Mises stress of the face's cell in the previous stage (none in the first).
struct StressInformedWear {
  bool enabled = false;
  double sensitivity = 1;         ///< [-]
  double reference_stress = 20e6; ///< [Pa]
  double exponent = 1;            ///< [-]
  double factor(double von_mises) const;
};

struct CouplingParameters {
  std::string schedule = "2 staged";   ///< "N scheme, N scheme, ..." in order
  int revolutions_per_stage = 1;       ///< DEM revolutions per stage
  double amplification = 1;            ///< [-] declared factor on the removed volume
  double max_depth_fraction = 0.5;     ///< [-] of the longest edge at a vertex, per stage
  bool adaptive_amplification = false; ///< lower a stage's amplification to meet the cap
  double min_amplification = 1;        ///< [-] below it an adaptive stage stops the run
  double push_tolerance = 0.01;        ///< [-] of the radius: overlaps above it are pushed out
  bool checkpoints = true;             ///< after every stage (staged and dem-only schemes)
  StressInformedWear stress_informed;
};

struct FemParameters {
  fem::ElasticityParameters elasticity;
  double remesh_min_scaled_jacobian = 0.01; ///< [-]
  double feature_angle_deg = 60;            ///< [deg] sharp edges kept when remeshing
  double chord_tolerance = 0.02e-3;         ///< [m] of the remeshed surface
  double remesh_min_tet_quality = 1e-3;     ///< [-] a remesh attempt below it is refused
  double worn_through_thickness = 1e-3;     ///< [m] wear faces this close to the bottom are gone
};

/// The schedule as items; throws std::invalid_argument naming "Coupling/Schedule".
std::vector<ScheduleItem> parse_schedule(const std::string& text);
/// Throws std::invalid_argument naming the parameter ("Coupling/...", "FEM/...").
void validate(const CouplingParameters& c, const FemParameters& f);

} // namespace wear::coupling

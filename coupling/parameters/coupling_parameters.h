#pragma once
// Parameters of a coupled run (case file subsection "Coupling", declared beside the structs
// by visit_parameters, meshes/parameter_visitor.h): the stage schedule and its schemes, the
// declared wear amplification and its cap, checkpoints, the optional stress-informed wear
// law. The FEM subsection is fem's (fem/fem_parameters.h).
#include "fem/fem_parameters.h"
#include "meshes/parameter_visitor.h"

#include <string>
#include <vector>

namespace wear::coupling {

/// How one stage changes the geometry.
enum class Scheme {
  staged,    ///< DEM, wear, FEM stress, recession, mesh motion or remeshing; new surface to DEM
  reference, ///< node-moving inside the DEM (docs/theory.md section 5), no FEM; stops at distortion
  dem_only   ///< DEM and wear evaluation on a fixed geometry (settling, steady state)
};
std::string scheme_name(Scheme s);
/// The scheme's number in stored records (checkpoint.h5, history.h5): staged 0, reference 1,
/// dem-only 2. scheme_from_index throws for any other number.
int scheme_index(Scheme s);
Scheme scheme_from_index(int index);

struct ScheduleItem {
  int n_stages = 1;
  Scheme scheme = Scheme::staged;
};

/// Stress-informed Archard law, a hypothesis to test: the wear coefficient on a face is
/// scaled by 1 + sensitivity (sigma_vM / reference stress)^exponent, sigma_vM being the von
/// Mises stress of the previous stage (none in the first) averaged over a ball of
/// FEM/Stress averaging radius at the face (fem/stress_measures.h). The factor is
/// part of the wear increment (coupling/loop/wear_increment.h, stress_factor).
struct StressInformedWear {
  bool enabled = false;
  double sensitivity = 1;         ///< [-]
  double reference_stress = 20e6; ///< [Pa]
  double exponent = 1;            ///< [-]
};

/// When a wearing part counts as worn out, which ends the run after that stage
/// (Coupling/Worn out when; the figures are meshes::part_life's).
enum class WornOutCriterion {
  never,         ///< the schedule runs to its end
  elements_gone, ///< no convex element stands higher than the vanish height
  thickness,     ///< the thinnest point under the wear reaches Worn-out thickness
  worn_through   ///< the wear has removed clamped area (a hole through the part)
};
/// The criterion a Worn out when value names; throws std::invalid_argument naming it.
WornOutCriterion worn_out_criterion(const std::string& name);

struct CouplingParameters {
  std::string schedule = "2 staged";   ///< "N scheme, N scheme, ..." in order
  int revolutions_per_stage = 1;       ///< DEM revolutions per stage
  double amplification = 1;            ///< [-] declared factor on the removed volume
  double max_depth_fraction = 10;      ///< [-] of the longest edge at a vertex, per stage
  bool adaptive_amplification = false; ///< lower a stage's amplification to meet the cap
  double min_amplification = 1;        ///< [-] below it an adaptive stage stops the run
  double push_tolerance = 0.01;        ///< [-] of the radius: overlaps above it are pushed out
  bool checkpoints = true;             ///< after every stage (staged and dem-only schemes)
  StressInformedWear stress_informed;
  std::string worn_out_when = "never"; ///< a WornOutCriterion's name
  double worn_out_thickness = 0;       ///< [m] with worn_out_when = thickness
  double hours_per_revolution = 0;     ///< [h] laboratory time of a revolution (0: not stated)
};

/// The schedule as items; throws std::invalid_argument naming "Coupling/Schedule".
std::vector<ScheduleItem> parse_schedule(const std::string& text);
/// Throws std::invalid_argument naming the parameter ("Coupling/...", "FEM/...").
void validate(const CouplingParameters& c, const fem::FemParameters& f);

/// The Stress-informed wear subsection of Coupling.
template <typename Visitor>
void visit_parameters(StressInformedWear& s, Visitor& v) {
  v.enter("Stress-informed wear");
  v.boolean("Enabled", s.enabled,
            "Hypothesis to test, off by default: scale the wear coefficient per face by "
            "1 + Sensitivity (sigma_vM / Reference stress)^Exponent, sigma_vM the von Mises "
            "stress of the previous stage averaged over a ball of FEM/Stress averaging radius "
            "centred at the face.");
  v.real("Sensitivity", s.sensitivity, "[-] Scale of the stress term.");
  v.real("Reference stress", s.reference_stress,
         "[Pa] Stress that doubles the coefficient at Sensitivity 1.");
  v.real("Exponent", s.exponent, "[-] Exponent of the stress ratio.");
  v.leave();
}

/// The Coupling subsection.
template <typename Visitor>
void visit_parameters(CouplingParameters& k, Visitor& v) {
  v.enter("Coupling");
  v.text("Schedule", k.schedule,
         "Stages of `wearsim run`, in order, as 'N scheme' items separated by commas, e.g. "
         "'6 dem-only, 10 staged'. Schemes: 'staged' (DEM on the current surface, wear per "
         "face, FEM stress under the stage-averaged face loads, recession, mesh motion or "
         "remeshing, the new surface back to the DEM with the bed kept); 'reference' (the "
         "node-moving method inside the DEM, no FEM: shows where a fixed mesh distorts; runs "
         "alone); 'dem-only' (no geometry change: settling, steady state).");
  v.integer("Revolutions per stage", k.revolutions_per_stage, 1, 100000,
            "DEM revolutions per stage (one revolution = one pass through the sector).");
  v.real("Amplification", k.amplification,
         "[-] Declared wear-amplification factor on the removed volume of every stage (1: "
         "physical); recorded in every output. In `wearsim run` it also replaces "
         "Deformation/Amplification for the reference scheme.");
  v.real("Maximum depth fraction", k.max_depth_fraction,
         "[-] Largest recession one stage may ask at a surface vertex (removed volume over "
         "area of the wear faces around it), as a fraction of the longest edge there, at most "
         "10 (the wear stage splits itself where the surface would fold); a stage asking for "
         "more stops the run (lower the amplification or the revolutions per stage), or, with "
         "Adaptive amplification, runs at a lower amplification. The default 10 lets the "
         "reference sample run at amplification 1: its curvature-refined element tips ask up "
         "to 7 edge lengths per revolution.");
  v.boolean("Adaptive amplification", k.adaptive_amplification,
            "A staged stage that would ask more than Maximum depth fraction at a vertex "
            "runs at the amplification that brings that vertex to the cap, A_stage = A x "
            "cap / fraction, instead of stopping the run (the step control of wear "
            "simulations: the wear of a step extrapolated only as far as the geometry "
            "allows). Each stage's amplification is recorded (stages.csv, summary.csv) and "
            "the equivalent test time follows it.");
  v.real("Minimum amplification", k.min_amplification,
         "[-] With Adaptive amplification, a stage that would need less than this stops the "
         "run as without it.");
  v.real("Push tolerance", k.push_tolerance,
         "[-] After a geometry update, particles the new surface overlaps by more than this "
         "fraction of their radius are pushed out to zero overlap (and counted).");
  v.boolean("Checkpoints", k.checkpoints,
            "Write checkpoint.h5 after every stage (atomically) so `wearsim run --resume` "
            "can continue a killed run bit for bit.");
  v.selection("Worn out when", k.worn_out_when, "never|elements gone|thickness|worn through",
              "When a wearing part is worn out, which ends the run after that stage with "
              "'worn out at N h' (each stage writes the part's life to part_life.csv: every "
              "convex element's height above its foot and volume, the part's thinnest point "
              "and volume): 'never' (the schedule runs to its end); 'elements gone' (no convex "
              "element stands higher than FEM/Implicit recession/Vanish height above its "
              "foot); 'thickness' (the thinnest point above the clamped bottom "
              "reaches Worn-out thickness); 'worn through' (the wear has removed clamped area: "
              "a hole through the part).");
  v.real("Worn-out thickness", k.worn_out_thickness,
         "[m] With Worn out when = thickness: the remaining thickness at which the part is "
         "worn out.");
  v.real("Hours per revolution", k.hours_per_revolution,
         "[h] Laboratory time one DEM revolution at amplification 1 stands for (the "
         "calibration's time scale, docs/theory.md section 4: 28 h for the reference study's "
         "calibrated alpha). The life is reported in equivalent hours, the sum over staged "
         "stages of revolutions x amplification x this; 0: not stated, equivalent revolutions "
         "only.");
  visit_parameters(k.stress_informed, v);
  v.leave();
}

} // namespace wear::coupling

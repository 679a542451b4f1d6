// Consistency checks of a whole case (case_consistency.h), run by read_case before anything
// is written or filled. Each check below refuses only a combination that cannot work:
//
// - The sample inside the periodic sector: its footprint spans the polar angles
//   Angle +- atan((L/2) / (R - W/2)) (the inner corners reach furthest; L and W grown by the
//   holder's rim on each side when it has one), plus half a largest particle of clearance as
//   an arc at that radius; past a cut the sample wall would be cut off
//   (the cut faces are periodic, the sample is not). The consolidator likewise, and its plate
//   must pass above the sample where both share polar angles.
// - The bed: the settled height below the walls; the insertion region (Loose factor x Fill
//   height, capped at the wall height) holding phi_ins = phi_assumed x H_fill / z_top of solid,
//   at most insertion_fraction_limit (random insertion jams near 0.38); the bed reaching above
//   the wear face, or nothing wears.
// - The depth cap of a staged stage (docs/coupling.md, "The depth cap before a run starts").
//   The deepest vertex recedes by at least the wear faces' mean depth: with W_v the wear-face
//   area around vertex v, sum_v W_v D_v = 3 sum_f dV_f and sum_v W_v = 3 sum_f A_f, so
//   max_v D_v / e_v >= (sum dV / sum A) / e_bar, e_bar the W-weighted mean longest edge at a
//   vertex (1.00 to 1.15 Mesh size on the shipped samples; edge_length_bound = 1.5). The mean
//   depth of a stage is estimated as d = A c p s: p = rho phi g (H_fill - z_face) the bed's
//   hydrostatic pressure, s = Theta R N the path of the bed past the sample at the floor's
//   speed over N revolutions, c the law's coefficient (Archard alpha; the frictional-work law's
//   coefficient times the particle-wall friction, |F_t . v_t| <= mu F_n |v_t|). Measured wear
//   is 0.07 to 0.9 of this estimate (the bed slips over the sample slower than the floor
//   turns); the check uses depth_efficiency_floor = 0.01, so f_min = 0.01 d / (1.5 h) is a
//   lower bound of the stage's largest depth fraction. A stage is refused when f_min exceeds
//   Maximum depth fraction at the declared amplification, or, with Adaptive amplification, at
//   Minimum amplification. The deepest vertices of measured stages asked 10^3 to 10^5 times
//   f_min (element tips, the exposed edge: the wear of many contacts on a few small faces),
//   which no a-priori bound can foresee: Adaptive amplification handles them at run time.
// - Worn-through thickness below the sample's thickness, or every wear face starts worn through.
// - A scene's Fill/Count no larger than its region holds at the densest packing of spheres
//   of the size distribution's smallest diameter (dem::require_fill_count_fits; a mesh region
//   is checked when its file is read, at the run's set-up): a larger count made the insertion
//   try for minutes before it gave up.
// - Pattern elements no slenderer than gmsh meshes: h over the smaller footprint semi-axis at
//   most 7 (6 meshed in 5 to 21 s; 8, 10, 12 did not finish in a minute, 10 not in 15 min).
//
// Warnings (the run works): more DEM threads than cores (the same results as on that many
// cores, at a fraction of the speed: threads sharing a core spin at each other's barriers);
// steady-state settings a run cannot meet; a mesh coarser than the elements it should show.
#include "coupling/parameters/case_consistency.h"

#include "meshes/constants.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace wear::coupling {

namespace {
constexpr double gravity = 9.81;              ///< [m/s^2]
constexpr double max_element_slenderness = 7; ///< [-] h / min(a, b) that gmsh still meshes

std::string num(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", x);
  return s;
}

void refuse(const std::string& what) {
  throw std::invalid_argument(what);
}

double deg(double rad) {
  return rad * 180 / pi;
}

bool has_scheme(const CouplingParameters& c, Scheme s) {
  for (const auto& item : parse_schedule(c.schedule))
    if (item.scheme == s)
      return true;
  return false;
}

/// [rad] Half the polar angle the sample's footprint (in its holder, when it has one) spans,
/// with half a largest particle of clearance at the inner corners.
double sample_half_angle(const CaseParameters& p) {
  const auto& s = p.geometry.sample;
  const auto& t = p.geometry.tester;
  const double rim = t.holder ? t.holder_rim_width : 0;
  const double inner = p.geometry.placement.radius - s.width / 2 - rim;
  return std::atan2(s.length / 2 + rim, inner) + 0.5 * p.dem.psd.max_diameter() / inner;
}

void check_sample_in_sector(const CaseParameters& p) {
  const auto& t = p.geometry.tester;
  if (t.sector_angle_deg >= 360)
    return; // a full annulus has no cut
  const double half = deg(sample_half_angle(p));
  const double angle = p.geometry.placement.angle_deg;
  if (angle - half > 0 && angle + half < t.sector_angle_deg)
    return;
  std::string fix = 2 * half < t.sector_angle_deg
                        ? "set Geometry/Placement/Angle = " + num(t.sector_angle_deg / 2)
                        : "set Geometry/Tester/Sector angle to at least " + num(2 * half + 1) +
                              " and Geometry/Placement/Angle to half of it";
  refuse("Geometry/Placement/Angle (" + num(angle) + " deg) and Geometry/Tester/Sector angle (" +
         num(t.sector_angle_deg) + " deg): the sample spans " + num(angle - half) + " to " +
         num(angle + half) +
         " deg (with half a largest particle of clearance), not inside the "
         "periodic sector 0 to " +
         num(t.sector_angle_deg) + " deg; the cut faces would cut the sample wall off; " + fix);
}

void check_consolidator(const CaseParameters& p) {
  const auto& t = p.geometry.tester;
  if (!t.consolidator)
    return;
  const double half = t.consolidator_extent_deg / 2, angle = t.consolidator_angle_deg;
  if (t.sector_angle_deg < 360 && !(angle - half > 0 && angle + half < t.sector_angle_deg))
    refuse("Geometry/Tester/Consolidator angle (" + num(angle) + " deg, extent " + num(2 * half) +
           " deg) lies outside the periodic sector 0 to " + num(t.sector_angle_deg) +
           " deg (Geometry/Tester/Sector angle); set Consolidator angle = " +
           num(t.sector_angle_deg / 2) + " or Geometry/Tester/Consolidator = false");
  const auto& s = p.geometry.sample;
  const auto& pl = p.geometry.placement;
  const double sample_half = deg(sample_half_angle(p));
  const double top = pl.wear_face_height + (s.convex ? s.pattern.h : 0) +
                     s.length / 2 * std::sin(std::abs(pl.incline_deg) * pi / 180);
  const bool over_sample = std::abs(angle - pl.angle_deg) < half + sample_half;
  if (over_sample && t.consolidator_height <= top)
    refuse("Geometry/Tester/Consolidator height (" + num(t.consolidator_height) +
           " m) is not above the sample's top (" + num(top) +
           " m), and the plate passes over the sample (Geometry/Tester/Consolidator angle " +
           num(angle) + " deg, Geometry/Placement/Angle " + num(pl.angle_deg) +
           " deg); raise Consolidator height above " + num(top) + " m or move the plate");
}

void check_bed(const CaseParameters& p) {
  const auto& d = p.dem;
  const auto& t = p.geometry.tester;
  if (d.fill_height >= t.wall_height)
    refuse("DEM/Fill height (" + num(d.fill_height) + " m) reaches Geometry/Tester/Wall height (" +
           num(t.wall_height) +
           " m): the bed would spill over the walls; lower Fill height (the "
           "reference: 0.13 m in walls of 0.35 m) or raise Wall height to Loose factor x Fill "
           "height, " +
           num(d.loose_factor * d.fill_height) + " m");
  const double z_top = std::min(d.loose_factor * d.fill_height, t.wall_height);
  const double loose = d.assumed_packing * d.fill_height / z_top;
  // 10 % above the height that just reaches the limit, so the suggestion is not on the edge.
  const double needed = 1.1 * d.assumed_packing * d.fill_height / insertion_fraction_limit;
  if (loose > insertion_fraction_limit)
    refuse("DEM/Fill height (" + num(d.fill_height) + " m) at DEM/Assumed packing (" +
           num(d.assumed_packing) + ") does not fit loosely below " + num(z_top) +
           " m (DEM/Loose factor x Fill height, capped at Geometry/Tester/Wall height): the "
           "insertion region would be " +
           num(loose) + " solid, above the " + num(insertion_fraction_limit) +
           " random insertion can reach; set Loose factor to "
           "at least " +
           num(needed / d.fill_height) + " with Wall height above " + num(needed) +
           " m, or lower Fill height");
  const double face = p.geometry.placement.wear_face_height;
  if (d.fill_height <= face)
    refuse("DEM/Fill height (" + num(d.fill_height) +
           " m) does not reach the wear face (Geometry/Placement/Wear face height " + num(face) +
           " m): no particle would press on it and nothing would wear; set Fill height above " +
           num(face + 2 * d.psd.max_diameter()) + " m (the reference: 0.13)");
}

void check_element_shape(const meshes::SampleGeometry& s) {
  if (!s.convex)
    return;
  const double narrow = std::min(s.pattern.a, s.pattern.b);
  if (s.pattern.h <= max_element_slenderness * narrow)
    return;
  refuse("Geometry/Sample/Pattern/h (" + num(s.pattern.h) + " m) over the footprint's smaller " +
         "semi-axis (Pattern/a, Pattern/b: " + num(narrow) + " m) is " + num(s.pattern.h / narrow) +
         ": gmsh does not finish meshing elements slenderer than " + num(max_element_slenderness) +
         "; set Pattern/h to at most " + num(max_element_slenderness * narrow) +
         " m or widen the footprint");
}

void check_worn_through(const CaseParameters& p) {
  const double t = p.geometry.sample.thickness;
  const double w = p.fem.worn_sample.worn_through_thickness;
  if (w < t)
    return;
  refuse("FEM/Worn-through thickness (" + num(w) + " m) is not below Geometry/Sample/Thickness (" +
         num(t) +
         " m): every wear face would count as worn through from the start and nothing "
         "would be removed; set Worn-through thickness below " +
         num(t) + " m (the default: 0.001)");
}

std::string coefficient_name(const std::string& model) {
  const auto laws = dem::wear_laws_of(model); // the first law's, of a sum
  if (!laws.front()->parameters.empty())
    return "Wear law/" + laws.front()->parameters.front().name;
  return "Wear law/Model";
}

void check_depth_cap(const CaseParameters& p) {
  const auto& c = p.coupling;
  if (!has_scheme(c, Scheme::staged))
    return;
  const StageDepthEstimate e = stage_depth_estimate(p);
  if (!e.known)
    return;
  const double lowest = c.adaptive_amplification ? c.min_amplification : c.amplification;
  const double f = e.fraction_lower_bound * lowest / c.amplification;
  if (f <= c.max_depth_fraction)
    return;
  const std::string which =
      c.adaptive_amplification ? "Coupling/Minimum amplification" : "Coupling/Amplification";
  refuse(which + " (" + num(lowest) + ") with Coupling/Revolutions per stage (" +
         std::to_string(c.revolutions_per_stage) + "), " + coefficient_name(p.wear_law.model) +
         " (" + num(e.coefficient) + ") and Geometry/Sample/Mesh size (" +
         num(p.geometry.sample.mesh_size) +
         " m): every staged stage would recede its deepest "
         "vertex by at least " +
         num(f) +
         " of its longest edge (a lower bound from the bed's "
         "pressure " +
         num(e.pressure) + " Pa and path " + num(e.path) +
         " m per stage), "
         "more than Coupling/Maximum depth fraction (" +
         num(c.max_depth_fraction) + ") allows; " + which + " at most " +
         num(lowest * c.max_depth_fraction / f) +
         " passes this check (measured stages asked 10^3 to 10^5 times this bound at element "
         "tips and edges: see Coupling/Adaptive amplification)");
}

int hardware_threads() {
  return int(std::thread::hardware_concurrency());
}

void warn_threads(const dem::TesterDemParameters& d, std::vector<std::string>& warnings) {
  const int cores = hardware_threads();
  if (cores <= 0 || d.n_threads <= cores)
    return;
  warnings.push_back("DEM/Threads (" + std::to_string(d.n_threads) + ") exceeds the " +
                     std::to_string(cores) + " cores here: the results are those of " +
                     std::to_string(d.n_threads) +
                     " threads, but threads sharing a core wait "
                     "for each other at every step (many times slower); set Threads = 0 (all "
                     "cores) unless this run must repeat one made with " +
                     std::to_string(d.n_threads) + " threads");
}

void warn_steady_state(const CaseParameters& p, std::vector<std::string>& warnings) {
  const auto& d = p.dem;
  if (d.revolutions_after_steady > 0 &&
      d.revolutions < d.steady_revolutions + d.revolutions_after_steady)
    warnings.push_back("DEM/Revolutions (" + std::to_string(d.revolutions) +
                       ") is below DEM/Steady revolutions + DEM/Revolutions after steady (" +
                       std::to_string(d.steady_revolutions + d.revolutions_after_steady) +
                       "): `wearsim dem` ends before it could stop after steady state");
  int settling = 0; // revolutions of the dem-only stages before the first staged one
  bool staged = false;
  for (const auto& item : parse_schedule(p.coupling.schedule)) {
    if (item.scheme == Scheme::staged) {
      staged = true;
      break;
    }
    settling += item.n_stages * p.coupling.revolutions_per_stage;
  }
  if (staged && settling > 0 && settling < d.steady_revolutions)
    warnings.push_back("the dem-only stages before the first staged stage of Coupling/Schedule "
                       "run " +
                       std::to_string(settling) +
                       " revolution(s), fewer than "
                       "DEM/Steady revolutions (" +
                       std::to_string(d.steady_revolutions) +
                       "): the coupling starts before the flow can be judged steady");
}

void warn_coarse_elements(const meshes::SampleGeometry& s, std::vector<std::string>& warnings) {
  const double width = 2 * std::min(s.pattern.a, s.pattern.b);
  if (!s.convex || s.curvature_refinement || s.mesh_size <= width)
    return;
  warnings.push_back("Geometry/Sample/Mesh size (" + num(s.mesh_size) +
                     " m) exceeds the elements' footprint width (" + num(width) +
                     " m, 2 x Pattern/b) without Geometry/Sample/Curvature refinement: the "
                     "meshed elements lose volume (30 % at 5 mm on the reference pattern); set "
                     "Curvature refinement = true or Mesh size <= " +
                     num(width));
}
} // namespace

StageDepthEstimate stage_depth_estimate(const CaseParameters& p) {
  StageDepthEstimate e;
  const auto& law = p.wear_law;
  if (law.model == "archard")
    e.coefficient = law.archard_coefficient;
  else if (law.model == "frictional-work")
    e.coefficient = law.work_coefficient * p.dem.particle_wall.friction;
  else
    return e;
  e.known = true;
  const auto& d = p.dem;
  const double column = std::max(0.0, d.fill_height - p.geometry.placement.wear_face_height);
  e.pressure = d.particle.density * d.assumed_packing * gravity * column;
  e.path = p.geometry.tester.sector_angle_deg * pi / 180 * p.geometry.placement.radius *
           p.coupling.revolutions_per_stage;
  e.mean_depth = p.coupling.amplification * e.coefficient * e.pressure * e.path;
  e.fraction_lower_bound =
      depth_efficiency_floor * e.mean_depth / (edge_length_bound * p.geometry.sample.mesh_size);
  return e;
}

std::vector<std::string> check_consistency(const CaseParameters& p) {
  check_sample_in_sector(p);
  check_consolidator(p);
  check_bed(p);
  check_element_shape(p.geometry.sample);
  if (has_scheme(p.coupling, Scheme::staged))
    check_worn_through(p);
  check_depth_cap(p);
  dem::require_fill_count_fits(p.scene, p.dem.psd); // a box's or cylinder's; a mesh's at set-up
  std::vector<std::string> warnings;
  warn_threads(p.dem, warnings);
  if (p.scene.walls.empty()) // a scene's stages are seconds, not the tester's revolutions
    warn_steady_state(p, warnings);
  warn_coarse_elements(p.geometry.sample, warnings);
  return warnings;
}

} // namespace wear::coupling

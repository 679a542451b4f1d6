// The Scene subsection's own checks (scene_parameters.h): names, list lengths, signs; and a
// fill's count against what its region can hold at the densest packing of spheres.
#include "dem/scene/scene_parameters.h"

#include "dem/scene/wall_catalogue.h"

#include "meshes/constants.h"
#include "meshes/surface_mesh.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

std::string scene_wall_path(const SceneWallParameters& w) {
  return "Scene/Wall " + w.name;
}

std::optional<std::size_t> scene_wall_index(const SceneParameters& s, const std::string& name) {
  for (std::size_t k = 0; k < s.walls.size(); ++k)
    if (s.walls[k].name == name)
      return k;
  return std::nullopt;
}

meshes::Vec3 scene_vector(const std::vector<double>& v) {
  return {v.at(0), v.at(1), v.at(2)};
}

std::vector<std::string> scene_names(const std::string& text_list, const std::string& what) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  std::string item;
  std::stringstream in(text_list);
  bool any = false;
  while (std::getline(in, item, ',')) {
    any = true;
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    const std::string name = b == std::string::npos ? "" : item.substr(b, e - b + 1);
    if (name.empty())
      throw std::invalid_argument(what + ": '" + text_list + "' has an empty name");
    for (const char c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-')
        throw std::invalid_argument(what + ": the name '" + name +
                                    "' may hold letters, digits, '_' and '-' only");
    if (!seen.insert(name).second)
      throw std::invalid_argument(what + ": the name '" + name + "' is listed twice");
    names.push_back(name);
  }
  if (!any && text_list.find_first_not_of(" \t") != std::string::npos)
    throw std::invalid_argument(what + ": cannot read '" + text_list + "'");
  return names;
}

SceneParameters scene_with_names(const SceneNames& names) {
  SceneParameters s;
  s.wall_names = names.walls;
  s.inlet_names = names.inlets;
  s.outlet_names = names.outlets;
  s.flux_plane_names = names.flux_planes;
  for (const auto& name : scene_names(names.walls, "Scene/Walls"))
    s.walls.emplace_back().name = name;
  for (const auto& name : scene_names(names.inlets, "Scene/Inlets"))
    s.inlets.emplace_back().name = name;
  for (const auto& name : scene_names(names.outlets, "Scene/Outlets"))
    s.outlets.emplace_back().name = name;
  for (const auto& name : scene_names(names.flux_planes, "Scene/Flux planes"))
    s.flux_planes.emplace_back().name = name;
  return s;
}

std::vector<int> surface_numbers(const std::string& text, const std::string& what) {
  std::vector<int> numbers;
  std::string item;
  std::stringstream in(text);
  while (std::getline(in, item, ',')) {
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    const std::string word = b == std::string::npos ? "" : item.substr(b, e - b + 1);
    std::size_t used = 0;
    int n = 0;
    try {
      n = std::stoi(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (word.empty() || used != word.size() || n < 1 || n > meshes::label::max_part_surfaces)
      throw std::invalid_argument(what + ": '" + word +
                                  "' is not a surface number (1 ... 999, as `wearsim scene` "
                                  "lists them)");
    if (std::find(numbers.begin(), numbers.end(), n) != numbers.end())
      throw std::invalid_argument(what + ": surface " + word + " is listed twice");
    numbers.push_back(n);
  }
  std::sort(numbers.begin(), numbers.end());
  return numbers;
}

RigidMotion rigid_motion(const SceneWallParameters& w) {
  RigidMotion m;
  m.start_time = w.start_time;
  if (w.end_time > 0)
    m.end_time = w.end_time;
  switch (wall_motion_of(w).kind) {
  case WallMotionKind::rotation:
    m.axis_point = scene_vector(w.axis_point);
    m.axis = scene_vector(w.rotation_axis);
    m.angular_velocity = w.angular_velocity;
    break;
  case WallMotionKind::translation:
    m.velocity = scene_vector(w.velocity);
    break;
  case WallMotionKind::oscillation:
    m.amplitude = scene_vector(w.amplitude);
    m.frequency = w.frequency;
    break;
  default: // at rest, or only its surface moves
    break;
  }
  return m;
}

WallMotion surface_motion(const SceneWallParameters& w) {
  WallMotion m;
  switch (wall_motion_of(w).kind) {
  case WallMotionKind::surface_rotation:
    m.axis_point = scene_vector(w.axis_point);
    m.axis = meshes::normalized(scene_vector(w.rotation_axis));
    m.angular_velocity = w.angular_velocity;
    break;
  case WallMotionKind::surface_translation:
    m.surface_velocity = scene_vector(w.velocity);
    break;
  default: // at rest, or it moves as a whole (rigid_motion)
    break;
  }
  return m;
}

std::string rank_slab_axis(const SceneParameters& s) {
  if (s.rank_slabs_along != "auto")
    return s.rank_slabs_along;
  return s.periodic_angle_deg > 0         ? "angle"
         : s.periodic_direction != "none" ? s.periodic_direction
                                          : "x";
}

bool rank_ring(const SceneParameters& s) {
  return rank_slab_axis(s) == "angle" || s.periodic_direction != "none";
}

int periodic_axis(const SceneParameters& s) {
  return s.periodic_direction == "x" ? 0 : s.periodic_direction == "y" ? 1 : 2;
}

bool moves_rigidly(const SceneWallParameters& w) {
  return wall_motion_of(w).rigid;
}

namespace {

/// n when x is n times `unit` to 1e-6 of it, else 0.
long whole_multiple(double x, double unit) {
  const double n = std::round(x / unit);
  return n >= 1 && std::abs(x - n * unit) <= 1e-6 * unit ? long(n) : 0;
}

void validate_evaluation(const SceneParameters& s) {
  const auto& e = s.evaluation;
  const SceneEvaluationParameters defaults;
  if (e.wall.empty()) {
    if (e.period != defaults.period || e.steady_threshold != defaults.steady_threshold ||
        e.steady_periods != defaults.steady_periods ||
        e.periods_after_steady != defaults.periods_after_steady)
      throw std::invalid_argument("Scene/Evaluation: Period and the steady-state entries "
                                  "evaluate a wall; name it in Scene/Evaluation/Wall (or leave "
                                  "them out)");
    return;
  }
  const auto k = scene_wall_index(s, e.wall);
  if (!k)
    throw std::invalid_argument("Scene/Evaluation/Wall: '" + e.wall +
                                "' is not a wall of Scene/Walls");
  const SceneWallParameters& w = s.walls[*k];
  if (wall_source_of(w).source != WallSource::sample || !w.wears)
    throw std::invalid_argument("Scene/Evaluation/Wall: '" + e.wall +
                                "' is not the tester's sample; the evaluation's columns and "
                                "elements are the sample's (Source = sample, Wears = true)");
  if (!(s.stage_duration > 0))
    throw std::invalid_argument("Scene/Evaluation/Wall: the evaluation is a wearing part's and "
                                "needs stages (Scene/Stage duration)");
  if (!(e.period > 0))
    throw std::invalid_argument("Scene/Evaluation/Period must be positive [s]");
  if (whole_multiple(e.period, s.output_interval) < 2)
    throw std::invalid_argument("Scene/Evaluation/Period: must be a whole number (at least two) "
                                "of Scene/Output interval, its samples; got " +
                                std::to_string(e.period / s.output_interval));
  if (whole_multiple(s.stage_duration, e.period) < 1)
    throw std::invalid_argument("Scene/Evaluation/Period: Scene/Stage duration must be a whole "
                                "number of periods (a period never spans two stages); got " +
                                std::to_string(s.stage_duration / e.period));
  if (!(e.steady_threshold > 0))
    throw std::invalid_argument("Scene/Evaluation/Steady threshold must be positive");
}

} // namespace

bool snapshot_due(const SceneParameters& s, int k) {
  return s.particle_snapshots || std::find(s.snapshot_records.begin(), s.snapshot_records.end(),
                                           k) != s.snapshot_records.end();
}

void validate(const SceneParameters& s) {
  const auto three = [](const std::vector<double>& v, const std::string& what) {
    if (v.size() != 3)
      throw std::invalid_argument(what + ": needs 3 values (x, y, z), got " +
                                  std::to_string(v.size()));
  };
  three(s.domain_min, "Scene/Domain minimum");
  three(s.domain_max, "Scene/Domain maximum");
  for (int d = 0; d < 3; ++d)
    if (!(s.domain_min[d] < s.domain_max[d]))
      throw std::invalid_argument("Scene/Domain minimum must lie below Scene/Domain maximum in "
                                  "every direction");
  for (const auto& w : s.walls) {
    const std::string p = scene_wall_path(w);
    for (const auto& [v, name] : {std::pair{&w.origin, "Origin"},
                                  {&w.edge_u, "Edge u"},
                                  {&w.edge_v, "Edge v"},
                                  {&w.axis, "Axis"},
                                  {&w.axis_point, "Axis point"},
                                  {&w.rotation_axis, "Rotation axis"},
                                  {&w.velocity, "Velocity"},
                                  {&w.amplitude, "Amplitude"}})
      three(*v, p + "/" + name);
    const WallSourceEntry& source = wall_source_of(w);
    const WallMotionEntry& motion = wall_motion_of(w);
    if (source.source == WallSource::file && w.file.empty())
      throw std::invalid_argument(p + "/File: a file is needed with Source = file");
    if (!(w.mesh_size > 0))
      throw std::invalid_argument(p + "/Mesh size must be positive [m], got " +
                                  std::to_string(w.mesh_size));
    if (motion.rotates && meshes::norm(scene_vector(w.rotation_axis)) == 0)
      throw std::invalid_argument(p + "/Rotation axis must not be zero");
    if (motion.kind == WallMotionKind::oscillation && !(w.frequency > 0))
      throw std::invalid_argument(p + "/Frequency must be positive [Hz] for an oscillation");
    validate(rigid_motion(w), p);
    if (w.wearing_surfaces != "all")
      surface_numbers(w.wearing_surfaces, p + "/Wearing surfaces");
    surface_numbers(w.clamped_surfaces, p + "/Clamped surfaces");
    surface_numbers(w.held_surfaces, p + "/Held surfaces");
    if (source.source == WallSource::sample &&
        (w.wearing_surfaces != "all" || !w.clamped_surfaces.empty() || !w.held_surfaces.empty()))
      throw std::invalid_argument(p + ": the tester's sample (Source = sample) brings its own "
                                      "roles (base and elements wear, bottom clamped, "
                                      "sides free, or held in a holder); leave Wearing "
                                      "surfaces, Clamped surfaces and Held surfaces at their "
                                      "defaults");
    if (source.tester_part && motion.kind != WallMotionKind::fixed)
      throw std::invalid_argument(p + "/Motion: the tester's " + w.source +
                                  " stands still (Motion = fixed)");
    if (source.source == WallSource::holder && w.wears)
      throw std::invalid_argument(p + "/Wears: the holder is steel and does not wear");
  }
  const auto count_source = [&](const std::string& source) {
    return std::count_if(s.walls.begin(), s.walls.end(),
                         [&](const SceneWallParameters& w) { return w.source == source; });
  };
  if (count_source("sample") > 1 || count_source("holder") > 1)
    throw std::invalid_argument("Scene/Walls: at most one wall with Source = sample and one "
                                "with Source = holder (the tester holds one sample)");
  if (count_source("holder") == 1 && count_source("sample") == 0)
    throw std::invalid_argument("Scene/Walls: a wall with Source = holder needs the sample it "
                                "holds (a wall with Source = sample)");
  if (!(s.periodic_angle_deg >= 0 && s.periodic_angle_deg < 360))
    throw std::invalid_argument("Scene/Periodic sector must lie in [0, 360) degrees, got " +
                                std::to_string(s.periodic_angle_deg));
  if (s.periodic_direction != "none") {
    if (s.periodic_angle_deg > 0)
      throw std::invalid_argument("Scene/Periodic direction: a planar periodic boundary and "
                                  "Scene/Periodic sector exclude each other");
    const int axis = periodic_axis(s);
    if (!(s.periodic_from < s.periodic_to))
      throw std::invalid_argument("Scene/Periodic from must lie below Scene/Periodic to");
    if (s.periodic_from <= s.domain_min[axis] || s.periodic_to >= s.domain_max[axis])
      throw std::invalid_argument("Scene/Periodic from and to must lie inside Scene/Domain "
                                  "along " +
                                  s.periodic_direction +
                                  " (particles cross the planes by up to half a skin before "
                                  "they are wrapped)");
    for (const auto& w : s.walls)
      if (moves_rigidly(w))
        throw std::invalid_argument(scene_wall_path(w) +
                                    "/Motion: a wall that moves as a rigid "
                                    "body (" +
                                    w.motion +
                                    ") cannot be part of a periodic scene (Scene/Periodic "
                                    "direction); give it a surface motion or none");
  }
  if (!(s.rank_rebalance == 0 || s.rank_rebalance > 1))
    throw std::invalid_argument("Scene/Rank rebalance must be 0 (never) or above 1, got " +
                                std::to_string(s.rank_rebalance));
  if (s.periodic_angle_deg > 0 && rank_slab_axis(s) != "angle")
    throw std::invalid_argument("Scene/Rank slabs along = " + s.rank_slabs_along +
                                ": a periodic sector (Scene/Periodic sector) is cut over ranks "
                                "along its angle; set Rank slabs along = angle or auto");
  if (s.periodic_direction != "none" && rank_slab_axis(s) != s.periodic_direction)
    throw std::invalid_argument("Scene/Rank slabs along = " + s.rank_slabs_along +
                                ": a scene periodic along " + s.periodic_direction +
                                " (Scene/Periodic direction) is cut over ranks along its period; "
                                "set Rank slabs along = " +
                                s.periodic_direction + " or auto");
  for (const auto& w : s.walls)
    if (s.periodic_angle_deg > 0 && moves_rigidly(w))
      throw std::invalid_argument(scene_wall_path(w) +
                                  "/Motion: a wall that moves as a rigid "
                                  "body (" +
                                  w.motion +
                                  ") cannot be part of a periodic sector "
                                  "(Scene/Periodic sector); give it a surface motion or none");
  if (s.stage_duration < 0)
    throw std::invalid_argument("Scene/Stage duration must not be negative [s]");
  three(s.gravity, "Scene/Gravity");
  if (!(s.end_time > 0))
    throw std::invalid_argument("Scene/End time must be positive [s]");
  if (!(s.output_interval > 0))
    throw std::invalid_argument("Scene/Output interval must be positive [s]");
  for (const int k : s.snapshot_records)
    if (k < 1)
      throw std::invalid_argument("Scene/Snapshot records: " + std::to_string(k) +
                                  " is not a record (they count from 1)");
  const auto inside_domain = [&](const std::vector<double>& lo, const std::vector<double>& hi,
                                 const std::string& what) {
    for (int d = 0; d < 3; ++d) {
      if (!(lo[d] < hi[d]))
        throw std::invalid_argument(what + "/Minimum must lie below Maximum in every direction");
      if (lo[d] < s.domain_min[d] || hi[d] > s.domain_max[d])
        throw std::invalid_argument(what + ": the region reaches outside Scene/Domain (check "
                                           "the unit: metres)");
    }
  };
  if (s.fill.region == "box") {
    three(s.fill.minimum, "Scene/Fill/Minimum");
    three(s.fill.maximum, "Scene/Fill/Maximum");
    inside_domain(s.fill.minimum, s.fill.maximum, "Scene/Fill");
  }
  if (s.fill.region == "cylinder") {
    three(s.fill.origin, "Scene/Fill/Origin");
    three(s.fill.axis, "Scene/Fill/Axis");
    const meshes::Vec3 o = scene_vector(s.fill.origin), a = scene_vector(s.fill.axis);
    const double length = meshes::norm(a);
    if (!(length > 0))
      throw std::invalid_argument("Scene/Fill/Axis must not be zero");
    if (!(s.fill.radius > 0))
      throw std::invalid_argument("Scene/Fill/Radius must be positive [m] for a cylinder");
    if (!(s.fill.radius_inner >= 0 && s.fill.radius_inner < s.fill.radius))
      throw std::invalid_argument("Scene/Fill/Inner radius must lie in [0, Radius)");
    if (s.fill.count == 0 && !(a.z > 0 && std::hypot(a.x, a.y) <= 1e-9 * length))
      throw std::invalid_argument("Scene/Fill/Axis: a fill to a Bed height needs the "
                                  "cylinder's axis along +z (its base the floor)");
    std::vector<double> lo(3), hi(3);
    for (int d = 0; d < 3; ++d) { // the bounding box of the two end discs
      const double e =
          s.fill.radius * std::sqrt(std::fmax(0.0, 1 - a[d] * a[d] / (length * length)));
      lo[d] = std::fmin(o[d], o[d] + a[d]) - e;
      hi[d] = std::fmax(o[d], o[d] + a[d]) + e;
    }
    inside_domain(lo, hi, "Scene/Fill");
  }
  if (s.fill.region == "mesh") {
    if (s.fill.file.empty())
      throw std::invalid_argument("Scene/Fill/File: a file is needed with Region = mesh");
    if (s.fill.count == 0)
      throw std::invalid_argument("Scene/Fill/Count: a fill from a mesh takes a Count (a Bed "
                                  "height needs a box or a cylinder, whose floor is flat)");
    if (!(s.fill.mesh_size > 0))
      throw std::invalid_argument("Scene/Fill/Mesh size must be positive [m]");
  }
  for (const auto& name : scene_names(s.fill.clear_above, "Scene/Fill/Clear above"))
    if (!scene_wall_index(s, name))
      throw std::invalid_argument("Scene/Fill/Clear above: '" + name +
                                  "' is not a wall of Scene/Walls");
  if (s.fill.region != "none" && s.fill.count == 0 && !(s.fill.bed_height > 0))
    throw std::invalid_argument("Scene/Fill: give a Count or a positive Bed height [m]");
  if (s.fields.cells.size() != 3)
    throw std::invalid_argument("Scene/Fields/Cells: needs 3 counts (nx, ny, nz), got " +
                                std::to_string(s.fields.cells.size()));
  if (s.fields.cells != std::vector<int>{0, 0, 0}) {
    three(s.fields.minimum, "Scene/Fields/Minimum");
    three(s.fields.maximum, "Scene/Fields/Maximum");
    for (int d = 0; d < 3; ++d) {
      if (s.fields.cells[d] < 1)
        throw std::invalid_argument("Scene/Fields/Cells: every count must be at least 1 (or "
                                    "all 0 for no fields)");
      if (!(s.fields.minimum[d] < s.fields.maximum[d]))
        throw std::invalid_argument("Scene/Fields: Minimum must lie below Maximum in every "
                                    "direction");
    }
  }
  validate_evaluation(s);
  for (const auto& in : s.inlets) {
    const std::string p = "Scene/Inlet " + in.name;
    three(in.corner, p + "/Corner");
    three(in.edge_u, p + "/Edge u");
    three(in.edge_v, p + "/Edge v");
    three(in.velocity, p + "/Velocity");
    if (!(in.mass_flow > 0))
      throw std::invalid_argument(p + "/Mass flow rate must be positive [kg/s]");
    if (in.start_time < 0 || in.end_time < 0)
      throw std::invalid_argument(p + ": Start time and End time must not be negative [s]");
  }
  for (const auto& f : s.flux_planes) {
    const std::string p = "Scene/Flux plane " + f.name;
    three(f.point, p + "/Point");
    three(f.normal, p + "/Normal");
    if (meshes::norm(scene_vector(f.normal)) == 0)
      throw std::invalid_argument(p + "/Normal must not be zero");
  }
  for (const auto& out : s.outlets) {
    const std::string p = "Scene/Outlet " + out.name;
    three(out.minimum, p + "/Minimum");
    three(out.maximum, p + "/Maximum");
    for (int d = 0; d < 3; ++d)
      if (!(out.minimum[d] < out.maximum[d]))
        throw std::invalid_argument(p + "/Minimum must lie below Maximum in every direction");
  }
}

bool fills_sector_only(const SceneParameters& s) {
  const auto& f = s.fill;
  return f.region == "cylinder" && s.periodic_angle_deg > 0 && f.origin.size() == 3 &&
         f.axis.size() == 3 && f.origin[0] == 0 && f.origin[1] == 0 && f.axis[0] == 0 &&
         f.axis[1] == 0 && f.axis[2] > 0;
}

void require_fill_count_fits(const SceneParameters& s, const SizeDistribution& psd,
                             double mesh_volume) {
  const auto& f = s.fill;
  if (f.region == "none" || f.count == 0 || (f.region == "mesh" && mesh_volume < 0))
    return;
  double volume = mesh_volume;
  std::string region = "the solid of '" + f.file + "'";
  if (f.region == "box") {
    volume = 1;
    for (int d = 0; d < 3; ++d)
      volume *= f.maximum[d] - f.minimum[d];
    region = "the box";
  } else if (f.region == "cylinder") {
    const double share = fills_sector_only(s) ? s.periodic_angle_deg / 360 : 1.0;
    volume = pi * (f.radius * f.radius - f.radius_inner * f.radius_inner) *
             meshes::norm(scene_vector(f.axis)) * share;
    region = share < 1 ? "the cylinder's share of the periodic sector" : "the cylinder";
  }
  // Why the smallest size bounds every size distribution: shrink each particle about its
  // centre to diameter d; they stay apart and inside the region, now equal spheres, which fill
  // at most 0.7405 of it (Kepler's bound of space, which a region's walls only lower). Sizes
  // mixed can pack denser than 0.7405 by volume, but not by count times the smallest volume.
  const double d = psd.min_diameter();
  const double sphere = pi / 6 * d * d * d;
  const double bound = std::floor(densest_sphere_packing * volume / sphere);
  if (double(f.count) <= bound)
    return;
  std::ostringstream m;
  m.precision(4);
  const auto whole = [](double x) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(0) << x;
    return s.str();
  };
  m << "Scene/Fill/Count (" << f.count << ") exceeds the most particles the fill region can "
    << "hold, " << whole(bound) << ": " << region << " of " << volume
    << " m^3 at the densest packing of spheres, pi/(3 sqrt 2) = 0.7405, of the size "
       "distribution's smallest diameter d = "
    << d << " m (DEM/PSD diameters x DEM/Scaling factor) holds 0.7405 x " << volume
    << " m^3 / (pi/6 d^3 = " << sphere << " m^3) = " << whole(bound)
    << " spheres, and no fill more (random insertion jams near half of that, at 0.38 solid for "
       "equal spheres); lower Count, enlarge the region, or set Count = 0 and a Bed height";
  throw std::invalid_argument(m.str());
}

} // namespace wear::dem

// The wear tester written as a scene (tester_scene.h).
//
// One revolution is one pass of the bed through the sector, T = Theta / omega; a stage of N
// revolutions lasts N T and a record is taken every T / (Samples per revolution). The walls
// turn at omega = Rotation rate [rad/s] about +z under a fixed sample, as in the built-in
// tester. The consolidator, an annular sector of extent e at height h there, is here the
// rectangle of the same height, centred on its angle, spanning r0 = r_i + 0.5 mm to
// r1 = sqrt((r_o - 1 mm)^2 - (w/2)^2) radially (its outer corners 1 mm inside the outer
// cylinder) and w = e (r_i + r_o) / 2 across: the sector's area to within a few per cent.
// The sample is evaluated per revolution as the built-in tester's (Scene/Evaluation, its
// steady state judged by DEM/Steady threshold and Steady revolutions).
#include "dem/tester/tester_scene.h"

#include "dem/tester/tester_parameters.h"
#include "meshes/constants.h"

#include <algorithm>
#include <cmath>

namespace wear::dem {

namespace {

SceneWallParameters turning(const std::string& name, const std::string& source, double omega,
                            double mesh_size) {
  SceneWallParameters w;
  w.name = name;
  w.source = source;
  w.origin = {0, 0, 0};
  w.mesh_size = mesh_size;
  w.motion = "surface rotation";
  w.axis_point = {0, 0, 0};
  w.rotation_axis = {0, 0, 1};
  w.angular_velocity = omega;
  return w;
}

SceneWallParameters consolidator(const meshes::TesterGeometry& t) {
  const double ri = t.inner_radius, ro = t.outer_radius;
  const double theta = t.consolidator_angle_deg * pi / 180;
  const double width = t.consolidator_extent_deg * pi / 180 * 0.5 * (ri + ro);
  const double r0 = ri + 0.5e-3;
  const double r1 = std::sqrt((ro - 1e-3) * (ro - 1e-3) - 0.25 * width * width);
  const double c = std::cos(theta), s = std::sin(theta);
  SceneWallParameters w;
  w.name = "consolidator";
  w.source = "plane";
  // the corner at r0 on the side of smaller angles; u radially outwards, v along +theta
  w.origin = {r0 * c + 0.5 * width * s, r0 * s - 0.5 * width * c, t.consolidator_height};
  w.edge_u = {(r1 - r0) * c, (r1 - r0) * s, 0};
  w.edge_v = {-width * s, width * c, 0};
  w.mesh_size = t.wall_mesh_size;
  return w;
}

} // namespace

SceneParameters tester_scene(const meshes::GeometryParameters& geometry,
                             const TesterDemParameters& dem, int revolutions_per_stage) {
  meshes::validate(geometry);
  validate(dem);
  if (revolutions_per_stage < 1)
    throw std::invalid_argument("Coupling/Revolutions per stage: must be at least 1");
  const auto& t = geometry.tester;
  const double omega = dem.rotation_rate_deg * pi / 180;
  const double revolution = t.sector_angle_deg * pi / 180 / omega; // [s]
  const double ri = t.inner_radius, ro = t.outer_radius, h = t.wall_height;

  SceneParameters s;
  SceneWallParameters floor = turning("floor", "disc", omega, t.wall_mesh_size);
  floor.axis = {0, 0, 1};
  floor.radius = ro;
  floor.radius_inner = ri;
  s.walls.push_back(floor);
  for (const auto& [name, r] : {std::pair{"inner", ri}, std::pair{"outer", ro}}) {
    SceneWallParameters cylinder = turning(name, "cylinder", omega, t.wall_mesh_size);
    cylinder.axis = {0, 0, h};
    cylinder.radius = r;
    s.walls.push_back(cylinder);
  }
  if (t.consolidator)
    s.walls.push_back(consolidator(t));
  if (t.holder) {
    SceneWallParameters holder;
    holder.name = "holder";
    holder.source = "holder";
    holder.material = "holder";
    holder.mesh_size = t.wall_mesh_size; // the built-in tester's holder
    s.walls.push_back(holder);
  }
  SceneWallParameters sample;
  sample.name = "sample";
  sample.source = "sample";
  sample.material = "sample";
  sample.wears = true;
  s.walls.push_back(sample);
  for (const auto& w : s.walls)
    s.wall_names += (s.wall_names.empty() ? "" : ", ") + w.name;

  if (t.sector_angle_deg < 360)
    s.periodic_angle_deg = t.sector_angle_deg;
  const double margin = ro + 0.05;
  s.domain_min = {-margin, -margin, -0.05};
  s.domain_max = {margin, margin, h + dem.fill_height * dem.loose_factor};
  s.stage_duration = revolutions_per_stage * revolution;
  s.output_interval = revolution / dem.samples_per_revolution;
  s.particle_snapshots = false;
  for (const int r : dem.snapshot_revolutions) // the particles after these revolutions
    s.snapshot_records.push_back(r * dem.samples_per_revolution);
  s.evaluation.wall = "sample";
  s.evaluation.period = revolution;
  s.evaluation.steady_threshold = dem.steady_threshold;
  s.evaluation.steady_periods = dem.steady_revolutions;
  s.evaluation.periods_after_steady = dem.revolutions_after_steady;

  auto& fill = s.fill;
  fill.region = "cylinder";
  fill.origin = {0, 0, 1e-4};
  // up to the walls' top, or higher when the loose fill needs more room (a short sector's
  // walls): the particles placed above the walls stand over the annulus and fall into it
  fill.axis = {0, 0, std::max(h, 1.001 * dem.loose_factor * dem.fill_height)};
  fill.radius = ro - 1e-4;
  fill.radius_inner = ri + 1e-4;
  fill.bed_height = dem.fill_height;
  if (t.consolidator)
    fill.clear_above = "consolidator";
  validate(s);
  return s;
}

} // namespace wear::dem

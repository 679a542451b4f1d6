#pragma once
// Shared scenes of the scene tests.
#include "dem/scene/scene_parameters.h"
#include "dem/tester/tester_parameters.h"

#include <string>

namespace wear::dem::testing {

/// Single-size 6 mm gravel, little rolling friction (a free-flowing bin), one thread.
inline TesterDemParameters gravel() {
  TesterDemParameters d;
  d.psd = {{0.006}, {1.0}, 1.0};
  d.particle = {1e7, 0.25, 2650};
  d.particle_particle = {0.5, 0.5, 0.02};
  d.particle_wall = {0.5, 0.5, 0.02};
  d.n_threads = 1;
  return d;
}

/// A cylindrical bin (wall 0, its side) of radius R and height H standing on a flat floor
/// (wall 1) with a central orifice of radius r_o, in a domain reaching 1.5 R around it and
/// H below and above; below the floor, from z = -H to z = -outlet_gap, the outlet (outlet 0)
/// takes what falls through. `walls` names the walls, the first two being the side and the
/// floor (further walls are left at their defaults).
inline SceneParameters flat_bottomed_bin(const std::string& walls, double R, double H, double r_o,
                                         double outlet_gap) {
  SceneParameters s = scene_with_names({walls, "", "below"});
  s.domain_min = {-1.5 * R, -1.5 * R, -H};
  s.domain_max = {1.5 * R, 1.5 * R, 1.25 * H};
  auto& side = s.walls[0];
  side.source = "cylinder";
  side.axis = {0, 0, H};
  side.radius = R;
  side.mesh_size = R / 10;
  auto& floor = s.walls[1];
  floor.source = "disc";
  floor.axis = {0, 0, 1};
  floor.radius = R;
  floor.radius_inner = r_o;
  floor.mesh_size = std::min(R / 10, r_o / 8); // the orifice's rim a 50-gon
  s.outlets[0].minimum = s.domain_min;
  s.outlets[0].maximum = {1.5 * R, 1.5 * R, -outlet_gap};
  return s;
}

/// Closes the orifice of a flat_bottomed_bin's floor (wall 1) to a 2 mm pinhole, so nothing
/// drains while a bed settles or stands.
inline void close_to_pinhole(SceneParameters& s) {
  s.walls[1].radius_inner = 0.002;
  s.walls[1].mesh_size = 0.006;
}

/// The 60 mm bin of flat_bottomed_bin (0.3 m tall) closed to a pinhole, with the walls named
/// `walls` (side, floor, others), and 600 particles to fill the cylinder 2 mm inside its side
/// from 1 mm over the floor.
inline SceneParameters pinhole_bin_cylinder_fill(const std::string& walls) {
  SceneParameters s = flat_bottomed_bin(walls, 0.06, 0.3, 0.025, 0.05);
  close_to_pinhole(s);
  s.fill.region = "cylinder";
  s.fill.origin = {0, 0, 0.001};
  s.fill.axis = {0, 0, 0.2};
  s.fill.radius = 0.058;
  s.fill.count = 600;
  return s;
}

/// A belt (a plane moving as a 'surface translation' at 0.5 m/s along x) between two fixed
/// side plates, the scene periodic in x over 0.2 m (the walls reach 50 mm past both planes),
/// 300 particles on it, a flux plane at x = 0 counting forwards along x.
inline SceneParameters endless_belt() {
  SceneParameters scene = scene_with_names({"belt, left, right", "", ""});
  scene.periodic_direction = "x";
  scene.periodic_from = -0.1;
  scene.periodic_to = 0.1;
  scene.domain_min = {-0.2, -0.1, -0.05};
  scene.domain_max = {0.2, 0.1, 0.2};
  auto& belt = scene.walls[0];
  belt.source = "plane";
  belt.origin = {-0.15, -0.05, 0};
  belt.edge_u = {0.3, 0, 0};
  belt.edge_v = {0, 0.1, 0};
  belt.mesh_size = 0.02;
  belt.motion = "surface translation";
  belt.velocity = {0.5, 0, 0};
  for (int k : {1, 2}) {
    auto& side = scene.walls[std::size_t(k)];
    side.source = "plane";
    side.origin = {-0.15, k == 1 ? -0.05 : 0.05, 0};
    side.edge_u = {0.3, 0, 0};
    side.edge_v = {0, 0, 0.15};
    side.mesh_size = 0.02;
  }
  scene.flux_plane_names = "middle";
  scene.flux_planes.push_back({"middle", {0, 0, 0}, {1, 0, 0}});
  scene.fill.region = "box";
  scene.fill.minimum = {-0.095, -0.045, 0.002};
  scene.fill.maximum = {0.095, 0.045, 0.06};
  scene.fill.count = 300;
  return scene;
}

} // namespace wear::dem::testing

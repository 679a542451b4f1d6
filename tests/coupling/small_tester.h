#pragma once
// The small wear tester the coupling tests run: a 30-degree periodic sector at s = 4 with a
// 55 mm bed (about 2,300 particles), no consolidator, a coarse (3 mm) sample centred in the
// sector, 2 threads. One revolution takes a few seconds. The tester runs as a scene.
#include "coupling/parameters/case_parameters.h"

#include <string>

inline wear::coupling::CaseParameters small_tester_case(const std::string& dir, bool convex) {
  wear::coupling::CaseParameters p;
  p.geometry.sample.convex = convex;
  p.geometry.sample.mesh_size = 3e-3;
  p.geometry.sample.curvature_refinement = false;
  p.geometry.placement.angle_deg = 15;
  p.geometry.tester.sector_angle_deg = 30;
  p.geometry.tester.consolidator = false;
  p.geometry.tester.wall_height = 0.2;
  p.dem.fill_height = 0.055;
  p.dem.settle_time = 0.15;
  p.dem.time_step_fraction = 0.35;
  p.dem.samples_per_revolution = 5;
  p.dem.n_threads = 2;
  p.output.directory = dir;
  return p;
}

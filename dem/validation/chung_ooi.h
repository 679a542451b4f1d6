#pragma once
// Single-impact scenarios of the Chung & Ooi (2011) DEM benchmark, run through the full
// engine (System, neighbour list, mesh walls). Used by the tests and by the table program.
#include "dem/engine/material.h"
#include "meshes/vec3.h"

#include <string>
#include <vector>

namespace wear::dem::validation {

using meshes::Vec3;

/// Where a sphere hits a flat triangle-mesh plane.
enum class PlaneSpot { face, edge, vertex };

struct ImpactResult {
  double contact_time = 0; ///< [s]
  double max_overlap = 0;  ///< [m]
  double max_force = 0;    ///< [N] normal force
  Vec3 v_after, w_after;   ///< sphere 1 after the impact [m/s], [rad/s]
  Vec3 v2_after, w2_after; ///< sphere 2 (pair impacts)
  double radius = 0;       ///< [m] of sphere 1
};

struct ImpactMaterial {
  double youngs_modulus, poisson_ratio, density; ///< [Pa], [-], [kg/m^3]
};

/// Sphere (radius r) against a plane z = 0 built from triangles (normal +z), no gravity,
/// dt = 1 % of the Rayleigh time. `rigid_plane`: the plane has infinite stiffness.
ImpactResult sphere_on_plane(const ImpactMaterial& m, double r, const Vec3& v, const Vec3& w,
                             double restitution, double friction, bool rigid_plane, PlaneSpot spot,
                             RestitutionMapping mapping);

/// Two spheres along x, sphere 1 at -x moving with v1, sphere 2 at +x with v2.
ImpactResult sphere_on_sphere(const ImpactMaterial& m1, double r1, const Vec3& v1, const Vec3& w1,
                              const ImpactMaterial& m2, double r2, const Vec3& v2, const Vec3& w2,
                              double restitution, double friction, RestitutionMapping mapping);

/// Hertz analytic values for an impact at relative speed v (Chung & Ooi Tests 1-2).
struct HertzPrediction {
  double contact_time, max_overlap, max_force;
};
HertzPrediction hertz_prediction(double e_star, double r_star, double m_star, double v);

/// One row of the generated table.
struct Row {
  std::string test, example, quantity;
  double expected, computed, tolerance; ///< tolerance: relative, or absolute when noted
  bool absolute = false;
  bool passed() const;
};
/// Runs all eight tests for both materials each; used by the table program and the tests.
std::vector<Row> run_suite();

} // namespace wear::dem::validation

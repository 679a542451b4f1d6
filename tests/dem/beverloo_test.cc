// Discharge of a flat-bottomed bin through a circular orifice against Beverloo's law
// (Beverloo, Leniger and van de Velde 1961; Nedderman, Statics and Kinematics of Granular
// Materials, 1992, ch. 10):
//
//   W = C rho_b sqrt(g) (D - k d)^(5/2),  C in 0.55 .. 0.65, k in 1 .. 3 (Nedderman's ranges;
//   the check takes 0.5 .. 0.7 for C),
//
// with W the mass flow rate, rho_b the bulk density of the bed, D the orifice diameter and d
// the particle diameter. Here: 6 mm gravel in a bin of 200 mm diameter, orifices of 40, 50
// and 60 mm (6.7 to 10 particle diameters), each closed by a plug (a disc wall) that drops
// away into the outlet when the bed has settled (a translating wall with an end time). W is the
// slope of the outlet's mass over the steady part of the discharge; W^(2/5) against D gives C and k
// by a straight-line fit.
#include "dem/scene/scene_run.h"
#include "meshes/constants.h"
#include "scene_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace wear::dem;

namespace {

constexpr double d = 0.006, rho_s = 2650, g = 9.81, t_open = 0.45;

struct Discharge {
  double rate = 0;         ///< [kg/s]
  double bulk_density = 0; ///< [kg/m^3] of the settled bed
  std::size_t n_particles = 0;
};

Discharge discharge(double orifice) {
  SceneParameters s = testing::flat_bottomed_bin("bin, floor, plug", 0.1, 0.4, orifice / 2, 0.1);
  auto& plug = s.walls[2];
  plug.source = "disc";
  plug.axis = {0, 0, 1};
  plug.radius = orifice / 2;
  plug.mesh_size = 0.005;
  // Drops 0.3 m in 0.15 s once the bed has settled, into the outlet below: faster than the
  // first particles fall (g t < 2 m/s for t < 0.2 s), so none lands on it.
  plug.motion = "translation";
  plug.velocity = {0, 0, -2};
  plug.start_time = t_open;
  plug.end_time = t_open + 0.15;
  s.fill.region = "box";
  s.fill.minimum = {-0.068, -0.068, 0.003};
  s.fill.maximum = {0.068, 0.068, 0.39};
  s.fill.count = 16000;
  s.output_interval = 0.05;
  TesterDemParameters dem;
  dem.psd = {{d}, {1.0}, 1.0};
  dem.particle = {1e7, 0.25, rho_s}; // soft: Beverloo's law does not depend on stiffness
  dem.particle_particle = {0.5, 0.5, 0.05};
  dem.particle_wall = {0.5, 0.5, 0.05};
  dem.n_threads = 2;
  SceneRun run(s, dem, build_scene_walls(s));
  run.setup();
  run.advance(t_open); // settles on the closed plug
  // Bulk density of the settled bed: its mass over the volume of the bin up to the bed's
  // top (the mean height of the highest layer's centres plus a radius).
  const auto& p = run.system().particles;
  std::vector<double> z(p.n_real);
  for (std::size_t i = 0; i < p.n_real; ++i)
    z[i] = p.position[i].z;
  std::sort(z.begin(), z.end());
  const std::size_t layer = std::size_t(wear::pi * 0.1 * 0.1 / (0.866 * d * d));
  double top = 0;
  for (std::size_t k = z.size() - layer; k < z.size(); ++k)
    top += z[k];
  top = top / double(layer) + d / 2;
  Discharge out;
  out.n_particles = p.n_real;
  out.bulk_density = double(p.n_real) * rho_s * wear::pi / 6 * d * d * d / (wear::pi * 0.01 * top);
  // Steady discharge: from 0.15 s after opening (the first particles reach the outlet and
  // the flow has formed) over 0.7 s, the outlet's mass sampled every 0.05 s (the bed then
  // still stands more than a diameter of the largest orifice above it).
  std::vector<double> t, m;
  run.advance(t_open + 0.15);
  while (run.time() < t_open + 0.85 - 1e-9) {
    const SceneWindow w = run.advance(run.time() + 0.05);
    t.push_back(w.t_end);
    m.push_back(w.outlet_mass[0]);
  }
  // Least-squares slope of mass against time.
  double tm = 0, mm = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    tm += t[k];
    mm += m[k];
  }
  tm /= double(t.size());
  mm /= double(t.size());
  double stt = 0, stm = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    stt += (t[k] - tm) * (t[k] - tm);
    stm += (t[k] - tm) * (m[k] - mm);
  }
  out.rate = stm / stt;
  return out;
}

} // namespace

TEST_CASE("Beverloo: the discharge of a bin follows W = C rho_b sqrt(g) (D - k d)^(5/2)",
          "[long]") {
  const std::vector<double> orifices{0.040, 0.050, 0.060};
  std::vector<double> x, y;
  double rho_b = 0;
  for (double D : orifices) {
    const Discharge r = discharge(D);
    INFO("D = " << D << " m: W = " << r.rate << " kg/s, rho_b = " << r.bulk_density << " kg/m^3, "
                << r.n_particles << " particles");
    REQUIRE(r.rate > 0);
    x.push_back(D);
    y.push_back(std::pow(r.rate, 0.4));
    rho_b += r.bulk_density / double(orifices.size());
    WARN("Beverloo: D = " << D << " m, W = " << r.rate << " kg/s, bulk density " << r.bulk_density
                          << " kg/m^3");
  }
  // W^(2/5) = (C rho_b sqrt(g))^(2/5) (D - k d): a straight line in D.
  const double n = double(x.size());
  double sx = 0, sy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sx += x[k];
    sy += y[k];
  }
  const double mx = sx / n, my = sy / n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
    syy += (y[k] - my) * (y[k] - my);
  }
  const double slope = sxy / sxx, intercept = my - slope * mx;
  const double r2 = sxy * sxy / (sxx * syy);
  const double C = std::pow(slope, 2.5) / (rho_b * std::sqrt(g));
  const double k = -intercept / (slope * d);
  WARN("Beverloo fit: C = " << C << ", k = " << k << ", R^2 = " << r2 << ", rho_b = " << rho_b);
  CHECK(r2 >= 0.99);
  CHECK(C >= 0.5);
  CHECK(C <= 0.7);
  CHECK(k >= 1);
  CHECK(k <= 3);
}

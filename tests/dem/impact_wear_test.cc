// Impact wear (dem/engine/impact_measure.h, the finnie, oka and sliding-impact laws of
// dem/wear/wear_law.h): a sphere striking a flat wearing wall at 2 to 10 m/s and 10 to 90
// degrees removes the volume of Finnie's and Oka's analytic curves, with their peak angle and
// speed exponent; a resting sphere removes nothing and a bouncing one books one impact per
// bounce; a sliding sphere under the combined law removes the Archard volume and no impact
// volume; the per-face impact sums of a window add up to the per-contact totals.
#include "dem/wear/wear_law.h"
#include "meshes/structured_grid.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::Vec3;

namespace {

constexpr double r = 4e-3;                                      ///< [m]
constexpr double density = 2650;                                ///< [kg/m^3]
const double mass = density * 4.0 / 3.0 * wear::pi * r * r * r; ///< [kg]

WearLawParameters law_named(const std::string& model) {
  WearLawParameters p;
  p.model = model;
  return p;
}

/// A system with a wearing square plate (material of the particle, e, mu) booking the law's
/// impact measure.
int plate_system(System& s, const WearLawParameters& law, double e, double mu, bool gravity) {
  const int g = s.materials.add({"gravel", 5e7, 0.25, density});
  s.materials.set_pair(g, g, {e, mu, 0.0});
  if (!gravity)
    s.settings.gravity = {};
  s.settings.impact = impact_measure(law);
  return s.add_wall(MeshWall(flat_square(0.05, 5), g, {}, true, "plate"));
}

/// One sphere striking the plate at speed v [m/s] and angle alpha [deg] to it, no gravity,
/// from 0.1 mm above it, until well after it left: the law's volume and the impact count.
std::pair<double, double> strike(const WearLawParameters& law, double v, double alpha_deg) {
  System s;
  const int w = plate_system(s, law, 0.5, 0.3, false);
  const double a = alpha_deg * wear::pi / 180;
  s.particles.add({-0.02, 0, r + 1e-4}, {v * std::cos(a), 0, -v * std::sin(a)}, r, density, 0);
  s.setup();
  while (s.time() < 1e-4 / (v * std::sin(a)) + 1e-3)
    s.run(10);
  const WearIntegrals wi = s.wear_integrals(w);
  return {make_wear_law(law)->total_removed_volume(wi), wi.total_impacts};
}

/// The angle [deg] of the largest of f over 0.1-degree steps in [lo, hi].
template <class F>
double peak_angle(F f, double lo, double hi) {
  double best = lo, best_value = -1;
  for (double a = lo; a <= hi + 1e-9; a += 0.1)
    if (f(a) > best_value) {
      best_value = f(a);
      best = a;
    }
  return best;
}

/// The slope of log V against log v over the speeds 2 to 10 m/s at angle alpha.
double speed_exponent(const WearLawParameters& law, double alpha_deg) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int n = 5;
  for (int k = 0; k < n; ++k) {
    const double v = 2.0 + 2.0 * k, x = std::log(v), y = std::log(strike(law, v, alpha_deg).first);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace

TEST_CASE("impact wear: a sphere striking a wall removes Finnie's volume", "[dem][impact]") {
  const WearLawParameters law = law_named("finnie");
  const double k_f = law.finnie_coefficient;
  for (const double v : {2.0, 6.0, 10.0})
    for (int alpha = 10; alpha <= 90; alpha += 10) {
      const auto [volume, impacts] = strike(law, v, alpha);
      const double expected =
          k_f * mass * v * v * finnie_angle_function(alpha * wear::pi / 180, law.finnie_k);
      INFO("v = " << v << " m/s, alpha = " << alpha << " deg");
      CHECK(impacts == 1);
      CHECK(std::abs(volume - expected) <= 0.02 * expected + 1e-30);
    }
  // Finnie's peak (K = 2): tan 2 alpha = 2/3, alpha = 16.85 degrees.
  const double analytic = 0.5 * std::atan(2.0 / 3.0) * 180 / wear::pi;
  const double measured = peak_angle([&](double a) { return strike(law, 5, a).first; }, 12, 22);
  CHECK(std::abs(measured - analytic) <= 0.15);
  CHECK(speed_exponent(law, 30) == Approx(2).epsilon(0.02));
  // Normal impact leaves no cutting wear (the second regime's K cos^2 / 6 vanishes).
  CHECK(strike(law, 5, 90).first <= 1e-12 * k_f * mass * 25);
}

TEST_CASE("impact wear: a sphere striking a wall removes Oka's volume", "[dem][impact]") {
  const WearLawParameters law = law_named("oka");
  const double scale = law.oka_coefficient * std::pow(law.oka_hardness, law.oka_k1);
  const double d = 2 * r;
  for (const double v : {2.0, 6.0, 10.0})
    for (int alpha = 10; alpha <= 90; alpha += 10) {
      const auto [volume, impacts] = strike(law, v, alpha);
      const double sin_a = std::sin(alpha * wear::pi / 180);
      const double expected = scale * mass * std::pow(v / 104, law.oka_k2) *
                              std::pow(d / 326e-6, law.oka_k3) * std::pow(sin_a, law.oka_n1) *
                              std::pow(1 + law.oka_hardness * (1 - sin_a), law.oka_n2);
      INFO("v = " << v << " m/s, alpha = " << alpha << " deg");
      CHECK(impacts == 1);
      CHECK(std::abs(volume - expected) <= 0.02 * expected);
    }
  // The peak of sin^n1 (1 + Hv (1 - sin))^n2, from the analytic curve on the same grid.
  const auto g = [&](double a) {
    const double s = std::sin(a * wear::pi / 180);
    return std::pow(s, law.oka_n1) * std::pow(1 + law.oka_hardness * (1 - s), law.oka_n2);
  };
  const double analytic = peak_angle(g, 5, 60);
  const double measured =
      peak_angle([&](double a) { return strike(law, 5, a).first; }, analytic - 3, analytic + 3);
  INFO("analytic peak " << analytic << " deg");
  CHECK(std::abs(measured - analytic) <= 0.15);
  CHECK(speed_exponent(law, 45) == Approx(law.oka_k2).epsilon(0.02));
}

TEST_CASE("impact wear: a resting sphere removes nothing, a bouncing one books each bounce",
          "[dem][impact]") {
  for (const char* model : {"finnie", "oka", "sliding-impact"}) {
    INFO(model);
    const WearLawParameters law = law_named(model);
    {
      System s;
      const int w = plate_system(s, law, 0.5, 0.5, true);
      const double e_star = 5e7 / (2 * (1 - 0.0625));
      const double delta = std::pow(mass * 9.81 / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);
      s.particles.add({0.001, 0.002, r - delta}, {}, r, density, 0);
      s.setup();
      s.run(3000);
      const WearIntegrals wi = s.wear_integrals(w);
      CHECK(wi.total_impacts == 0);
      for (const auto& [mechanism, volume] : make_wear_law(law)->removed_by_mechanism(wi))
        for (const double v : volume)
          CHECK((mechanism == "sliding" || v == 0));
    }
    System s;
    const int w = plate_system(s, law, 0.8, 0.5, true);
    s.particles.add({0.001, 0.002, r + 0.02}, {}, r, density, 0);
    s.setup();
    int bounces = 0;
    double vz = 0;
    while (s.time() < 0.4) {
      s.run(1);
      const double now = s.particles.velocity[0].z;
      bounces += vz < 0 && now >= 0;
      vz = now;
    }
    const WearIntegrals wi = s.wear_integrals(w);
    CHECK(bounces >= 4);
    CHECK(wi.total_impacts == bounces);
    // The first impact alone brings the energy of the drop, m g h.
    CHECK(wi.total_impact_energy > mass * 9.81 * 0.02 * 0.99);
  }
}

TEST_CASE("impact wear: a sliding sphere under the combined law removes the Archard volume",
          "[dem][impact]") {
  WearLawParameters law = law_named("sliding-impact");
  law.sliding_coefficient = 5e-9;
  law.impact_coefficient = 1e-6;
  System s;
  const int w = plate_system(s, law, 0.5, 0.3, true);
  const double e_star = 5e7 / (2 * (1 - 0.0625));
  const double delta = std::pow(mass * 9.81 / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);
  s.particles.add({-0.02, 0, r - delta}, {0.5, 0, 0}, r, density, 0);
  s.setup();
  s.run(2000);
  const WearIntegrals wi = s.wear_integrals(w);
  const auto combined = make_wear_law(law);
  WearLawParameters archard = law_named("archard");
  archard.archard_coefficient = 5e-9;
  CHECK(wi.total_archard > 0);
  CHECK(wi.total_impacts == 0);
  CHECK(combined->total_removed_volume(wi) == make_wear_law(archard)->total_removed_volume(wi));
  double sliding = 0, impact = 0;
  for (const auto& [mechanism, volume] : combined->removed_by_mechanism(wi))
    for (const double v : volume)
      (mechanism == "impact" ? impact : sliding) += v;
  CHECK(impact == 0);
  CHECK(sliding == Approx(5e-9 * wi.total_archard).epsilon(1e-12));
}

TEST_CASE("impact wear: the faces' impact sums add up to the contacts' totals", "[dem][impact]") {
  // 40 spheres raining at random places and angles onto a coarse plate (2 x 2 quads, so many
  // strike an edge or a vertex and split their impact over the faces that share it).
  const WearLawParameters law = law_named("finnie");
  System s;
  const int g = s.materials.add({"gravel", 5e7, 0.25, density});
  s.materials.set_pair(g, g, {0.5, 0.3, 0.0});
  s.settings.gravity = {};
  s.settings.impact = impact_measure(law);
  const int w = s.add_wall(MeshWall(flat_square(0.05, 2), g, {}, true, "plate"));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 40; ++k) {
    // Every fifth on the middle vertex or an edge through it.
    const Vec3 at = k % 5 == 0 ? Vec3{k % 10 == 0 ? 0.0 : 0.01 * u(rng), 0, 0}
                               : Vec3{0.04 * u(rng), 0.04 * u(rng), 0};
    const Vec3 v{2 * u(rng), 2 * u(rng), -1.5 - std::abs(u(rng))};
    const double t_hit = 1e-4 + 1e-3 * k; // [s] one after another
    s.particles.add(at + Vec3{0, 0, r} - v * t_hit, v, r, density, g);
  }
  s.setup();
  while (s.time() < 0.05)
    s.run(20);
  const WearIntegrals wi = s.wear_integrals(w);
  double impacts = 0, measure = 0, energy = 0;
  for (std::size_t f = 0; f < wi.impacts.size(); ++f) {
    impacts += wi.impacts[f];
    measure += wi.impact_measure[f];
    energy += wi.impact_energy[f];
  }
  CHECK(wi.total_impacts >= 30); // some meet another sphere on its way back
  CHECK(impacts == Approx(wi.total_impacts).epsilon(1e-12));
  CHECK(measure == Approx(wi.total_impact_measure).epsilon(1e-12));
  CHECK(energy == Approx(wi.total_impact_energy).epsilon(1e-12));
  const auto volumes = make_wear_law(law)->removed_volume(wi);
  double sum = 0;
  for (const double v : volumes)
    sum += v;
  CHECK(sum == Approx(make_wear_law(law)->total_removed_volume(wi)).epsilon(1e-12));
}

// The impact wear laws' angle functions and the per-impact measure (impact_measure.h).
//
// Finnie (1960), ductile cutting by a rigid particle of mass m at speed v and angle alpha:
//   V = c m v^2 / (p psi K) f_K(alpha),
//   f_K = sin 2 alpha - (6/K) sin^2 alpha   for tan alpha <= K/6,
//   f_K = K cos^2 alpha / 6                 for tan alpha >  K/6,
// p the flow pressure, psi the ratio of contact length to cut depth, K the ratio of the
// vertical to the horizontal force on the particle's tip; the two branches meet at tan alpha =
// K/6. With K = 2 the peak is at alpha = atan(2/3)/2 = 16.8 deg and f vanishes at 90 deg. The
// engine books m v^2 f_K; the law's coefficient is c / (p psi K) [1/Pa].
//
// Oka et al. (2005), volume per particle mass at normal impact E90 times the angle function:
//   V = m E90 g(alpha),  E90 = K Hv^k1 (v / v')^k2 (d / d')^k3,
//   g(alpha) = sin^n1(alpha) (1 + Hv (1 - sin alpha))^n2,
// Hv the Vickers hardness [GPa], v' = 104 m/s and d' = 326 um the reference speed and size.
// The engine books m (v/v')^k2 (d/d')^k3 g(alpha); the law multiplies by K Hv^k1 [m^3/kg].
#include "dem/engine/impact_measure.h"

#include <algorithm>
#include <cmath>

namespace wear::dem {

double finnie_angle_function(double alpha, double k) {
  const double s = std::sin(alpha), c = std::cos(alpha);
  if (std::tan(alpha) <= k / 6)
    return std::max(0.0, 2 * s * c - 6 / k * s * s);
  return k * c * c / 6;
}

double oka_angle_function(double sin_alpha, double n1, double n2, double hardness) {
  return std::pow(sin_alpha, n1) * std::pow(1 + hardness * (1 - sin_alpha), n2);
}

double ImpactMeasure::operator()(double m, double d, double v, double sin_alpha) const {
  sin_alpha = std::clamp(sin_alpha, 0.0, 1.0);
  switch (kind) {
  case Kind::finnie:
    return m * v * v * finnie_angle_function(std::asin(sin_alpha), finnie_k);
  case Kind::oka:
    return m * std::pow(v / reference_speed, speed_exponent) *
           std::pow(d / reference_diameter, size_exponent) *
           oka_angle_function(sin_alpha, oka_n1, oka_n2, oka_hardness);
  case Kind::none:
    break;
  }
  return 0;
}

} // namespace wear::dem

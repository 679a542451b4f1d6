// Materials, pair properties and the restitution-to-damping mapping.
//
// Effective moduli (docs/theory.md section 2): 1/E* = sum (1 - nu^2)/E, 1/G* = sum 2 (2 - nu)(1 +
// nu)/E. Damping: beta = ln e / sqrt(ln^2 e + pi^2). With x = L X, t = (L / v0) T and L = (m v0^2 /
// K)^(2/5), K = 4/3 E* sqrt(R*), the damped Hertz impact becomes X'' = -(X^(3/2) - sqrt(5) beta
// X^(1/4) X'), independent of m, R, E and v0; the realised restitution is therefore a function of
// beta alone. Integrated with RK4 until the overlap closes; with the force clamped at zero the last
// phase is force-free.
#include "dem/engine/material.h"

#include "meshes/constants.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace wear::dem {

namespace {
void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument(what);
}
} // namespace

int MaterialTable::add(const Material& m) {
  require(m.youngs_modulus > 0, "material '" + m.name + "': Young's modulus must be positive [Pa]");
  require(m.poisson_ratio > -1 && m.poisson_ratio < 0.5,
          "material '" + m.name + "': Poisson's ratio must lie in (-1, 0.5)");
  require(m.density > 0 && std::isfinite(m.density),
          "material '" + m.name + "': density must be positive and finite [kg/m^3]");
  const int n = n_materials();
  std::vector<PairProperties> p((n + 1) * (n + 1));
  std::vector<bool> s((n + 1) * (n + 1), false);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      p[a * (n + 1) + b] = pairs_[a * n + b];
      s[a * (n + 1) + b] = pair_set_[a * n + b];
    }
  pairs_ = std::move(p);
  pair_set_ = std::move(s);
  materials_.push_back(m);
  return n;
}

void MaterialTable::set_pair(int a, int b, const PairProperties& p) {
  const int n = n_materials();
  require(a >= 0 && a < n && b >= 0 && b < n, "material pair id out of range");
  const std::string who = "pair (" + materials_[a].name + ", " + materials_[b].name + "): ";
  require(p.restitution > 0 && p.restitution <= 1, who + "restitution must lie in (0, 1]");
  require(p.friction >= 0, who + "friction must not be negative");
  require(p.rolling_friction >= 0 && p.rolling_friction <= max_rolling_friction,
          who + "rolling friction must lie in [0, 1] (max_rolling_friction)");
  pairs_[a * n + b] = pairs_[b * n + a] = p;
  pair_set_[a * n + b] = pair_set_[b * n + a] = true;
}

const PairProperties& MaterialTable::pair(int a, int b) const {
  return pairs_.at(a * n_materials() + b);
}

std::vector<ContactParameters> MaterialTable::contact_table() const {
  const int n = n_materials();
  std::vector<ContactParameters> t(n * n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      if (!pair_set_[a * n + b])
        throw std::invalid_argument("no contact properties for pair (" + materials_[a].name + ", " +
                                    materials_[b].name + ")");
      const Material &A = materials_[a], &B = materials_[b];
      const auto inv_e = [](const Material& m) {
        return std::isinf(m.youngs_modulus)
                   ? 0.0
                   : (1 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
      };
      const auto inv_g = [](const Material& m) {
        return std::isinf(m.youngs_modulus)
                   ? 0.0
                   : 2 * (2 - m.poisson_ratio) * (1 + m.poisson_ratio) / m.youngs_modulus;
      };
      const PairProperties& p = pairs_[a * n + b];
      ContactParameters& c = t[a * n + b];
      c.e_star = 1 / (inv_e(A) + inv_e(B));
      c.g_star = 1 / (inv_g(A) + inv_g(B));
      c.beta = mapping_ == RestitutionMapping::exact ? exact_damping_ratio(p.restitution)
                                                     : classical_damping_ratio(p.restitution);
      c.friction = p.friction;
      c.rolling_friction = p.rolling_friction;
      c.tangential_damping_ratio = std::sqrt(4 * c.g_star / c.e_star);
    }
  return t;
}

double classical_damping_ratio(double e) {
  if (e >= 1)
    return 0;
  const double l = std::log(e);
  return l / std::sqrt(l * l + pi * pi);
}

double realised_restitution(double beta) {
  const double c = -std::sqrt(5.0) * beta; // >= 0
  const auto acc = [c](double x, double v) {
    if (x <= 0)
      return 0.0;
    const double f = std::pow(x, 1.5) + c * std::pow(x, 0.25) * v;
    return f > 0 ? -f : 0.0;
  };
  // Contact lasts about 3.2 dimensionless time units; 3e4 RK4 steps resolve e to ~1e-8.
  const double h = 1e-4;
  double x = 0, v = 1;
  for (int i = 0; i < 10000000; ++i) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    const double xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xn <= 0 && i > 0)
      return -vn;
    x = xn;
    v = vn;
  }
  return 0;
}

double exact_damping_ratio(double e) {
  if (e >= 1)
    return 0;
  // realised_restitution decreases monotonically as beta goes from 0 to -1.
  double lo = -1.0, hi = 0.0;
  while (realised_restitution(lo) > e)
    lo *= 2;
  for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
    const double mid = 0.5 * (lo + hi);
    (realised_restitution(mid) > e ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

} // namespace wear::dem

// Means with 95 % intervals for `wearsim compare`.
//
// One run: the values x_1..x_n of the revolutions after steady state are correlated (the bed
// carries its state from one revolution to the next), so s / sqrt(n) would understate the
// error. Batch means: the series is cut into k batches of b values, the batch means y_j are
// nearly independent once b is a few integrated autocorrelation times
//   tau = 1 + 2 sum_{t>=1} rho(t)          (Var(mean) = tau sigma^2 / n for large n),
// and mean = mean(y), se = s_y / sqrt(k) with k - 1 degrees of freedom. tau is estimated by
// Sokal's automatic window: rho(t) from the series' autocovariance (divisor n), summed up to
// the smallest M with M >= 5 tau(M) (beyond that the estimate only adds noise). The batch size
// is b = ceil(5 tau), with at least 5 batches kept (b <= n / 5). Why 5 tau: for an AR(1)
// series the batch-means variance falls short of the true one by about tau / (2 b) (the
// correlation inside a batch and between neighbouring batches), and tau itself is
// underestimated on short series; b = 2 tau covered the mean in 92 % of draws (n = 200,
// phi = 0.5, 2000 draws), b = 5 tau in 94.6 %, b = 10 tau in 95.3 % (within the draws'
// scatter of 0.5 %) with half as many batches, so a wider interval on short series.
// The floor of 5 batches keeps t_{0.975,k-1} <= 2.78 on short series, where a large b would
// leave too few batches for a usable interval; there the interval is too narrow when the
// series is strongly correlated (n = 40, phi = 0.8: 88 % coverage), so several runs per side
// are the better answer. The first n mod b values are dropped (they lie nearest to the
// transient). Coverage figures: tests/coupling/interval_test.cc and docs/coupling.md.
//
// Several runs: each run's mean is one independent value; se = s / sqrt(m), m - 1 dof.
//
// Reduction R = 1 - B/A: the delta method for independent A and B,
//   se_R^2 = c_A + c_B,  c_A = B^2 se_A^2 / A^4,  c_B = se_B^2 / A^2
// (= (B/A)^2 (se_A^2/A^2 + se_B^2/B^2)), with Welch-Satterthwaite degrees of freedom
//   nu = (c_A + c_B)^2 / (c_A^2 / nu_A + c_B^2 / nu_B).
// It assumes se_A / A is small (below about 0.3); Fieller's interval would be exact for
// normal A and B but is unbounded when A's interval reaches 0.
//
// Student-t quantile: the distribution function for t >= 0 is
//   F(t) = 1 - I_x(nu/2, 1/2) / 2,  x = nu / (nu + t^2),
// with I the regularized incomplete beta function (continued fraction, modified Lentz), and
// t_p is found by bisection on F (monotone), to a relative 1e-14. The normal quantile
// (nu = infinity, or nu > 1e8 where t and normal agree to 1e-8) by bisection on erfc.
#include "coupling/analysis/interval.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wear::coupling {

namespace {
// Continued fraction of the incomplete beta function (converges fast for x < (a+1)/(a+b+2)).
double beta_fraction(double a, double b, double x) {
  const double tiny = 1e-300;
  double c = 1, d = 1 - (a + b) * x / (a + 1);
  d = 1 / (std::abs(d) < tiny ? tiny : d);
  double h = d;
  for (int m = 1; m < 10000; ++m) {
    for (int half = 0; half < 2; ++half) {
      const double num = half == 0 ? m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m))
                                   : -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1));
      d = 1 + num * d;
      d = 1 / (std::abs(d) < tiny ? tiny : d);
      c = 1 + num / c;
      if (std::abs(c) < tiny)
        c = tiny;
      h *= d * c;
      if (half == 1 && std::abs(d * c - 1) < 1e-16)
        return h;
    }
  }
  return h;
}

double incomplete_beta(double a, double b, double x) {
  if (x <= 0)
    return 0;
  if (x >= 1)
    return 1;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1) / (a + b + 2))
    return front * beta_fraction(a, b, x) / a;
  return 1 - front * beta_fraction(b, a, 1 - x) / b;
}

// P(T <= t) for t >= 0.
double t_cdf_upper(double t, double dof) {
  return 1 - 0.5 * incomplete_beta(0.5 * dof, 0.5, dof / (dof + t * t));
}

double bisect(double p, double (*cdf)(double, double), double dof) {
  double lo = 0, hi = 1;
  while (cdf(hi, dof) < p)
    hi *= 2;
  for (int k = 0; k < 200 && hi - lo > 1e-14 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (cdf(mid, dof) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double normal_cdf(double z, double) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

// Sokal's windowed integrated autocorrelation time (1 for a constant series).
double autocorrelation_time(const std::vector<double>& x, double mean) {
  const std::size_t n = x.size();
  const auto autocovariance = [&](std::size_t lag) {
    double s = 0;
    for (std::size_t i = 0; i + lag < n; ++i)
      s += (x[i] - mean) * (x[i + lag] - mean);
    return s / double(n);
  };
  const double c0 = autocovariance(0);
  if (!(c0 > 0))
    return 1;
  double tau = 1;
  for (std::size_t lag = 1; lag < n; ++lag) {
    tau += 2 * autocovariance(lag) / c0;
    if (double(lag) >= 5 * tau)
      break;
  }
  return tau;
}

double sample_variance(const std::vector<double>& v, double mean) {
  double s = 0;
  for (double x : v)
    s += (x - mean) * (x - mean);
  return s / double(v.size() - 1);
}

Estimate finish(Estimate e) {
  e.half_width = e.standard_error > 0 ? student_t_quantile(0.975, e.dof) * e.standard_error : 0;
  return e;
}
} // namespace

double mean_of(const std::vector<double>& v) {
  double s = 0;
  for (double x : v)
    s += x;
  return s / double(v.size());
}

double student_t_quantile(double p, double dof) {
  if (!(p > 0 && p < 1))
    throw std::invalid_argument("student_t_quantile: p = " + std::to_string(p) +
                                " is not in (0, 1)");
  if (!(dof > 0))
    throw std::invalid_argument("student_t_quantile: degrees of freedom " + std::to_string(dof) +
                                " must be positive");
  if (p < 0.5)
    return -student_t_quantile(1 - p, dof);
  if (p == 0.5)
    return 0;
  if (dof > 1e8)
    return bisect(p, normal_cdf, dof);
  return bisect(p, t_cdf_upper, dof);
}

Estimate batch_means(const std::vector<double>& series) {
  const int n = int(series.size());
  if (n < 2)
    throw std::invalid_argument("batch means: " + std::to_string(n) +
                                " value(s); an interval needs at least 2");
  Estimate e;
  e.n_values = n;
  e.tau = autocorrelation_time(series, mean_of(series));
  e.batch_size = std::max(1, std::min(int(std::ceil(5 * e.tau)), n / 5));
  e.n_batches = n / e.batch_size;
  const int first = n - e.n_batches * e.batch_size;
  std::vector<double> batch(std::size_t(e.n_batches), 0.0);
  for (int i = first; i < n; ++i)
    batch[std::size_t((i - first) / e.batch_size)] += series[std::size_t(i)] / e.batch_size;
  e.mean = mean_of(batch);
  e.standard_error = std::sqrt(sample_variance(batch, e.mean) / e.n_batches);
  e.dof = e.n_batches - 1;
  return finish(e);
}

Estimate independent_mean(const std::vector<double>& values) {
  const int n = int(values.size());
  if (n < 2)
    throw std::invalid_argument("independent mean: " + std::to_string(n) +
                                " value(s); an interval needs at least 2");
  Estimate e;
  e.n_values = e.n_batches = n;
  e.mean = mean_of(values);
  e.standard_error = std::sqrt(sample_variance(values, e.mean) / n);
  e.dof = n - 1;
  return finish(e);
}

Estimate reduction(const Estimate& a, const Estimate& b) {
  if (a.mean == 0)
    throw std::invalid_argument("reduction: the reference mean A is 0");
  const double q = b.mean / a.mean;
  // The two terms of Var(B/A) = se_B^2 / A^2 + B^2 se_A^2 / A^4 (also for B = 0).
  const double ca = q * q * a.standard_error * a.standard_error / (a.mean * a.mean);
  const double cb = b.standard_error * b.standard_error / (a.mean * a.mean);
  Estimate r;
  r.mean = 1 - q;
  r.standard_error = std::sqrt(ca + cb);
  const double denominator = (a.dof > 0 ? ca * ca / a.dof : 0) + (b.dof > 0 ? cb * cb / b.dof : 0);
  r.dof = denominator > 0 ? (ca + cb) * (ca + cb) / denominator : std::max(a.dof, b.dof);
  r.n_values = a.n_values + b.n_values;
  return finish(r);
}

} // namespace wear::coupling

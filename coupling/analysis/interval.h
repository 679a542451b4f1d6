#pragma once
// Confidence intervals for `wearsim compare`: the mean of a short, possibly autocorrelated
// series (one run's per-revolution values after steady state) by batch means, the mean of
// independent runs, the reduction 1 - B/A of two such means, and Student-t quantiles.
#include <string>
#include <vector>

namespace wear::coupling {

/// The quantile t_{p,dof} of Student's t distribution: P(T <= t) = p, for 0 < p < 1 and
/// dof > 0 (real, as Welch-Satterthwaite gives); dof = infinity gives the normal quantile.
/// Throws for p or dof outside that range.
double student_t_quantile(double p, double dof);

/// Arithmetic mean of a non-empty series.
double mean_of(const std::vector<double>& v);

/// A mean with its uncertainty. Units are those of the values it was made from.
struct Estimate {
  double mean = 0;           ///< of the values
  double standard_error = 0; ///< of the mean
  double dof = 0;            ///< degrees of freedom of the standard error [-]
  double half_width = 0;     ///< of the two-sided 95 % interval, t_{0.975,dof} x standard error
  int n_values = 0;          ///< values (revolutions or runs) the mean is made of
  int batch_size = 1;        ///< values per batch (batch means; 1 for independent values)
  int n_batches = 0;         ///< batches the standard error is made of
  double tau = 1;            ///< [-] integrated autocorrelation time estimated from the series
  double low() const { return mean - half_width; }
  double high() const { return mean + half_width; }
};

/// Batch means of one series: the batch size is b = ceil(5 tau) for the series' integrated
/// autocorrelation time tau (Sokal's windowed estimate), lowered where needed so that at least
/// 5 batches remain; the first n mod b values are left out. Throws for fewer than 2 values.
Estimate batch_means(const std::vector<double>& series);

/// Mean over independent values (one per run): standard error s / sqrt(n), n - 1 dof.
/// Throws for fewer than 2 values.
Estimate independent_mean(const std::vector<double>& values);

/// The reduction R = 1 - B/A of two independent estimates by the delta method:
/// se_R^2 = (B/A)^2 (se_A^2 / A^2 + se_B^2 / B^2), dof by Welch-Satterthwaite from the two
/// terms. Throws when A's mean is 0.
Estimate reduction(const Estimate& a, const Estimate& b);

/// True when the 95 % interval of a difference (or reduction) excludes 0.
inline bool significant(const Estimate& e) {
  return e.low() > 0 || e.high() < 0;
}

} // namespace wear::coupling

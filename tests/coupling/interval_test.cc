// The intervals of `wearsim compare` (coupling/analysis/interval.cc):
// - Student-t quantiles against tabulated values (Abramowitz & Stegun table 26.10), 1e-5;
// - batch means on AR(1) series x_i = mu + phi (x_{i-1} - mu) + e_i (unit normal e, stationary
//   start; integrated autocorrelation time (1 + phi) / (1 - phi)): the 95 % interval covers
//   mu in 95 +- 2 % of 2000 series of 200 values, for phi = 0.5 and phi = 0 (seed 36);
// - the reduction 1 - B/A by the delta method on constructed estimates, against values worked
//   out independently (the t quantiles at Welch-Satterthwaite dof by Simpson integration of
//   the t density and bisection, in Python), 1e-5.
#include "coupling/analysis/interval.h"
#include "meshes/constants.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>

using namespace wear::coupling;

namespace {
// Unit normal numbers from mt19937_64 by Box-Muller: the same on every standard library
// (std::normal_distribution is not).
class Normal {
public:
  explicit Normal(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = (double(rng_() >> 11) + 0.5) * 0x1.0p-53,
                 u2 = double(rng_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2 * std::log(u1)), angle = 2 * wear::pi * u2;
    spare_ = r * std::sin(angle);
    has_spare_ = true;
    return r * std::cos(angle);
  }

private:
  std::mt19937_64 rng_;
  double spare_ = 0;
  bool has_spare_ = false;
};

std::vector<double> ar1(Normal& z, int n, double phi, double mu) {
  std::vector<double> x(static_cast<std::size_t>(n));
  double v = z() / std::sqrt(1 - phi * phi);
  for (int i = 0; i < n; ++i) {
    if (i > 0)
      v = phi * v + z();
    x[std::size_t(i)] = mu + v;
  }
  return x;
}

struct Coverage {
  double fraction = 0;   ///< of the draws whose interval holds mu
  double batch_size = 0; ///< mean over the draws
};

Coverage coverage(int n, double phi, int draws, std::uint64_t seed) {
  Normal z(seed);
  Coverage c;
  const double mu = 3;
  for (int d = 0; d < draws; ++d) {
    const Estimate e = batch_means(ar1(z, n, phi, mu));
    c.fraction += std::abs(e.mean - mu) <= e.half_width ? 1.0 / draws : 0;
    c.batch_size += double(e.batch_size) / draws;
  }
  return c;
}
} // namespace

TEST_CASE("Student-t quantiles match the tables", "[coupling][interval]") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(std::abs(student_t_quantile(0.975, 4) - 2.776445) < 1e-5);
  CHECK(std::abs(student_t_quantile(0.975, 10) - 2.228139) < 1e-5);
  CHECK(std::abs(student_t_quantile(0.975, inf) - 1.959964) < 1e-5);
  CHECK(std::abs(student_t_quantile(0.975, 1) - 12.706205) < 1e-5);
  CHECK(std::abs(student_t_quantile(0.975, 2) - 4.302653) < 1e-5);
  CHECK(std::abs(student_t_quantile(0.995, 30) - 2.749996) < 1e-5);
  CHECK(std::abs(student_t_quantile(0.95, 1000) - 1.646379) < 1e-5);
  CHECK(std::abs(student_t_quantile(0.9995, 3) - 12.923979) < 1e-5);
  // Symmetry, and the median.
  CHECK(student_t_quantile(0.025, 4) == -student_t_quantile(0.975, 4));
  CHECK(student_t_quantile(0.5, 7) == 0);
  CHECK_THROWS_WITH(student_t_quantile(1.0, 4), Catch::Contains("p = 1"));
  CHECK_THROWS_WITH(student_t_quantile(0.975, 0), Catch::Contains("degrees of freedom"));
}

TEST_CASE("batch means: the 95 % interval of an AR(1) series covers its mean 95 +- 2 % of the "
          "time",
          "[coupling][interval]") {
  // phi = 0.5: autocorrelation time 3, batches of about 14; phi = 0: independent values.
  for (const double phi : {0.5, 0.0}) {
    const Coverage c = coverage(200, phi, 2000, 36);
    INFO("phi " << phi << ": coverage " << c.fraction << ", mean batch size " << c.batch_size);
    std::printf("AR(1) phi %.1f, n 200, 2000 draws, seed 36: coverage %.4f, mean batch size "
                "%.2f\n",
                phi, c.fraction, c.batch_size);
    CHECK(std::abs(c.fraction - 0.95) <= 0.02);
  }
  // Short and odd inputs.
  CHECK_THROWS_WITH(batch_means({1.0}), Catch::Contains("at least 2"));
  const Estimate flat = batch_means(std::vector<double>(12, 4.0));
  CHECK(flat.mean == 4.0);
  CHECK(flat.half_width == 0);
  // Independent values of one batch each: the ordinary t interval of the mean.
  const Estimate two = batch_means({1.0, 3.0});
  CHECK(two.batch_size == 1);
  CHECK(two.mean == 2.0);
  CHECK(two.half_width == Approx(12.706205).epsilon(1e-6)); // s = sqrt(2), se = 1
}

TEST_CASE("batch means: coverage over series lengths and correlations",
          "[coupling][interval][long]") {
  // The table in docs/coupling.md (10000 draws each); the rule holds 95 +- 2 % from 200 values.
  for (const int n : {40, 100, 200, 500})
    for (const double phi : {0.0, 0.5, 0.8}) {
      const Coverage c = coverage(n, phi, 10000, 36);
      std::printf("n %3d  phi %.1f  coverage %.4f  mean batch size %.2f\n", n, phi, c.fraction,
                  c.batch_size);
      if (n >= 200)
        CHECK(std::abs(c.fraction - 0.95) <= 0.02);
    }
}

TEST_CASE("the reduction 1 - B/A and its delta-method interval", "[coupling][interval]") {
  // Independent values of mean m and standard error se with dof: se_R^2 = c_A + c_B,
  // c_A = B^2 se_A^2 / A^4, c_B = se_B^2 / A^2, nu by Welch-Satterthwaite.
  Estimate a, b;
  a.mean = 10, a.standard_error = 1, a.dof = 4, a.half_width = 2.776445;
  b.mean = 8, b.standard_error = 0.5, b.dof = 9, b.half_width = 1.131;
  // c_A = 64/10^4 = 0.0064, c_B = 0.25/100 = 0.0025, se_R = sqrt(0.0089) = 0.0943398,
  // nu = 0.0089^2 / (0.0064^2/4 + 0.0025^2/9) = 7.244081, t_{0.975,7.244081} = 2.348569.
  const Estimate r = reduction(a, b);
  CHECK(r.mean == Approx(0.2).epsilon(1e-12));
  CHECK(r.standard_error == Approx(0.0943398).epsilon(1e-6));
  CHECK(r.dof == Approx(7.244081).epsilon(1e-6));
  CHECK(r.half_width == Approx(2.348569 * 0.0943398).epsilon(1e-5));
  CHECK_FALSE(significant(r)); // 20 +- 22 %: the interval holds 0

  // B = 5: c_A = c_B = 0.0025, se_R = 0.0707107, nu = 11.07692, t = 2.199122: 50 +- 15.6 %.
  b.mean = 5;
  const Estimate r2 = reduction(a, b);
  CHECK(r2.mean == Approx(0.5).epsilon(1e-12));
  CHECK(r2.dof == Approx(11.07692).epsilon(1e-6));
  CHECK(r2.half_width == Approx(2.199122 * 0.0707107).epsilon(1e-5));
  CHECK(significant(r2));
  CHECK_THROWS_WITH(reduction(Estimate{}, b), Catch::Contains("A is 0"));

  // Across runs: four runs' means 1, 2, 3, 6: mean 3, s = sqrt(14/3), se = 1.0801234, 3 dof.
  const Estimate runs = independent_mean({1, 2, 3, 6});
  CHECK(runs.mean == 3);
  CHECK(runs.standard_error == Approx(1.0801234).epsilon(1e-7));
  CHECK(runs.dof == 3);
  CHECK(runs.half_width == Approx(3.182446 * 1.0801234).epsilon(1e-6));
}

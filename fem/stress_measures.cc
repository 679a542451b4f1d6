// Stress measures over the quadrature points of a solve (stress_measures.h).
//
//   von Mises          sigma_vM = sqrt(3/2 s:s),  s = sigma - tr(sigma)/3 I
//   percentile p       min { v : sum_{q: vM_q <= v} w_q >= p sum_q w_q },  w_q = JxW_q
//   ball average at c  sigma_B(c) = sum_{q: |x_q - c| <= R} w_q sigma_q / sum_{q: ...} w_q,
//                      reported as sigma_vM(sigma_B(c))
// The ball is cut by the sample's boundary: only material inside counts, so a centre on the
// surface averages over the half ball below it. The quadrature points stand for the cells'
// volume: a cell cut by the sphere contributes the points inside, an error of the order of
// the cell size over R in the ball's volume, which the mean largely cancels. The tensor is
// averaged before von Mises is taken (the mean stress the material of that ball carries; the
// mean of von Mises would keep the peak's sharpness). Cost: each centre scans the bins of
// edge R/2 its ball overlaps (at most 5^3 = 125 when the grid is not capped), about 3.7 times
// the samples inside the ball.
#include "fem/stress_measures.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace wear::fem {

using dealii::Point;
using dealii::SymmetricTensor;

double von_mises(const SymmetricTensor<2, 3>& stress) {
  const auto d = dealii::deviator(stress);
  return std::sqrt(1.5 * dealii::scalar_product(d, d));
}

std::vector<double> volume_percentiles(const std::vector<double>& values,
                                       const std::vector<double>& weights,
                                       const std::vector<double>& fractions) {
  if (values.size() != weights.size() || values.empty())
    throw std::invalid_argument("volume_percentiles: " + std::to_string(values.size()) +
                                " values and " + std::to_string(weights.size()) +
                                " weights; need as many, at least one");
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  // Ties broken by index: the same samples give the same order on any platform.
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return values[a] < values[b] || (values[a] == values[b] && a < b);
  });
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  std::vector<double> out;
  for (const double f : fractions) {
    if (!(f > 0 && f <= 1))
      throw std::invalid_argument("volume_percentiles: fraction " + std::to_string(f) +
                                  " outside (0, 1]");
    double below = 0;
    std::size_t k = 0;
    for (; k + 1 < order.size(); ++k) {
      below += weights[order[k]];
      if (below >= f * total)
        break;
    }
    out.push_back(values[order[k]]);
  }
  return out;
}

BallAverage::BallAverage(const StressSamples& samples, double radius)
    : radius_(radius), bin_(radius / 2) {
  const std::size_t n = samples.points.size();
  if (!(radius > 0) || !std::isfinite(radius))
    throw std::invalid_argument("BallAverage: the radius must be positive [m], got " +
                                std::to_string(radius));
  if (samples.stress.size() != n || samples.weights.size() != n)
    throw std::invalid_argument("BallAverage: points, stresses and weights differ in number");
  Point<3> lo, hi;
  for (unsigned int d = 0; d < 3; ++d) {
    lo[d] = n ? samples.points[0][d] : 0;
    hi[d] = lo[d];
  }
  for (const auto& x : samples.points)
    for (unsigned int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[d]);
      hi[d] = std::max(hi[d], x[d]);
    }
  origin_ = lo;
  // A radius far below the sample's size would ask for more bins than samples: the bins grow
  // (a centre then scans more samples outside its ball, never misses one inside).
  const auto count = [&] {
    double total = 1;
    for (unsigned int d = 0; d < 3; ++d) {
      n_bins_[d] = long((hi[d] - lo[d]) / bin_) + 1;
      total *= double(n_bins_[d]);
    }
    return total;
  };
  while (count() > 4.0 * double(n) + 64)
    bin_ *= 1.25;
  const std::size_t n_total = std::size_t(n_bins_[0] * n_bins_[1] * n_bins_[2]);
  std::vector<std::size_t> bin_of(n);
  bin_start_.assign(n_total + 1, 0);
  for (std::size_t q = 0; q < n; ++q) {
    std::array<long, 3> b{};
    for (unsigned int d = 0; d < 3; ++d)
      b[d] = std::min(n_bins_[d] - 1, long((samples.points[q][d] - origin_[d]) / bin_));
    bin_of[q] = std::size_t((b[2] * n_bins_[1] + b[1]) * n_bins_[0] + b[0]);
    ++bin_start_[bin_of[q] + 1];
  }
  std::partial_sum(bin_start_.begin(), bin_start_.end(), bin_start_.begin());
  std::vector<std::size_t> next(bin_start_.begin(), bin_start_.end() - 1);
  points_.resize(n);
  weighted_.resize(n);
  weights_.resize(n);
  for (std::size_t q = 0; q < n; ++q) { // counting sort, stable: samples keep their order
    const std::size_t k = next[bin_of[q]]++;
    points_[k] = samples.points[q];
    weighted_[k] = samples.weights[q] * samples.stress[q];
    weights_[k] = samples.weights[q];
  }
}

SymmetricTensor<2, 3> BallAverage::mean_stress(const Point<3>& centre) const {
  std::array<long, 3> from{}, to{};
  for (unsigned int d = 0; d < 3; ++d) {
    from[d] = std::max(0L, long(std::floor((centre[d] - radius_ - origin_[d]) / bin_)));
    to[d] = std::min(n_bins_[d] - 1, long(std::floor((centre[d] + radius_ - origin_[d]) / bin_)));
  }
  const double r2 = radius_ * radius_;
  SymmetricTensor<2, 3> sum;
  double weight = 0;
  for (long k = from[2]; k <= to[2]; ++k)
    for (long j = from[1]; j <= to[1]; ++j) {
      const std::size_t row = std::size_t((k * n_bins_[1] + j) * n_bins_[0]);
      if (from[0] > to[0])
        continue;
      const std::size_t end = bin_start_[row + std::size_t(to[0]) + 1];
      for (std::size_t q = bin_start_[row + std::size_t(from[0])]; q < end; ++q)
        if ((points_[q] - centre).norm_square() <= r2) {
          sum += weighted_[q];
          weight += weights_[q];
        }
    }
  return weight > 0 ? sum / weight : sum;
}

std::vector<double> BallAverage::von_mises_at(const std::vector<Point<3>>& centres) const {
  std::vector<double> out(centres.size());
  const long n = long(centres.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (long c = 0; c < n; ++c)
    out[std::size_t(c)] = von_mises(mean_stress(centres[std::size_t(c)]));
  return out;
}

} // namespace wear::fem

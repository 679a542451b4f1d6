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
// mean of von Mises would keep the peak's sharpness). Cost: the samples are sorted into bins
// of edge R/4 with their sums; a centre visits the bins of its ball's bounding box (at most
// 9^3 when the grid is not capped), adds the sums of those wholly inside the ball and tests
// the samples of those its sphere cuts, about 1.5 times the samples in a shell of one bin's
// diagonal around the sphere.
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

StressSamples cell_means(const StressSamples& samples, unsigned int per_cell) {
  const std::size_t n = samples.points.size();
  if (per_cell == 0 || n % per_cell != 0 || samples.stress.size() != n ||
      samples.weights.size() != n)
    throw std::invalid_argument("cell_means: " + std::to_string(n) +
                                " samples are not whole groups of " + std::to_string(per_cell));
  StressSamples out;
  for (std::size_t c = 0; c < n; c += per_cell) {
    Point<3> x;
    SymmetricTensor<2, 3> stress;
    double w = 0;
    for (std::size_t q = c; q < c + per_cell; ++q) {
      x += samples.weights[q] * samples.points[q];
      stress += samples.weights[q] * samples.stress[q];
      w += samples.weights[q];
    }
    out.points.push_back(x / w);
    out.stress.push_back(stress / w);
    out.weights.push_back(w);
  }
  return out;
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
    : radius_(radius), bin_(radius / 4) {
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
  bin_weighted_.resize(n_total);
  bin_weight_.assign(n_total, 0);
  for (std::size_t b = 0; b < n_total; ++b)
    for (std::size_t q = bin_start_[b]; q < bin_start_[b + 1]; ++q) {
      bin_weighted_[b] += weighted_[q];
      bin_weight_[b] += weights_[q];
    }
}

SymmetricTensor<2, 3> BallAverage::mean_stress(const Point<3>& centre) const {
  std::array<long, 3> from{}, to{};
  for (unsigned int d = 0; d < 3; ++d) {
    from[d] = std::max(0L, long(std::floor((centre[d] - radius_ - origin_[d]) / bin_)));
    to[d] = std::min(n_bins_[d] - 1, long(std::floor((centre[d] + radius_ - origin_[d]) / bin_)));
  }
  const double r2 = radius_ * radius_;
  // Squared distances from the centre to the nearest and farthest point of bin slab i along
  // direction d.
  const auto near_far = [&](unsigned int d, long i) {
    const double lo = origin_[d] + double(i) * bin_ - centre[d], hi = lo + bin_;
    const double near = lo > 0 ? lo : (hi < 0 ? -hi : 0);
    const double far = std::max(std::abs(lo), std::abs(hi));
    return std::make_pair(near * near, far * far);
  };
  SymmetricTensor<2, 3> sum;
  double weight = 0;
  for (long k = from[2]; k <= to[2]; ++k) {
    const auto z = near_far(2, k);
    for (long j = from[1]; j <= to[1]; ++j) {
      const auto y = near_far(1, j);
      for (long i = from[0]; i <= to[0]; ++i) {
        const auto x = near_far(0, i);
        if (x.first + y.first + z.first > r2)
          continue;
        const std::size_t b = std::size_t((k * n_bins_[1] + j) * n_bins_[0] + i);
        if (x.second + y.second + z.second <= r2) { // the whole bin lies inside the ball
          sum += bin_weighted_[b];
          weight += bin_weight_[b];
          continue;
        }
        for (std::size_t q = bin_start_[b]; q < bin_start_[b + 1]; ++q)
          if ((points_[q] - centre).norm_square() <= r2) {
            sum += weighted_[q];
            weight += weights_[q];
          }
      }
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

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
// mean of von Mises would keep the peak's sharpness). Cost: the cells (groups of per_cell
// points) are sorted into bins of edge R/4 by centroid, with the sums of each cell and bin and
// the cells' extent e (farthest point from the centroid); a centre adds the sums of the bins
// lying within R - e, the sums of the cells within R - e of it, and tests single points only
// in the cells the sphere may cut (centroid within R +- e). Counting a cut cell whole or not by
// its centroid instead would be cheaper, but the ball's volume then jumps by whole cells:
// under a point load the largest average moved 6 % between h/R = 0.67 and 0.33 (P2) against
// 4 % with the points.
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

BallAverage::BallAverage(const StressSamples& samples, double radius, unsigned int per_cell)
    : radius_(radius), per_cell_(per_cell), bin_(radius / 4) {
  const std::size_t n = samples.points.size();
  if (!(radius > 0) || !std::isfinite(radius))
    throw std::invalid_argument("BallAverage: the radius must be positive [m], got " +
                                std::to_string(radius));
  if (samples.stress.size() != n || samples.weights.size() != n)
    throw std::invalid_argument("BallAverage: points, stresses and weights differ in number");
  if (per_cell == 0 || n % per_cell != 0)
    throw std::invalid_argument("BallAverage: " + std::to_string(n) +
                                " samples are not whole groups of " + std::to_string(per_cell));
  const std::size_t n_cells = n / per_cell;
  // Each cell's centroid, sums and extent (its farthest sample from the centroid), in the
  // samples' order.
  centroids_in_order_.resize(n_cells);
  volumes_in_order_.resize(n_cells);
  std::vector<SymmetricTensor<2, 3>> sum(n_cells);
  std::vector<double> extent(n_cells, 0);
  for (std::size_t c = 0; c < n_cells; ++c) {
    Point<3> x;
    double w = 0;
    for (std::size_t q = c * per_cell; q < (c + 1) * per_cell; ++q) {
      x += samples.weights[q] * samples.points[q];
      sum[c] += samples.weights[q] * samples.stress[q];
      w += samples.weights[q];
    }
    if (w > 0)
      x /= w;
    else
      x = samples.points[c * per_cell];
    for (std::size_t q = c * per_cell; q < (c + 1) * per_cell; ++q)
      extent[c] = std::max(extent[c], samples.points[q].distance(x));
    centroids_in_order_[c] = x;
    volumes_in_order_[c] = w;
  }
  Point<3> lo, hi;
  for (unsigned int d = 0; d < 3; ++d) {
    lo[d] = n_cells ? centroids_in_order_[0][d] : 0;
    hi[d] = lo[d];
  }
  for (const auto& x : centroids_in_order_)
    for (unsigned int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[d]);
      hi[d] = std::max(hi[d], x[d]);
    }
  origin_ = lo;
  // A radius far below the sample's size would ask for more bins than cells: the bins grow
  // (a centre then scans more cells outside its ball, never misses one inside).
  const auto count = [&] {
    double total = 1;
    for (unsigned int d = 0; d < 3; ++d) {
      n_bins_[d] = long((hi[d] - lo[d]) / bin_) + 1;
      total *= double(n_bins_[d]);
    }
    return total;
  };
  while (count() > 4.0 * double(n_cells) + 64)
    bin_ *= 1.25;
  const std::size_t n_total = std::size_t(n_bins_[0] * n_bins_[1] * n_bins_[2]);
  std::vector<std::size_t> bin_of(n_cells);
  bin_start_.assign(n_total + 1, 0);
  for (std::size_t c = 0; c < n_cells; ++c) {
    std::array<long, 3> b{};
    for (unsigned int d = 0; d < 3; ++d)
      b[d] = std::min(n_bins_[d] - 1, long((centroids_in_order_[c][d] - origin_[d]) / bin_));
    bin_of[c] = std::size_t((b[2] * n_bins_[1] + b[1]) * n_bins_[0] + b[0]);
    ++bin_start_[bin_of[c] + 1];
  }
  std::partial_sum(bin_start_.begin(), bin_start_.end(), bin_start_.begin());
  std::vector<std::size_t> next(bin_start_.begin(), bin_start_.end() - 1);
  cell_centroid_.resize(n_cells);
  cell_extent_.resize(n_cells);
  cell_weighted_.resize(n_cells);
  cell_weight_.resize(n_cells);
  points_.resize(n);
  weighted_.resize(n);
  weights_.resize(n);
  for (std::size_t c = 0; c < n_cells; ++c) { // counting sort, stable: cells keep their order
    const std::size_t k = next[bin_of[c]]++;
    cell_centroid_[k] = centroids_in_order_[c];
    cell_extent_[k] = extent[c];
    cell_weighted_[k] = sum[c];
    cell_weight_[k] = volumes_in_order_[c];
    for (std::size_t j = 0; j < per_cell; ++j) {
      const std::size_t q = c * per_cell + j;
      points_[k * per_cell + j] = samples.points[q];
      weighted_[k * per_cell + j] = samples.weights[q] * samples.stress[q];
      weights_[k * per_cell + j] = samples.weights[q];
    }
  }
  bin_weighted_.resize(n_total);
  bin_weight_.assign(n_total, 0);
  bin_extent_.assign(n_total, 0);
  for (std::size_t b = 0; b < n_total; ++b)
    for (std::size_t c = bin_start_[b]; c < bin_start_[b + 1]; ++c) {
      bin_weighted_[b] += cell_weighted_[c];
      bin_weight_[b] += cell_weight_[c];
      bin_extent_[b] = std::max(bin_extent_[b], cell_extent_[c]);
    }
  max_extent_ = n_total ? *std::max_element(bin_extent_.begin(), bin_extent_.end()) : 0;
}

SymmetricTensor<2, 3> BallAverage::mean_stress(const Point<3>& centre) const {
  // A cell whose centroid lies farther than R + extent has no sample in the ball.
  const double reach = radius_ + max_extent_;
  std::array<long, 3> from{}, to{};
  for (unsigned int d = 0; d < 3; ++d) {
    from[d] = std::max(0L, long(std::floor((centre[d] - reach - origin_[d]) / bin_)));
    to[d] = std::min(n_bins_[d] - 1, long(std::floor((centre[d] + reach - origin_[d]) / bin_)));
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
  const auto square = [](double x) { return x * x; };
  SymmetricTensor<2, 3> sum;
  double weight = 0;
  const double reach2 = reach * reach;
  for (long k = from[2]; k <= to[2]; ++k) {
    const auto z = near_far(2, k);
    for (long j = from[1]; j <= to[1]; ++j) {
      const auto y = near_far(1, j);
      if (y.first + z.first > reach2)
        continue;
      for (long i = from[0]; i <= to[0]; ++i) {
        const auto x = near_far(0, i);
        const std::size_t b = std::size_t((k * n_bins_[1] + j) * n_bins_[0] + i);
        const double e = bin_extent_[b];
        if (x.first + y.first + z.first > square(radius_ + e))
          continue;
        if (e <= radius_ && x.second + y.second + z.second <= square(radius_ - e)) {
          sum += bin_weighted_[b]; // every sample of every cell of the bin lies inside
          weight += bin_weight_[b];
          continue;
        }
        for (std::size_t c = bin_start_[b]; c < bin_start_[b + 1]; ++c) {
          const double d2 = (cell_centroid_[c] - centre).norm_square(), ec = cell_extent_[c];
          if (d2 > square(radius_ + ec))
            continue;
          if (ec <= radius_ && d2 <= square(radius_ - ec)) {
            sum += cell_weighted_[c];
            weight += cell_weight_[c];
            continue;
          }
          for (std::size_t q = c * per_cell_; q < (c + 1) * per_cell_; ++q)
            if ((points_[q] - centre).norm_square() <= r2) {
              sum += weighted_[q];
              weight += weights_[q];
            }
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

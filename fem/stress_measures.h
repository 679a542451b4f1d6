#pragma once
// Stress measures of a solve that converge under mesh refinement, beside the one that does
// not: the von Mises stress of the stress tensor averaged over a ball of a material radius,
// and volume-weighted percentiles of von Mises, both taken over the quadrature points of the
// solve (the largest quadrature-point value grows without bound under refinement near a
// contact load; docs/theory.md).
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <array>
#include <cstddef>
#include <vector>

namespace wear::fem {

/// The stress at the quadrature points of a solve: the samples every measure is taken over.
struct StressSamples {
  std::vector<dealii::Point<3>> points;              ///< [m]
  std::vector<dealii::SymmetricTensor<2, 3>> stress; ///< [Pa]
  std::vector<double> weights;                       ///< [m^3] quadrature JxW (volume share)
};

/// sqrt(3/2 s:s), s the deviator of `stress` [Pa].
double von_mises(const dealii::SymmetricTensor<2, 3>& stress);

/// Volume-weighted percentiles of `values`: for each fraction f in (0, 1], the smallest value
/// v such that the samples with values <= v hold at least f of the total weight. Throws when
/// the sizes differ, there is no sample or a fraction lies outside (0, 1].
std::vector<double> volume_percentiles(const std::vector<double>& values,
                                       const std::vector<double>& weights,
                                       const std::vector<double>& fractions);

/// The stress averaged over the sample inside a ball of fixed radius: the weighted mean of the
/// tensors of the samples within the radius of a centre (the tensor is averaged, then von
/// Mises taken). The samples come in cells of `per_cell` consecutive quadrature points; the
/// cells are binned by centroid on a uniform grid of a quarter of the radius with their sums
/// per bin, so a centre adds the sums of the bins whose cells lie wholly inside its ball, the
/// sums of the cells wholly inside, and tests the quadrature points only of the cells its
/// sphere cuts. The result is that of testing every sample, in another order of summation.
class BallAverage {
public:
  /// Keeps a copy of the samples sorted by bin. Throws when radius <= 0, the sizes differ or
  /// the count is not a multiple of per_cell.
  BallAverage(const StressSamples& samples, double radius, unsigned int per_cell = 1);

  double radius() const { return radius_; } ///< [m]
  /// Mean stress [Pa] within the radius of `centre` (zero tensor when no sample is there).
  dealii::SymmetricTensor<2, 3> mean_stress(const dealii::Point<3>& centre) const;
  /// von Mises [Pa] of the mean stress at each centre (OpenMP over centres; each centre's sum
  /// runs in a fixed order, so the result does not depend on the thread count).
  std::vector<double> von_mises_at(const std::vector<dealii::Point<3>>& centres) const;
  /// [m] the cells' volume-weighted centroids and [m^3] volumes, in the samples' order.
  const std::vector<dealii::Point<3>>& cell_centroids() const { return centroids_in_order_; }
  const std::vector<double>& cell_volumes() const { return volumes_in_order_; }

private:
  double radius_;
  unsigned int per_cell_;
  double bin_;                                  ///< [m] bin edge, radius / 4 (or more)
  dealii::Point<3> origin_;                     ///< [m] lower corner of the grid
  std::array<long, 3> n_bins_{};                ///< per direction
  std::vector<std::size_t> bin_start_;          ///< first cell of each bin (and the end)
  std::vector<double> bin_extent_;              ///< [m] largest cell extent in each bin
  double max_extent_ = 0;                       ///< [m] largest cell extent
  std::vector<dealii::Point<3>> cell_centroid_; ///< [m] sorted by bin
  std::vector<double> cell_extent_;             ///< [m] farthest sample from it
  std::vector<dealii::SymmetricTensor<2, 3>> cell_weighted_; ///< [Pa m^3] sum per cell
  std::vector<double> cell_weight_;                          ///< [m^3] sum per cell
  std::vector<dealii::Point<3>> points_;                ///< [m] samples, per_cell per sorted cell
  std::vector<dealii::SymmetricTensor<2, 3>> weighted_; ///< [Pa m^3] stress x weight
  std::vector<double> weights_;                         ///< [m^3]
  std::vector<dealii::SymmetricTensor<2, 3>> bin_weighted_; ///< [Pa m^3] sum per bin
  std::vector<double> bin_weight_;                          ///< [m^3] sum per bin
  std::vector<dealii::Point<3>> centroids_in_order_;        ///< [m]
  std::vector<double> volumes_in_order_;                    ///< [m^3]
};

} // namespace wear::fem

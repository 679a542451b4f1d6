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

/// The samples merged in consecutive groups of `per_cell` (a cell's quadrature points): each
/// group's weight sum, weighted centroid and weighted mean stress. Throws when the count is
/// not a multiple of per_cell.
StressSamples cell_means(const StressSamples& samples, unsigned int per_cell);

/// Volume-weighted percentiles of `values`: for each fraction f in (0, 1], the smallest value
/// v such that the samples with values <= v hold at least f of the total weight. Throws when
/// the sizes differ, there is no sample or a fraction lies outside (0, 1].
std::vector<double> volume_percentiles(const std::vector<double>& values,
                                       const std::vector<double>& weights,
                                       const std::vector<double>& fractions);

/// The stress averaged over the sample inside a ball of fixed radius: the weighted mean of the
/// tensors of the samples within the radius of a centre (the tensor is averaged, then von
/// Mises taken). Samples are binned on a uniform grid of a quarter of the radius with their
/// sums per bin, so a centre adds the sums of the bins wholly inside its ball and tests only
/// the samples of the bins its sphere cuts.
class BallAverage {
public:
  /// Keeps a copy of the samples sorted by bin. Throws when radius <= 0 or sizes differ.
  BallAverage(const StressSamples& samples, double radius);

  double radius() const { return radius_; } ///< [m]
  /// Mean stress [Pa] within the radius of `centre` (zero tensor when no sample is there).
  dealii::SymmetricTensor<2, 3> mean_stress(const dealii::Point<3>& centre) const;
  /// von Mises [Pa] of the mean stress at each centre (OpenMP over centres; each centre's sum
  /// runs in a fixed order, so the result does not depend on the thread count).
  std::vector<double> von_mises_at(const std::vector<dealii::Point<3>>& centres) const;

private:
  double radius_;
  double bin_;                                          ///< [m] bin edge, radius / 4 (or more)
  dealii::Point<3> origin_;                             ///< [m] lower corner of the grid
  std::array<long, 3> n_bins_{};                        ///< per direction
  std::vector<std::size_t> bin_start_;                  ///< first sample of each bin (and the end)
  std::vector<dealii::Point<3>> points_;                ///< [m] sorted by bin
  std::vector<dealii::SymmetricTensor<2, 3>> weighted_; ///< [Pa m^3] stress x weight
  std::vector<double> weights_;                         ///< [m^3]
  std::vector<dealii::SymmetricTensor<2, 3>> bin_weighted_; ///< [Pa m^3] sum per bin
  std::vector<double> bin_weight_;                          ///< [m^3] sum per bin
};

} // namespace wear::fem

#pragma once
// Continuum fields of a scene's particles on a grid of boxes: the solid
// fraction and the mass-weighted mean velocity per cell, averaged over the samples of a
// window (one sample per exchange interval of the run).
#include "dem/engine/particles.h"
#include "dem/engine/rank_link.h"

#include <array>
#include <cstdint>
#include <vector>

namespace wear::dem {

/// An axis-aligned box split into nx x ny x nz equal cells.
struct FieldGrid {
  Vec3 minimum, maximum;             ///< [m]
  std::array<int, 3> cells{1, 1, 1}; ///< nx, ny, nz
  std::size_t n_cells() const { return std::size_t(cells[0]) * cells[1] * cells[2]; }
  Vec3 spacing() const; ///< [m] the cells' edges
  /// The cell holding point x, index (k nz-major: (k * ny + j) * nx + i), or -1 outside.
  long cell_of(const Vec3& x) const;
};

/// A window's means per cell, in the cell order of FieldGrid::cell_of.
struct BinnedWindow {
  std::vector<double> solid_fraction; ///< [-] sum of the particle volumes / cell volume
  std::vector<Vec3> velocity;         ///< [m/s] mass-weighted; zero in a cell never occupied
  std::vector<double> occupancy;      ///< [-] mean particle count
  int n_samples = 0;
};

/// Each particle counts wholly in the cell of its centre: the fields are those of a coarse
/// grid, cells several particle diameters wide (a particle straddling a boundary is counted on
/// one side; the error of the solid fraction is of the order of d / cell edge).
class BinnedFields {
public:
  /// Throws std::invalid_argument naming "Scene/Fields" for an empty box or a count below 1.
  explicit BinnedFields(const FieldGrid& grid);
  const FieldGrid& grid() const { return grid_; }
  /// Adds the real particles' present state as one sample.
  void sample(const Particles& p);
  /// The means over the samples since the last reset (zeros without a sample). Over ranks
  /// (`link`, every rank calls it together) each rank samples its own particles and the sums
  /// are added over the ranks in rank order: every rank gets the whole scene's window.
  BinnedWindow window(RankLink* link = nullptr) const;
  void reset();

private:
  FieldGrid grid_;
  std::vector<double> volume_, mass_, count_; ///< per cell, summed over the samples
  std::vector<Vec3> momentum_;                ///< [kg m/s] per cell, summed
  int n_samples_ = 0;
};

} // namespace wear::dem

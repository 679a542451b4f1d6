#pragma once
// Verlet neighbour list built from a cell list: every pair (i, j) whose surfaces are closer
// than the skin, once: i real and j > i real, or j a ghost. Lists of each i are sorted by j,
// so the result does not depend on the thread count.
#include "dem/engine/particles.h"

#include <cstdint>
#include <vector>

namespace wear::dem {

class NeighborList {
public:
  std::vector<std::uint32_t> pair_i, pair_j;

  /// Rebuilds from the current positions (real and ghost slots). Reuses its buffers.
  void build(const Particles& p, double skin);
  std::size_t n_pairs() const { return pair_i.size(); }
  /// Removes, keeping the order, the pairs of two real slots of one group (group[slot] >= 0
  /// and equal; `group` covers the real slots, ghosts belong to none).
  void drop_pairs_within(const std::vector<std::int32_t>& group);

private:
  struct CellGrid;
  static CellGrid make_grid(const Particles& p, double skin);
  /// Bins the slots into the cells (counting sort: cell_start_, cell_items_, binned_).
  void bin(const Particles& p, const CellGrid& grid);
  /// Appends to `out` the partners of real particle i, sorted; returns their count. `scan`
  /// holds the stencil's candidates (grown as needed, never shrunk).
  std::size_t list_partners(const Particles& p, const CellGrid& grid, double skin, std::size_t i,
                            std::vector<std::uint32_t>& scan,
                            std::vector<std::uint32_t>& out) const;
  /// pair_i, pair_j from the threads' buffers, in thread order.
  void concatenate(int n_threads);

  std::vector<std::uint32_t> cell_of_, cell_start_, cell_items_, offset_;
  struct Binned {
    double x, y, z, r; ///< [m] position and radius of cell_items_[s]
  };
  std::vector<Binned> binned_;
  std::vector<std::vector<std::uint32_t>> chunk_i_, chunk_j_, chunk_scan_; // per thread, reused
};

} // namespace wear::dem

#pragma once
// A hash grid of particle centres for placing new particles without overlap (filling, inlets).
#include "dem/engine/particles.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace wear::dem {

/// Hash grid of particle centres with cubic cells: the particles that may overlap a new one
/// lie in its own cell or the 26 around it when the cell is the largest diameter.
class InsertionGrid {
public:
  /// An empty grid of cells of size `cell` [m]: at least the largest diameter.
  explicit InsertionGrid(double cell) : cell_(cell) {}
  /// The grid of every real particle of p.
  InsertionGrid(const Particles& p, double cell) : cell_(cell) {
    for (std::uint32_t i = 0; i < p.n_real; ++i)
      add(p.position[i], i);
  }
  /// Lists particle i of the Particles later passed to overlaps(), centred at x.
  void add(const Vec3& x, std::uint32_t i) { cells_[key(x)].push_back(i); }
  /// True when a sphere of radius r at x overlaps a particle of p listed in the grid.
  bool overlaps(const Particles& p, const Vec3& x, double r) const {
    const Key c = key(x);
    for (long a = -1; a <= 1; ++a)
      for (long b = -1; b <= 1; ++b)
        for (long e = -1; e <= 1; ++e) {
          auto it = cells_.find({c.i + a, c.j + b, c.k + e});
          if (it == cells_.end())
            continue;
          for (auto j : it->second) {
            const double s = r + p.radius[j];
            if (meshes::norm2(p.position[j] - x) < s * s)
              return true;
          }
        }
    return false;
  }

private:
  struct Key {
    long i, j, k;
    bool operator==(const Key& o) const { return i == o.i && j == o.j && k == o.k; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k.i) * 73856093u ^ std::size_t(k.j) * 19349663u ^
             std::size_t(k.k) * 83492791u;
    }
  };
  Key key(const Vec3& x) const {
    return Key{long(std::floor(x.x / cell_)), long(std::floor(x.y / cell_)),
               long(std::floor(x.z / cell_))};
  }
  double cell_;
  std::unordered_map<Key, std::vector<std::uint32_t>, Hash> cells_;
};

} // namespace wear::dem

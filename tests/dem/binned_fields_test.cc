// Binned continuum fields (dem/scene/binned_fields.h): centre binning conserves the particle
// volume, a rigid motion's binned velocity is the motion at the cell's mass centre, samples
// average, and a bad grid is refused naming Scene/Fields.
#include "dem/scene/binned_fields.h"
#include "meshes/constants.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace wear::dem;
using wear::pi;

namespace {

/// n particles at random in [0, 0.1]^3, radii 1 to 3 mm, density 2650 kg/m^3.
Particles random_particles(std::size_t n, unsigned seed) {
  Particles p;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 0.1), r(1e-3, 3e-3);
  for (std::size_t i = 0; i < n; ++i)
    p.add({u(rng), u(rng), u(rng)}, {}, r(rng), 2650, 0);
  return p;
}

double volume(const Particles& p) {
  double v = 0;
  for (std::size_t i = 0; i < p.n_real; ++i)
    v += 4.0 / 3.0 * pi * std::pow(p.radius[i], 3);
  return v;
}

} // namespace

TEST_CASE("binned fields: the particle volume is conserved and a rigid rotation is exact") {
  Particles p = random_particles(2000, 5);
  const Vec3 omega{0.3, -1.2, 2.0}, centre{0.05, 0.05, 0.05};
  for (std::size_t i = 0; i < p.n_real; ++i)
    p.velocity[i] = wear::meshes::cross(omega, p.position[i] - centre);
  const FieldGrid grid{{0, 0, 0}, {0.1, 0.1, 0.1}, {4, 5, 3}};
  BinnedFields fields(grid);
  fields.sample(p);
  const auto w = fields.window();
  REQUIRE(w.n_samples == 1);
  const Vec3 h = grid.spacing();
  double binned = 0, count = 0;
  for (std::size_t c = 0; c < grid.n_cells(); ++c) {
    binned += w.solid_fraction[c] * h.x * h.y * h.z;
    count += w.occupancy[c];
  }
  CHECK(binned == Approx(volume(p)).epsilon(1e-12));
  CHECK(count == 2000);
  // Mass-weighted, a velocity linear in position averages to its value at the cell's mass
  // centre.
  std::vector<Vec3> moment(grid.n_cells());
  std::vector<double> mass(grid.n_cells(), 0);
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const auto c = std::size_t(grid.cell_of(p.position[i]));
    moment[c] += p.mass[i] * p.position[i];
    mass[c] += p.mass[i];
  }
  for (std::size_t c = 0; c < grid.n_cells(); ++c) {
    REQUIRE(mass[c] > 0);
    const Vec3 expected = wear::meshes::cross(omega, moment[c] / mass[c] - centre);
    CHECK(wear::meshes::norm(w.velocity[c] - expected) < 1e-12);
  }
}

TEST_CASE("binned fields: samples average, outside particles are ignored, bad grids refused") {
  Particles p = random_particles(500, 9);
  const FieldGrid grid{{0, 0, 0}, {0.05, 0.1, 0.1}, {2, 2, 2}}; // holds about half of them
  BinnedFields fields(grid);
  fields.sample(p);
  const auto one = fields.window();
  fields.sample(Particles{}); // a sample with nothing in the grid halves the means
  const auto two = fields.window();
  double inside = 0;
  for (std::size_t i = 0; i < p.n_real; ++i)
    if (p.position[i].x < 0.05)
      inside += 4.0 / 3.0 * pi * std::pow(p.radius[i], 3);
  const Vec3 h = grid.spacing();
  double binned = 0;
  for (std::size_t c = 0; c < grid.n_cells(); ++c) {
    binned += one.solid_fraction[c] * h.x * h.y * h.z;
    CHECK(two.solid_fraction[c] == Approx(0.5 * one.solid_fraction[c]).epsilon(1e-15));
    CHECK(two.occupancy[c] == Approx(0.5 * one.occupancy[c]).epsilon(1e-15));
  }
  CHECK(binned == Approx(inside).epsilon(1e-12));
  fields.reset();
  CHECK(fields.window().n_samples == 0);
  CHECK(grid.cell_of({0.05, 0.05, 0.05}) == -1); // the upper faces belong outside
  CHECK(grid.cell_of({-1e-12, 0.05, 0.05}) == -1);
  CHECK_THROWS_WITH(BinnedFields(FieldGrid{{0, 0, 0}, {0.1, 0.1, 0.1}, {2, 0, 2}}),
                    Catch::Contains("Scene/Fields/Cells"));
  CHECK_THROWS_WITH(BinnedFields(FieldGrid{{0, 0, 0}, {0.1, -0.1, 0.1}, {2, 2, 2}}),
                    Catch::Contains("Scene/Fields: Minimum must lie below Maximum"));
}

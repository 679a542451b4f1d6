// The wear tester over the ranks of the test (1, 2 or 3: angular slabs of 30, 15 or 10 degrees
// of a 30-degree periodic sector at s = 4, with the sample and its holder across the cuts)
// against the same tester in one process, which every rank also runs: the same bed inserted
// (ids, positions bitwise), settled for 0.06 s, then 400 steps of the turning walls. The
// ranked run's particles, gathered by id, follow the one-process run's and its window
// integrals on the sample, summed over the ranks in rank order, match the one-process
// integrals; the evaluation's gather sees the same particles over the sample.
//
// Tolerances: the two runs add the same contact forces in different orders (a ghost's forces
// come back from the rank above after the rank's own), so they part by round-off, which the
// collisions of a falling, landing bed amplify. Measured after 2,800 steps (2,057 particles):
// 4.8e-13 m and 3.4e-10 m/s at 2 ranks, 4.6e-12 m and 2.1e-9 m/s at 3; held to 1e-8 m (a
// millionth of a radius) and 1e-6 m/s. The window integrals to 1e-6 of their total. One rank
// is the same engine as one process: bitwise equal (0 m, 0 m/s).
#include "dem/tester/wear_tester.h"
#include "meshes/sample_generator.h"
#include "tests/dem_mpi/dem_mpi_fixtures.h"

using namespace wear;
using namespace wear::dem;
using namespace wear::dem::testing;

namespace {

MpiRankLink& ring() {
  static MpiRankLink link(MPI_COMM_WORLD, true);
  return link;
}

struct SmallTester {
  meshes::GeometryParameters geometry;
  TesterDemParameters dem;
  meshes::SurfaceMesh sample;
  SmallTester() {
    geometry.sample.mesh_size = 3e-3;
    geometry.sample.curvature_refinement = false;
    geometry.sample.volume_mesh = false;
    geometry.placement.angle_deg = 15;
    geometry.tester.sector_angle_deg = 30;
    geometry.tester.consolidator = false;
    geometry.tester.wall_height = 0.2;
    dem.fill_height = 0.055;
    dem.settle_time = 0.05; // the settling stops at its first check past it, t = 0.06 s
    dem.time_step_fraction = 0.35;
    dem.samples_per_revolution = 5;
    dem.n_threads = 1;
    sample = meshes::generate_sample(geometry.sample).surface;
  }
};

/// Fills, settles and turns the walls for `n_steps` steps (a multiple of the stop check).
void run(WearTester& t, std::uint64_t n_steps) {
  t.fill_and_settle();
  std::uint64_t asked = 0;
  const bool done =
      t.advance_revolution({}, [&] { return asked++ * WearTester::stop_check_steps >= n_steps; });
  REQUIRE(!done);
}

} // namespace

TEST_CASE("the tester over ranks follows the tester in one process", "[dem_mpi][tester]") {
  const SmallTester c;
  WearTester plain(c.geometry, c.dem, WearLawParameters{}, ReferenceDeformationParameters{},
                   c.sample);
  WearTester ranked(c.geometry, c.dem, WearLawParameters{}, ReferenceDeformationParameters{},
                    c.sample);
  ranked.set_rank_link(world().n_ranks() > 1 ? &ring() : nullptr);
  run(plain, 400);
  run(ranked, 400);
  const std::size_t n = plain.system().particles.n_real;
  CHECK(ranked.n_particles() == n);
  CHECK(ranked.system().time() == plain.system().time());
  const BedState a = gather(ranked.system(), n, world()), b = by_id(plain.system(), n);
  for (std::size_t id = 0; id < n; ++id)
    REQUIRE(a.held[id] == 1);
  const double dx = max_difference(a.x, b.x), dv = max_difference(a.v, b.v);
  INFO(n << " particles on " << world().n_ranks() << " ranks: largest departure " << dx << " m, "
         << dv << " m/s (speeds up to " << max_norm(b.v) << " m/s)");
  CHECK(dx <= 1e-8);
  CHECK(dv <= 1e-6);
  // The sample's window integrals, summed over the ranks.
  const WearIntegrals w = ranked.system().wear_integrals_over_ranks(ranked.sample_wall());
  const WearIntegrals w1 = plain.system().wear_integrals(plain.sample_wall());
  REQUIRE(w1.total_normal_impulse > 0); // the bed presses on the sample
  CHECK(std::abs(w.total_normal_impulse - w1.total_normal_impulse) <=
        1e-6 * w1.total_normal_impulse);
  CHECK(std::abs(w.total_archard - w1.total_archard) <= 1e-6 * w1.total_archard);
  double diff = 0, total = 0;
  for (std::size_t f = 0; f < w.normal_impulse.size(); ++f) {
    diff += std::abs(w.normal_impulse[f] - w1.normal_impulse[f]);
    total += w1.normal_impulse[f];
  }
  CHECK(diff <= 1e-6 * total);
  // The whole bed gathered for a snapshot: every id once.
  const Particles& bed = ranked.bed_particles();
  REQUIRE(bed.n_real == n);
  std::vector<int> seen(n, 0);
  for (std::size_t i = 0; i < bed.n_real; ++i)
    seen[std::size_t(bed.id[i])] += 1;
  CHECK(std::count(seen.begin(), seen.end(), 1) == std::ptrdiff_t(n));
}

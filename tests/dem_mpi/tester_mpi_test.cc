// The wear tester as a scene (dem::tester_scene) over the ranks of the test (1, 2 or 3:
// angular slabs of a 30-degree periodic sector at s = 4, with the sample and its holder across
// the cuts) against the same scene in one process, which every rank also runs: the same bed
// inserted (ids, positions bitwise), settled for 0.06 s, then 400 steps of the turning walls. The
// ranked run's particles, gathered by id, follow the one-process run's and its window
// integrals on the sample, summed over the ranks in rank order, match the one-process
// integrals; the gather of the bed to the first rank sees every particle once.
//
// Tolerances: the two runs add the same contact forces in different orders (a ghost's forces
// come back from the rank above after the rank's own), so they part by round-off, which the
// collisions of a falling, landing bed amplify. Measured after 2,800 steps (2,057 particles):
// 4.8e-13 m and 3.4e-10 m/s at 2 ranks, 4.6e-12 m and 2.1e-9 m/s at 3; held to 1e-8 m (a
// millionth of a radius) and 1e-6 m/s. The window integrals to 1e-6 of their total. One rank
// is the same engine as one process: bitwise equal (0 m, 0 m/s).
#include "dem/scene/scene_run.h"
#include "dem/scene/scene_walls.h"
#include "dem/tester/tester_scene.h"
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
  SceneParameters scene;
  std::size_t sample_wall = 0;
  SmallTester() {
    geometry.sample.mesh_size = 3e-3;
    geometry.sample.curvature_refinement = false;
    geometry.placement.angle_deg = 15;
    geometry.tester.sector_angle_deg = 30;
    geometry.tester.consolidator = false;
    geometry.tester.wall_height = 0.2;
    dem.fill_height = 0.055;
    dem.settle_time = 0.05; // the settling stops at its first check past it, t = 0.06 s
    dem.time_step_fraction = 0.35;
    dem.samples_per_revolution = 5;
    dem.n_threads = 1;
    scene = tester_scene(geometry, dem, 1);
    sample_wall = scene_wall_index(scene, "sample").value();
  }
  std::unique_ptr<SceneRun> start(RankLink* link) const {
    auto run = std::make_unique<SceneRun>(scene, dem, build_scene_walls(scene, geometry));
    run->set_rank_link(link);
    return run;
  }
};

/// Fills, settles and turns the walls for `n_steps` steps; the window's record.
SceneWindow run(SceneRun& s, std::uint64_t n_steps) {
  s.setup();
  return s.advance(s.time() + double(n_steps) * s.system().time_step());
}

} // namespace

TEST_CASE("the tester over ranks follows the tester in one process", "[dem_mpi][tester]") {
  const SmallTester c;
  const auto plain = c.start(nullptr);
  const auto ranked = c.start(world().n_ranks() > 1 ? &ring() : nullptr);
  const SceneWindow w1 = run(*plain, 400);
  const SceneWindow w = run(*ranked, 400);
  const std::size_t n = plain->system().particles.n_real;
  CHECK(w.n_particles == n);
  CHECK(ranked->system().time() == plain->system().time());
  const BedState a = gather(ranked->system(), n, world()), b = by_id(plain->system(), n);
  for (std::size_t id = 0; id < n; ++id)
    REQUIRE(a.held[id] == 1);
  const double dx = max_difference(a.x, b.x), dv = max_difference(a.v, b.v);
  INFO(n << " particles on " << world().n_ranks() << " ranks: largest departure " << dx << " m, "
         << dv << " m/s (speeds up to " << max_norm(b.v) << " m/s)");
  CHECK(dx <= 1e-8);
  CHECK(dv <= 1e-6);
  // The sample's window integrals, summed over the ranks.
  const WearIntegrals& ws = w.wearing.at(c.sample_wall);
  const WearIntegrals& ws1 = w1.wearing.at(c.sample_wall);
  REQUIRE(ws1.total_normal_impulse > 0); // the bed presses on the sample
  CHECK(std::abs(ws.total_normal_impulse - ws1.total_normal_impulse) <=
        1e-6 * ws1.total_normal_impulse);
  CHECK(std::abs(ws.total_archard - ws1.total_archard) <= 1e-6 * ws1.total_archard);
  double diff = 0, total = 0;
  for (std::size_t f = 0; f < ws.normal_impulse.size(); ++f) {
    diff += std::abs(ws.normal_impulse[f] - ws1.normal_impulse[f]);
    total += ws1.normal_impulse[f];
  }
  CHECK(diff <= 1e-6 * total);
  // The whole bed gathered for a snapshot on the first rank: every id once.
  const Particles bed = ranked->particles_on_first_rank();
  if (world().rank() == 0) {
    REQUIRE(bed.n_real == n);
    std::vector<int> seen(n, 0);
    for (std::size_t i = 0; i < bed.n_real; ++i)
      seen[std::size_t(bed.id[i])] += 1;
    CHECK(std::count(seen.begin(), seen.end(), 1) == std::ptrdiff_t(n));
  } else
    CHECK(bed.n_real == 0);
}

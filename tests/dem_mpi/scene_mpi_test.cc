// A scene over the ranks of MPI_COMM_WORLD (dem::SceneRun::set_rank_link), run at 1, 2 and 3
// ranks by ctest: a 120 mm bin filled with 300 spheres and fed from above by an inlet, draining
// through its orifice into an outlet, a flux plane under the orifice, a grid of binned fields,
// cut into balanced slabs along x (the cuts through the orifice, where most particles pass
// between ranks).
// - Every window, on every rank: filled + inserted = in the scene + removed, exactly in count;
//   the flux plane has seen every particle the outlet took (and at most those below it), none
//   backwards; the fields' occupancy holds the particles in the grid.
// - The balanced cuts give every rank the same share of the fill within 10 %.
// - The same run twice on as many ranks: every figure and every particle bit for bit.
// - A state taken between two windows and resumed on as many ranks continues bit for bit; the
//   bed merged into one process's and taken back (as a resume on another rank count) keeps
//   every particle and the count balance.
// - Uniform slabs over the bin's domain leave the middle one of 3 ranks with most of the fill;
//   rebalanced() cuts the same bed anew, each rank within 10 % of the mean, keeps every
//   particle and the balance, and does it alike twice (bit for bit).
// - A bed on an endless belt periodic along x (scene_fixtures.h), its ranks a ring through
//   the seam: no particle lost in 1 s, and the flux plane at x = 0 counts more than half the
//   bed's mass forwards (as on one process, scene_run_test.cc).
#include "dem/engine/rank_states.h"
#include "dem/scene/scene_run.h"
#include "dem/scene/scene_walls.h"
#include "meshes/constants.h"
#include "tests/dem/scene_fixtures.h"
#include "tests/dem_mpi/dem_mpi_fixtures.h"

#include <catch2/catch.hpp>

#include <cstring>

using namespace wear::dem;
using namespace wear::dem::testing;

namespace {

constexpr int n_fill = 300;

SceneParameters fed_bin() {
  SceneParameters s = flat_bottomed_bin("bin, floor", 0.06, 0.3, 0.02, 0.05);
  s.fill.region = "cylinder";
  s.fill.origin = {0, 0, 0.001};
  s.fill.axis = {0, 0, 0.1};
  s.fill.radius = 0.058;
  s.fill.count = n_fill;
  s.inlet_names = "feed";
  s.inlets.push_back({});
  auto& feed = s.inlets.back();
  feed.name = "feed";
  feed.corner = {-0.03, -0.03, 0.26};
  feed.edge_u = {0.06, 0, 0};
  feed.edge_v = {0, 0.06, 0};
  feed.mass_flow = 0.4;
  feed.velocity = {0, 0, -1};
  s.flux_plane_names = "orifice";
  s.flux_planes.push_back({"orifice", {0, 0, -0.02}, {0, 0, -1}});
  s.fields.cells = {4, 4, 6};
  s.fields.minimum = {-0.06, -0.06, 0};
  s.fields.maximum = {0.06, 0.06, 0.3};
  s.output_interval = 0.05;
  s.end_time = 0.3;
  return s;
}

/// The scene over the world's ranks, set up.
std::unique_ptr<SceneRun> start(const SceneParameters& s) {
  auto run = std::make_unique<SceneRun>(s, gravel(), build_scene_walls(s));
  run->set_rank_link(&world());
  return run;
}

/// The flat numbers of a window, for bitwise comparisons.
std::vector<double> numbers(const SceneWindow& w) {
  std::vector<double> v{
      w.t_end,         double(w.n_particles), double(w.n_inserted), double(w.n_removed),
      w.inserted_mass, w.mean_speed,          w.max_speed};
  v.insert(v.end(), w.outlet_mass.begin(), w.outlet_mass.end());
  v.insert(v.end(), w.flux_mass.begin(), w.flux_mass.end());
  for (const auto& l : w.walls)
    v.insert(v.end(), {l.force.x, l.force.y, l.force.z, l.archard});
  v.insert(v.end(), w.fields.solid_fraction.begin(), w.fields.solid_fraction.end());
  return v;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

/// The particles over the ranks by id: position and velocity bits.
std::vector<double> bed(const SceneRun& run) {
  const BedState b = gather(run.system(), std::size_t(run.system().next_id()), world());
  std::vector<double> v;
  for (std::size_t id = 0; id < b.x.size(); ++id)
    v.insert(v.end(),
             {b.held[id], b.x[id].x, b.x[id].y, b.x[id].z, b.v[id].x, b.v[id].y, b.v[id].z});
  return v;
}

/// Checks that hold after every window: counts, the flux plane against the outlet, fields.
void check_balance(const SceneRun& run, const SceneWindow& w) {
  INFO("t = " << w.t_end << " s on " << world().n_ranks() << " rank(s)");
  CHECK(w.n_particles + w.n_removed == n_fill + w.n_inserted);
  const double m = 2650 * wear::pi / 6 * 0.006 * 0.006 * 0.006;
  CHECK(w.outlet_mass[0] == Approx(double(w.n_removed) * m).epsilon(1e-12));
  double below = 0;
  const auto& p = run.system().particles;
  for (std::size_t i = 0; i < p.n_real; ++i)
    below += p.position[i].z < -0.02 ? 1 : 0;
  below = over_ranks({below}, world())[0];
  CHECK(w.flux_mass[0] >= w.outlet_mass[0] - 1e-12);
  CHECK(w.flux_mass[0] <= w.outlet_mass[0] + below * m + 1e-12);
  CHECK(run.flux_planes()[0].n_backward() == 0);
  // The grid's mean occupancy is at most the particles present, and holds some.
  double occupancy = 0;
  for (const double o : w.fields.occupancy)
    occupancy += o;
  CHECK(occupancy > 0);
  CHECK(occupancy <= double(n_fill + w.n_inserted));
}

} // namespace

TEST_CASE("scene over ranks: counts balance, balanced slabs, the same bits twice") {
  const SceneParameters s = fed_bin();
  auto a = start(s);
  a->setup();
  // Balanced cuts: each rank's share of the fill within 10 % of the mean.
  const double mine = double(a->system().particles.n_real);
  double spread[2] = {mine, -mine};
  world().max_over_ranks(spread, 2);
  const double mean = double(n_fill) / world().n_ranks();
  INFO(a->rank_layout());
  CHECK(spread[0] <= 1.1 * mean);
  CHECK(-spread[1] >= 0.9 * mean);

  std::vector<std::vector<double>> first;
  SceneWindow w;
  while (a->time() < s.end_time - 1e-9) {
    w = a->advance(std::min(s.end_time, a->time() + s.output_interval));
    check_balance(*a, w);
    first.push_back(numbers(w));
  }
  CHECK(w.n_removed > 20);  // it drains
  CHECK(w.n_inserted > 50); // and is fed
  const std::vector<double> first_bed = bed(*a);

  auto b = start(s);
  b->setup();
  for (std::size_t k = 0; b->time() < s.end_time - 1e-9; ++k) {
    const SceneWindow again = b->advance(std::min(s.end_time, b->time() + s.output_interval));
    CHECK(same_bits(numbers(again), first.at(k)));
  }
  CHECK(same_bits(bed(*b), first_bed));
}

TEST_CASE("scene over ranks: a state resumed on as many ranks, and as a merged bed") {
  const SceneParameters s = fed_bin();
  auto a = start(s);
  a->setup();
  a->advance(0.1);
  const SceneRunState state = a->state();
  CHECK(state.rank_bounds.size() == (world().n_ranks() > 1 ? world().n_ranks() + 1 : 0));

  // The same ranks: bit for bit.
  auto b = start(s);
  b->resume(state);
  const SceneWindow wa = a->advance(0.2), wb = b->advance(0.2);
  CHECK(same_bits(numbers(wa), numbers(wb)));
  CHECK(same_bits(bed(*a), bed(*b)));

  // The bed merged into one process's (what a checkpoint read on another rank count gives),
  // sent to every rank: every particle kept, the balance holds on.
  SceneRunState whole = state;
  whole.system = whole_state_on_every_rank(state.system, world());
  auto c = start(s);
  c->resume(whole);
  const double n_state = over_ranks({double(state.system.position.size())}, world())[0];
  CHECK(double(c->system().n_particles_over_ranks()) == n_state);
  const SceneWindow wc = c->advance(0.2);
  check_balance(*c, wc);
  CHECK(wc.n_inserted == wa.n_inserted); // the inlet's generator went on alike
}

TEST_CASE("scene over ranks: a bed on an endless belt goes round a ring of ranks") {
  const SceneParameters s = endless_belt();
  SceneRun run(s, gravel(), build_scene_walls(s));
  MpiRankLink ring(MPI_COMM_WORLD, true);
  run.set_rank_link(&ring);
  run.setup();
  const SceneWindow w = run.advance(1.0);
  CHECK(w.n_particles == 300);
  const double m = 2650 * wear::pi / 6 * 0.006 * 0.006 * 0.006;
  CHECK(w.flux_mass[0] > 0.5 * 300 * m);
  CHECK(run.flux_planes()[0].n_forward() >= run.flux_planes()[0].n_backward());
}

TEST_CASE("scene over ranks: a bed off its cuts is rebalanced, the same way twice") {
  if (world().n_ranks() < 2)
    return; // one process has nothing to balance
  SceneParameters s = fed_bin();
  s.rank_slabs = "uniform";
  std::vector<double> first;
  for (int repeat = 0; repeat < 2; ++repeat) {
    auto a = start(s);
    a->setup();
    a->advance(0.05);
    const double before = a->rank_imbalance();
    if (world().n_ranks() == 3)
      CHECK(before > 1.25); // the middle slab holds most of the bin
    const auto b = a->rebalanced();
    INFO(a->rank_layout() << " -> " << b->rank_layout());
    CHECK(b->rank_imbalance() < 1.1);
    CHECK(b->time() == a->time());
    const SceneWindow w = b->advance(0.15);
    check_balance(*b, w);
    const std::vector<double> now = bed(*b);
    if (repeat == 0)
      first = now;
    else
      CHECK(same_bits(now, first));
  }
}

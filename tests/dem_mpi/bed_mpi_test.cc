// Beds decomposed over the ranks of the test (1, 2 or 3; slabs along x) against the same bed
// in one plain System that every rank runs: a pile resting across the cuts on a wearing floor
// (its positions, its per-face wear integrals summed in rank order, a repeated run bitwise),
// a sphere sliding across a cut on the floor (wall history migrating), a stack of two spheres
// sliding across a cut together (both leaving the rank in the same rebuild with the pair's
// history), a dense collisional gas in a box (momentum and energy), and slabs too narrow.
#include "tests/dem_mpi/dem_mpi_fixtures.h"

#include <cstdint>

using namespace wear::dem;
using namespace wear::dem::testing;
namespace meshes = wear::meshes;

namespace {

constexpr double r = bed_radius; ///< [m]

/// Slabs along x with cuts through the beds below (widths at least 19 mm, above the reach).
SlabDecomposition slabs_across_x() {
  return x_slabs({{-1, 1}, {-1, 0.002, 1}, {-1, -0.006, 0.013, 1}});
}

/// Runs `n_steps` steps of the bed `make` builds, over the ranks or in one System, and
/// returns the state by id (gathered over the ranks) every `every` steps.
template <class Make>
std::vector<BedState> run(bool ranked, Make make, std::size_t n_ids, int n_steps, int every,
                          System* keep = nullptr, int n_threads = 1,
                          const SlabDecomposition& slabs = slabs_across_x(),
                          RankLink& link = world()) {
  System local;
  System& s = keep ? *keep : local;
  make(s);
  if (ranked)
    s.set_rank_link(&link, &slabs);
  s.setup();
  s.set_n_threads(n_threads);
  std::vector<BedState> states;
  for (int k = 0; k < n_steps; k += every) {
    s.run(std::uint64_t(every));
    states.push_back(ranked ? gather(s, n_ids, world()) : by_id(s, n_ids));
  }
  return states;
}

/// The ranks of the world as a ring, for a periodic bed (the seam joins the last and rank 0).
MpiRankLink& ring() {
  static MpiRankLink link(MPI_COMM_WORLD, true);
  return link;
}

/// The gas over the ranks against one System after 1000 steps: momentum to 1e-12 of sum m |v|,
/// kinetic, rotational and elastic energy to 1e-9 of the total.
void check_gas(bool periodic) {
  const std::size_t n = 343;
  const auto make = [periodic](System& s) { gas(s, periodic); };
  System ranked_system, plain_system;
  // Two threads per rank: ghosts of the rank below meet the threads' split (ForeignForces).
  const SlabDecomposition thirds = periodic
                                       ? x_slabs({{0, 0.1}, {0, 0.05, 0.1}, {0, 0.035, 0.065, 0.1}})
                                       : x_slabs({{-1, 1}, {-1, 0.05, 1}, {-1, 0.035, 0.065, 1}});
  run(true, make, n, 1000, 1000, &ranked_system, 2, thirds, periodic ? ring() : world());
  run(false, make, n, 1000, 1000, &plain_system);
  const auto a = over_ranks(momentum_and_energy(ranked_system), world());
  const auto b = momentum_and_energy(plain_system);
  double mv = 0; // [kg m/s] sum of m |v|, the momentum's scale
  for (std::size_t i = 0; i < plain_system.particles.n_real; ++i)
    mv += plain_system.particles.mass[i] * meshes::norm(plain_system.particles.velocity[i]);
  INFO("momentum " << a[0] << " " << a[1] << " " << a[2] << " (one rank " << b[0] << " " << b[1]
                   << " " << b[2] << ", scale " << mv << "); kinetic " << a[3] << " (" << b[3]
                   << "), rotational " << a[4] << " (" << b[4] << "), elastic " << a[5] << " ("
                   << b[5] << ")");
  for (int k = 0; k < 3; ++k)
    CHECK(std::abs(a[k] - b[k]) <= 1e-12 * mv);
  const double total = b[3] + b[4] + b[5];
  CHECK(std::abs(a[3] - b[3]) <= 1e-9 * total);
  CHECK(std::abs(a[4] - b[4]) <= 1e-9 * total);
  CHECK(std::abs(a[5] - b[5]) <= 1e-9 * total);
  CHECK(plain_system.n_pair_contacts() > 0);
}

} // namespace

TEST_CASE("a pile across the cuts stays put as on one rank; its wear sums in rank order",
          "[dem_mpi][pile]") {
  const std::size_t n = 23;
  System ranked_system, plain_system;
  const auto make = [](System& s) { pile(s, true); };
  const auto ranked = run(true, make, n, 2000, 500, &ranked_system);
  const auto plain = run(false, make, n, 2000, 500, &plain_system);
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    INFO("after " << 500 * (k + 1) << " steps");
    for (std::size_t id = 0; id < n; ++id)
      CHECK(ranked[k].held[id] == 1);
    CHECK(max_difference(ranked[k].x, plain[k].x) <= 1e-12);
    CHECK(max_difference(ranked[k].v, plain[k].v) <= 1e-10);
  }
  // Stays put: the upper layer sank into the hollows by the overlaps only.
  CHECK(max_difference(ranked.back().x, ranked.front().x) < 1e-4);
  const WearIntegrals w = ranked_system.wear_integrals_over_ranks(0);
  const WearIntegrals w1 = plain_system.wear_integrals(0);
  double scale = 0, diff = 0;
  for (std::size_t f = 0; f < w.normal_impulse.size(); ++f) {
    scale = std::max(scale, w1.normal_impulse[f]);
    diff = std::max(diff, std::abs(w.normal_impulse[f] - w1.normal_impulse[f]));
  }
  CHECK(scale > 0);
  CHECK(diff <= 1e-12 * scale);
  CHECK(w.total_normal_impulse == Approx(w1.total_normal_impulse).epsilon(1e-12));
  CHECK(meshes::norm(w.total_impulse - w1.total_impulse) <= 1e-12 * meshes::norm(w1.total_impulse));
  // The same run again over the same ranks: the same bits.
  System again;
  const auto repeated = run(true, make, n, 2000, 500, &again);
  const WearIntegrals w2 = again.wear_integrals_over_ranks(0);
  CHECK(w2.normal_impulse == w.normal_impulse);
  CHECK(w2.archard == w.archard);
  CHECK(w2.total_impulse_moment.x == w.total_impulse_moment.x);
  for (std::size_t id = 0; id < n; ++id)
    CHECK(repeated.back().x[id].x == ranked.back().x[id].x);
}

TEST_CASE("a sphere sliding across a cut follows its one-rank trajectory",
          "[dem_mpi][trajectory]") {
  // Sliding at 0.5 m/s with a spin against it: the floor's friction turns it to rolling
  // while it crosses the cuts (x = 0.002; -0.006 and 0.013 on three ranks) with the
  // wall-contact slot that migrates with it.
  const auto make = [](System& s) {
    const int g = gravel_on_floor(s, false);
    s.particles.add({-0.009, 0, r - 1e-6}, {0.5, 0, 0}, r, 2650, g);
    s.particles.angular_velocity[0] = {0, -30, 0};
  };
  const auto ranked = run(true, make, 1, 2500, 100);
  const auto plain = run(false, make, 1, 2500, 100);
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    INFO("after " << 100 * (k + 1) << " steps: x = " << plain[k].x[0].x);
    CHECK(meshes::norm(ranked[k].x[0] - plain[k].x[0]) <= 1e-12 * meshes::norm(plain[k].x[0]));
    CHECK(meshes::norm(ranked[k].v[0] - plain[k].v[0]) <= 1e-12 * 0.5);
    CHECK(meshes::norm(ranked[k].w[0] - plain[k].w[0]) <= 1e-12 * 80);
  }
  CHECK(plain.back().x[0].x > 0.02); // it crossed every cut
}

TEST_CASE("two touching spheres leave a rank together with their history", "[dem_mpi][history]") {
  // Sphere 1 rests on sphere 0, which slides on a slippery floor (mu = 0.1) at 0.3 m/s: the
  // floor turns sphere 0, so the pair (mu = 0.5) slips and holds a tangential history. Both
  // start in the middle slab on three ranks (rank 0 on two) and cross x = 0.013 (0.002) in
  // the same rebuild.
  const double x0 = world().n_ranks() == 3 ? 0.0102 : -0.0008;
  const auto make = [x0](System& s) {
    const int g = gravel_on_slippery_floor(s);
    s.particles.add({x0, 0, r - 1e-6}, {0.3, 0, 0}, r, 2650, g);
    s.particles.add({x0, 0, 3 * r - 3e-6}, {0.3, 0, 0}, r, 2650, g);
  };
  const auto ranked = run(true, make, 2, 1200, 1);
  const auto plain = run(false, make, 2, 1200, 1);
  int n_together = 0;
  for (std::size_t k = 1; k < ranked.size(); ++k) {
    const bool moved0 = ranked[k].rank[0] != ranked[k - 1].rank[0];
    const bool moved1 = ranked[k].rank[1] != ranked[k - 1].rank[1];
    CHECK(moved0 == moved1);
    n_together += moved0 && moved1;
  }
  if (world().n_ranks() > 1)
    CHECK(n_together == 1);
  double worst = 0;
  for (std::size_t k = 0; k < ranked.size(); ++k)
    for (int id = 0; id < 2; ++id)
      worst = std::max({worst, meshes::norm(ranked[k].x[id] - plain[k].x[id]) / 0.01,
                        meshes::norm(ranked[k].v[id] - plain[k].v[id]) / 0.3,
                        meshes::norm(ranked[k].w[id] - plain[k].w[id]) / 60});
  INFO("largest relative departure from the one-rank run: " << worst);
  CHECK(worst <= 1e-12);
  // The pair slipped: sphere 1 turns the other way to sphere 0.
  CHECK(plain.back().w[0].y * plain.back().w[1].y < 0);
}

TEST_CASE("a dense collisional gas keeps the one-rank momentum and energy", "[dem_mpi][gas]") {
  check_gas(false);
}

TEST_CASE("a gas across the seam of a periodic slab keeps the one-rank momentum and energy",
          "[dem_mpi][gas][seam]") {
  // The period along x joins the last rank and rank 0: ghosts of the last rank reach rank 0
  // shifted by -L, particles cross the seam into the other end's rank.
  check_gas(true);
}

TEST_CASE("a state exported over the ranks continues bit for bit on the same ranks",
          "[dem_mpi][state]") {
  // The gas over the ranks, two threads each: after 400 steps each rank exports its part. A
  // fresh System on the same ranks takes it (its particles added where the last rebuild saw
  // them, so that setup keeps each on its rank) and resumes it exactly; another imports it
  // through the common rebuild, as the coupler does at a stage boundary, and is compared with
  // the first run importing its own state at the same step.
  const std::size_t n = 343;
  const auto make = [](System& s) { gas(s, false); };
  const SlabDecomposition thirds = x_slabs({{-1, 1}, {-1, 0.05, 1}, {-1, 0.035, 0.065, 1}});
  const auto fresh_from = [&](System& s, const SystemState& state) {
    const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
    s.materials.set_pair(g, g, {0.9, 0.3, 0.0});
    s.settings.gravity = {};
    s.settings.domain = {{-0.05, -0.01, -0.01}, {0.15, 0.11, 0.11}};
    s.add_wall(MeshWall(box_or_channel(0.1, true, 0.01), g, {}, false, "box"));
    for (std::size_t i = 0; i < state.position.size(); ++i) {
      s.particles.add(state.reference_position[i], {}, state.radius[i], 2650, state.material[i]);
      s.particles.id.back() = state.id[i];
    }
    s.set_rank_link(&world(), &thirds);
    s.setup();
    s.set_n_threads(2);
  };
  // Every particle on one rank, its position, velocity and spin the same bits in both runs.
  const auto check_same_bits = [n](const System& x, const System& y) {
    const BedState bx = gather(x, n, world()), by = gather(y, n, world());
    for (std::size_t id = 0; id < n; ++id) {
      REQUIRE(bx.held[id] == 1);
      CHECK(max_difference({bx.x[id], bx.v[id], bx.w[id]}, {by.x[id], by.v[id], by.w[id]}) == 0);
    }
  };
  System a, again;
  run(true, make, n, 400, 400, &a, 2, thirds);
  const SystemState state = a.export_state();
  CHECK(state.n_ranks == world().n_ranks());
  a.run(400);
  System b;
  fresh_from(b, state);
  b.resume_state(state);
  b.run(400);
  check_same_bits(b, a);
  // Through the rebuild of an import, against the first run doing the same.
  run(true, make, n, 400, 400, &again, 2, thirds);
  again.import_state(again.export_state());
  again.run(400);
  System c;
  fresh_from(c, state);
  c.import_state(state);
  c.run(400);
  check_same_bits(c, again);
}

TEST_CASE("a swirling gas round the full circle keeps the one-rank momentum and energy",
          "[dem_mpi][gas][circle]") {
  // Angular slabs round the whole circle (an annulus, no periodic boundary) are a ring whose
  // seam at theta = 0 turns by 2 pi: the last rank's ghosts reach rank 0 unturned. 3 x 4 rings
  // of spheres at radii 0.1 to 0.136 m, 12 mm apart, swirling at 2 m/s about z with random
  // velocities of about 1 m/s on top, no walls, no gravity; 1000 steps carry them 10 degrees
  // round, across every cut.
  const auto make = [](System& s) {
    const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
    s.materials.set_pair(g, g, {0.9, 0.3, 0.0});
    s.settings.gravity = {};
    s.settings.domain = {{-0.3, -0.3, -0.1}, {0.3, 0.3, 0.1}};
    std::uint64_t seed = 777;
    const auto uniform = [&seed]() {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      return double(seed >> 11) / double(std::uint64_t(1) << 53) - 0.5;
    };
    for (int ring_k = 0; ring_k < 4; ++ring_k)
      for (int layer = 0; layer < 3; ++layer) {
        const double rho = 0.1 + 0.012 * ring_k;
        const int n_around = int(2 * pi * rho / 0.012);
        for (int q = 0; q < n_around; ++q) {
          const double th = 2 * pi * (q + 0.5 * (layer % 2)) / n_around;
          const Vec3 x{rho * std::cos(th), rho * std::sin(th), 0.012 * layer};
          const Vec3 v{-2 * std::sin(th) + uniform(), 2 * std::cos(th) + uniform(), uniform()};
          s.particles.add(x, v, r, 2650, g);
        }
      }
  };
  System probe;
  make(probe);
  const std::size_t n = probe.particles.n_real;
  const int n_ranks = world().n_ranks();
  const SlabDecomposition slabs =
      SlabDecomposition::angular(SlabDecomposition::uniform_slabs(0, 2 * pi, n_ranks), 0.09);
  System ranked_system, plain_system;
  run(true, make, n, 1000, 1000, &ranked_system, 2, slabs, n_ranks > 1 ? ring() : world());
  run(false, make, n, 1000, 1000, &plain_system);
  const auto a = over_ranks(momentum_and_energy(ranked_system), world());
  const auto b = momentum_and_energy(plain_system);
  double mv = 0;
  for (std::size_t i = 0; i < plain_system.particles.n_real; ++i)
    mv += plain_system.particles.mass[i] * meshes::norm(plain_system.particles.velocity[i]);
  INFO("momentum " << a[0] << " " << a[1] << " (one rank " << b[0] << " " << b[1] << ", scale "
                   << mv << "); kinetic " << a[3] << " (" << b[3] << "), elastic " << a[5] << " ("
                   << b[5] << ")");
  for (int k = 0; k < 3; ++k)
    CHECK(std::abs(a[k] - b[k]) <= 1e-12 * mv);
  const double total = b[3] + b[4] + b[5];
  for (int k = 3; k < 6; ++k)
    CHECK(std::abs(a[k] - b[k]) <= 1e-9 * total);
  CHECK(b[4] > 1e-3 * total); // collisions with friction turned them
  // Without the ring the pairs across theta = 0 would be lost.
  if (n_ranks > 1) {
    System line;
    make(line);
    line.set_rank_link(&world(), &slabs);
    CHECK_THROWS_WITH(line.setup(), Catch::Matchers::Contains("full circle"));
  }
}

TEST_CASE("a stack crossing the seam of a periodic sector follows its one-rank trajectory",
          "[dem_mpi][history][seam]") {
  // As the stack above, at radius 0.3 m in a 30-degree sector, sliding along +theta across
  // theta = 30 degrees into rank 0 (rotated by -30 degrees with its histories and wall slot).
  // The upper sphere runs ahead and crosses a rebuild earlier: for a while the pair is
  // computed on rank 0 with the lower one as a ghost from across the seam. Angular slabs 10
  // or 15 degrees wide (52 mm at the inner radius 0.3 m).
  const double angle = pi / 6, rho = 0.3, th0 = angle - 0.009 / rho;
  const auto make = [=](System& s) {
    const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
    const int f = s.materials.add({"floor", 5e7, 0.25, 2650});
    s.materials.set_pair(g, g, {0.5, 0.5, 0.0});
    s.materials.set_pair(g, f, {0.5, 0.1, 0.0});
    s.materials.set_pair(f, f, {0.5, 0.1, 0.0});
    s.add_wall(MeshWall(floor_mesh(0.1, 0.45, -0.1, 0.3, 10, 10), f, {}, false, "floor"));
    s.settings.domain = {{-0.5, -0.5, -0.05}, {0.5, 0.5, 0.2}};
    s.settings.periodic = {true, angle};
    const Vec3 at{rho * std::cos(th0), rho * std::sin(th0), 0};
    const Vec3 v{-0.3 * std::sin(th0), 0.3 * std::cos(th0), 0};
    s.particles.add(at + Vec3{0, 0, r - 1e-6}, v, r, 2650, g);
    s.particles.add(at + Vec3{0, 0, 3 * r - 3e-6}, v, r, 2650, g);
  };
  const int n_ranks = world().n_ranks();
  const SlabDecomposition slabs =
      SlabDecomposition::angular(SlabDecomposition::uniform_slabs(0, angle, n_ranks), rho);
  const auto ranked = run(true, make, 2, 1200, 1, nullptr, 1, slabs, ring());
  const auto plain = run(false, make, 2, 1200, 1);
  int n_wrapped[2] = {0, 0};
  double worst = 0;
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    for (int id = 0; id < 2 && k > 0; ++id)
      n_wrapped[id] += ranked[k].rank[id] != ranked[k - 1].rank[id] && ranked[k].rank[id] == 0;
    for (int id = 0; id < 2; ++id)
      worst = std::max({worst, meshes::norm(ranked[k].x[id] - plain[k].x[id]) / rho,
                        meshes::norm(ranked[k].v[id] - plain[k].v[id]) / 0.3,
                        meshes::norm(ranked[k].w[id] - plain[k].w[id]) / 60});
  }
  INFO("largest relative departure from the one-rank run: " << worst);
  CHECK(worst <= 1e-12);
  if (n_ranks > 1) {
    CHECK(n_wrapped[0] == 1);
    CHECK(n_wrapped[1] == 1);
  }
  CHECK(std::atan2(plain.back().x[0].y, plain.back().x[0].x) < 0.1); // both wrapped
  CHECK(std::atan2(plain.back().x[1].y, plain.back().x[1].x) < 0.1);
  CHECK(plain.back().w[0].x * plain.back().w[1].x + plain.back().w[0].y * plain.back().w[1].y <
        0); // the pair slipped
}

TEST_CASE("slabs narrower than the reach are refused before any step", "[dem_mpi][bad-input]") {
  const int n_ranks = world().n_ranks();
  if (n_ranks < 2)
    return;
  // The pile is 80 mm long; cut into slabs of 20 mm / (n_ranks - 1) near its middle.
  System s;
  pile(s, false);
  std::vector<double> b{-1.0};
  for (int k = 1; k < n_ranks; ++k)
    b.push_back(0.02 * k / n_ranks);
  b.push_back(1.0);
  if (n_ranks == 2)
    b = {-1.0, 0.0, 0.01}; // the last slab 10 mm wide
  const SlabDecomposition slabs = SlabDecomposition::along_axis(0, b);
  s.set_rank_link(&world(), &slabs);
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(s.setup(), Contains(std::to_string(n_ranks) + " ranks") &&
                                   Contains("0.0125 m") && Contains("at most"));
  CHECK(s.n_steps() == 0);
}

TEST_CASE("balanced slabs carry equal shares of a cost histogram", "[dem_mpi][slabs]") {
  // Bins of [0, 4) with costs 1, 1, 2, 0: the cumulative cost is linear within a bin.
  const std::vector<double> cost{1, 1, 2, 0};
  CHECK(SlabDecomposition::balanced_slabs(cost, 0, 4, 1) == std::vector<double>{0, 4});
  CHECK(SlabDecomposition::balanced_slabs(cost, 0, 4, 2) == std::vector<double>{0, 2, 4});
  const auto three = SlabDecomposition::balanced_slabs(cost, 0, 4, 3);
  REQUIRE(three.size() == 4);
  CHECK(three[1] == Approx(4.0 / 3).epsilon(1e-15));
  CHECK(three[2] == Approx(7.0 / 3).epsilon(1e-15));
  // No cost at all: equal widths.
  CHECK(SlabDecomposition::balanced_slabs({0, 0}, 0, 1, 2) == std::vector<double>{0, 0.5, 1});
  // Angular slabs are measured as arcs at the inner radius: 10 degrees at 0.05 m is 8.7 mm.
  const auto a = SlabDecomposition::angular({0, pi / 18, pi / 9}, 0.05);
  CHECK(a.width(0) == Approx(0.05 * pi / 18));
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(a.check_widths(0.0125), Contains("2 ranks") && Contains("0.0125 m") &&
                                                Contains("arc at the inner radius") &&
                                                Contains("at most 1 slabs"));
  CHECK_NOTHROW(a.check_widths(0.008));
}

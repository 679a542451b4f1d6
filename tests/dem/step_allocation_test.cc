// The step loop allocates nothing (docs/dem.md, "Performance"): once a flowing bed's buffers
// have grown to its size, steps, list rebuilds (histories carried by id, ghosts across the
// periodic cut, wall candidates and slots) and the periodic spatial reordering reuse them; so
// does a bed of rigid clumps (the bodies reordered after their members).
//
// This executable replaces the global operator new with a counting one, which is why it is
// not part of test_dem: the count is process-wide, and only the window under test is counted.
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <omp.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> counting{false};
std::atomic<long> n_allocations{0};

void* counted_allocation(std::size_t size) {
  if (counting.load(std::memory_order_relaxed))
    n_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}
} // namespace

void* operator new(std::size_t size) {
  return counted_allocation(size);
}
void* operator new[](std::size_t size) {
  return counted_allocation(size);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

using namespace wear::dem;
using namespace wear::dem::testing;

TEST_CASE("a flowing bed steps and rebuilds without allocating", "[dem][allocation]") {
  // 1500 spheres of 8 and 10 mm in a 30-degree periodic tester sector, the floor turning at
  // 90 deg/s and wearing (its per-face window accumulates), on two threads.
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  add_periodic_tester_sector(s, g, 30, false, true);
  SizeDistribution psd{{8e-3, 10e-3}, {0.5, 0.5}, 1.0};
  const auto n =
      insert_random(s.particles, annular_sector_region(0.29, 0.5, 30 * pi / 180, 0, 0.06, 5.1e-3),
                    psd, 1500, 2650, g, 3);
  REQUIRE(n > 1000); // the spatial reordering runs from 1000 particles
  omp_set_num_threads(2);
  counting = true; // the counter sees the set-up's allocations (lists, slots, scratch)
  s.setup();
  counting = false;
  REQUIRE(n_allocations.load() > 0);
  n_allocations = 0;
  // Settling and flow for 0.5 s: the bed's counts (pairs, ghosts, near-wall particles, cells)
  // reach their level, and the buffers with them (after 0.3 s two buffers still grew once,
  // by the doubling of a vector that the growing list filled: growth, not a buffer made anew).
  s.run(std::uint64_t(0.5 / s.time_step()));
  const auto rebuilds_before = s.n_rebuilds();
  counting = true;
  s.run(std::uint64_t(0.2 / s.time_step()));
  counting = false;
  omp_set_num_threads(omp_get_num_procs());
  const auto n_rebuilds = s.n_rebuilds() - rebuilds_before;
  INFO(n_rebuilds << " rebuilds, " << s.n_ghosts() << " ghosts, "
                  << s.wear_integrals(0).total_archard << " N m of Archard load-distance");
  // Enough rebuilds that at least two reorder the particles (every tenth does).
  REQUIRE(n_rebuilds >= 20);
  REQUIRE(s.n_ghosts() > 0);
  REQUIRE(s.wear_integrals(0).total_archard > 0);
  CHECK(n_allocations.load() == 0);
}

TEST_CASE("a flowing bed of clumps steps and rebuilds without allocating", "[dem][allocation]") {
  // 400 clumps of four spheres (1600 members) on a turning annular floor, on two threads:
  // the bodies' pass, the gathering of their forces, the members found by id and the bodies
  // reordered after their members at every tenth rebuild.
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  WallMotion turning;
  turning.angular_velocity = 0.5 * pi;
  const double ri = 0.1, ro = 0.2;
  s.add_wall(RevolutionWall(RevolutionSurface::annulus(0, ri, ro), g, turning, false, "floor"));
  s.add_wall(RevolutionWall(RevolutionSurface::cylinder(ri, 0, 0.1), g, {}, false, "inner"));
  s.add_wall(RevolutionWall(RevolutionSurface::cylinder(ro, 0, 0.1), g, {}, false, "outer"));
  s.settings.domain = {{-0.3, -0.3, -0.01}, {0.3, 0.3, 0.3}};
  const ClumpShape shape = clump_shape({"tetrahedron",
                                        {{{0.7, 0, 0}, 1},
                                         {{-0.6, 0.4, 0.1}, 0.9},
                                         {{-0.3, -0.5, 0}, 0.85},
                                         {{0, 0.1, 0.45}, 0.8}}});
  SizeDistribution psd{{8e-3}, {1}, 1.0};
  const double margin = 4e-3;
  FillRegion region{{-ro, -ro, 0}, {ro, ro, 0.05}, [=](const Vec3& x) {
                      const double r = std::hypot(x.x, x.y);
                      return ri + margin < r && r < ro - margin && x.z > margin && x.z < 0.05;
                    }};
  REQUIRE(insert_random_clumps(s, region, psd, shape, 400, 2650, g, 3) == 400);
  omp_set_num_threads(2);
  s.setup();
  s.run(std::uint64_t(0.5 / s.time_step()));
  const auto rebuilds_before = s.n_rebuilds();
  n_allocations = 0;
  counting = true;
  s.run(std::uint64_t(0.2 / s.time_step()));
  counting = false;
  omp_set_num_threads(omp_get_num_procs());
  const auto n_rebuilds = s.n_rebuilds() - rebuilds_before;
  INFO(n_rebuilds << " rebuilds");
  REQUIRE(n_rebuilds >= 20);
  CHECK(n_allocations.load() == 0);
}

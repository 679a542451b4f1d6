// Clumps decomposed over the ranks of the test (1, 2 or 3) against the same bodies in one
// plain System: a stack of two clumps sliding across the cuts along x on a floor (a body
// migrates whole, its members' wall slots and pair histories with it, and its members overhang
// into the neighbour's slab before and after), and two clumps colliding across the seam of a
// periodic sector over a ring of ranks (the body wraps from the last rank into rank 0 while in
// contact). The members' states are compared by stable id at every gather. A pile of clumps'
// parts merged into one process's bed (bodies and all) go on in one process and over the ranks
// again as the run that was not stopped.
#include "dem/engine/clump_shape.h"
#include "dem/engine/rank_states.h"
#include "dem/scene/particle_shapes.h"
#include "tests/dem_mpi/dem_mpi_fixtures.h"

#include <cstdint>

using namespace wear::dem;
using namespace wear::dem::testing;
namespace meshes = wear::meshes;

namespace {

/// A library shape scaled to the equivalent diameter d [m].
ClumpShape library_shape(const std::string& name, double d) {
  const ClumpShape s = clump_shape(named_clump_template(name, "test"));
  return s.scaled(d / s.equivalent_diameter());
}

/// The ranks of the world as a ring, for a periodic bed (the seam joins the last and rank 0).
MpiRankLink& ring() {
  static MpiRankLink link(MPI_COMM_WORLD, true);
  return link;
}

/// Runs `n_steps` steps of the bodies `make` adds, over the ranks (slabs, link) or in one
/// System, and returns the members' states by id every `every` steps.
template <class Make>
std::vector<BedState> run(bool ranked, Make make, std::size_t n_ids, int n_steps, int every,
                          const SlabDecomposition& slabs, RankLink& link) {
  System s;
  make(s);
  if (ranked)
    s.set_rank_link(&link, &slabs);
  s.setup();
  s.set_n_threads(1);
  std::vector<BedState> states;
  for (int k = 0; k < n_steps; k += every) {
    s.run(std::uint64_t(every));
    states.push_back(ranked ? gather(s, n_ids, world()) : by_id(s, n_ids));
  }
  return states;
}

/// The largest departure of `ranked` from `plain` over the gathers, relative to the scales of
/// position, velocity and spin; every member held by exactly one rank, and the members of each
/// body (ids [m k, m (k + 1))) by the same one. Counts the gathers at which body `b` changed
/// rank into `n_moves[b]`.
double departure(const std::vector<BedState>& ranked, const std::vector<BedState>& plain,
                 std::size_t members, double x_scale, double v_scale, double w_scale,
                 std::vector<int>& n_moves) {
  double worst = 0;
  const std::size_t n_ids = plain.front().x.size();
  for (std::size_t k = 0; k < ranked.size(); ++k)
    for (std::size_t id = 0; id < n_ids; ++id) {
      REQUIRE(ranked[k].held[id] == 1);
      REQUIRE(ranked[k].rank[id] == ranked[k].rank[id - id % members]);
      if (id % members == 0 && k > 0)
        n_moves[id / members] += ranked[k].rank[id] != ranked[k - 1].rank[id];
      worst = std::max({worst, meshes::norm(ranked[k].x[id] - plain[k].x[id]) / x_scale,
                        meshes::norm(ranked[k].v[id] - plain[k].v[id]) / v_scale,
                        meshes::norm(ranked[k].w[id] - plain[k].w[id]) / w_scale});
    }
  return worst;
}

} // namespace

TEST_CASE("a stack of clumps sliding across the cuts follows its one-rank trajectory",
          "[dem_mpi][clump][history]") {
  // Two 'elongated 2' clumps (8 mm) lying along x, one on the other, the lower one sliding at
  // 0.3 m/s on a slippery floor (mu = 0.1) with a spin against it: the floor turns it, so the
  // two member pairs (mu = 0.5) slip and hold tangential histories. The stack starts 1.4 mm
  // short of the cut (x = 0.002 on two ranks, 0.013 on three) and crosses it; the bodies'
  // members reach 2.4 mm beyond their centres, into the neighbour's slab.
  const ClumpShape shape = library_shape("elongated 2", 8e-3);
  const double rm = shape.members[0].radius;
  const double x0 = world().n_ranks() == 3 ? 0.0116 : 0.0006;
  const auto make = [&](System& s) {
    const int g = gravel_on_slippery_floor(s);
    const Quaternion q{};
    s.add_clump(shape, 2650, g, {x0, 0, rm - 1e-6}, q, {0.3, 0, 0}, {0, -30, 0});
    s.add_clump(shape, 2650, g, {x0, 2e-4, 3 * rm - 3e-6}, q, {0.3, 0, 0}, {});
  };
  const SlabDecomposition slabs = x_slabs({{-1, 1}, {-1, 0.002, 1}, {-1, -0.006, 0.013, 1}});
  const auto ranked = run(true, make, 4, 2000, 1, slabs, world());
  const auto plain = run(false, make, 4, 2000, 1, slabs, world());
  std::vector<int> n_moves(2, 0);
  const double worst = departure(ranked, plain, 2, 0.01, 0.3, 60, n_moves);
  INFO("largest relative departure from the one-rank run: " << worst);
  CHECK(worst <= 1e-12);
  if (world().n_ranks() > 1) {
    CHECK(n_moves[0] == 1);
    CHECK(n_moves[1] == 1);
  }
  // It crossed the cut, and the pairs slipped: the upper body turns against the lower one.
  CHECK(plain.back().x[0].x > x0 + 0.003);
  CHECK(plain.back().w[0].y * plain.back().w[2].y < 0);
}

TEST_CASE("a clump running into another across a cut meets it where its member overhangs",
          "[dem_mpi][clump][reach]") {
  // Two 'elongated 2' clumps (8 mm) lying along x on a floor, head to tail: b at rest with its
  // centre 0.3 mm beyond the cut (x = 0.002 on two ranks, 0.013 on three), a behind it on the
  // rank below, sliding into it at 0.3 m/s. They touch where b's rear member overhangs the cut,
  // with a's front member more than the contact reach of spheres (two largest radii and the
  // skin, 0.5 mm here) below the cut: the rank above sees it as a ghost only because the ghosts
  // reach a member's overhang further.
  const ClumpShape shape = library_shape("elongated 2", 8e-3);
  const double c = std::abs(shape.members[0].centre.x), rm = shape.members[0].radius;
  const double cut = world().n_ranks() == 3 ? 0.013 : 0.002, skin = 0.5e-3;
  const double xb = cut + 0.3e-3, xa = xb - 2 * c - 2 * rm - 0.5e-3;
  REQUIRE(c + 2 * rm - 0.3e-3 > 2 * rm + skin + 1e-3); // a's front member out of spheres' reach
  const auto make = [&](System& s) {
    const int g = gravel_on_slippery_floor(s);
    s.settings.skin = skin;
    s.add_clump(shape, 2650, g, {xa, 0, rm - 1e-6}, {}, {0.3, 0, 0}, {});
    s.add_clump(shape, 2650, g, {xb, 1e-4, rm - 1e-6}, {}, {}, {});
  };
  const SlabDecomposition slabs = x_slabs({{-1, 1}, {-1, 0.002, 1}, {-1, -0.006, 0.013, 1}});
  const auto ranked = run(true, make, 4, 1500, 10, slabs, world());
  const auto plain = run(false, make, 4, 1500, 10, slabs, world());
  std::vector<int> n_moves(2, 0);
  const double worst = departure(ranked, plain, 2, 0.01, 0.3, 60, n_moves);
  INFO("largest relative departure from the one-rank run: " << worst);
  CHECK(worst <= 1e-12);
  // a hit b: b moves on along +x.
  CHECK(plain.back().v[2].x > 0.05);
}

TEST_CASE("two clumps colliding across the seam of a periodic sector over a ring of ranks "
          "follow their one-rank run",
          "[dem_mpi][clump][seam]") {
  // The collision of clump_system_test.cc: two 'elongated 2' clumps (6 mm) along the circle
  // at R = 0.4 m drifting along it at about 3 m/s in a 30-degree sector; a's front member has
  // crossed the seam theta = 30 degrees when the pair touches, and a's centre crosses it while
  // they touch: a passes from the last rank into rank 0 whole (its members with their
  // histories turned by the seam), its members reaching 1.7 mm beyond its centre. Angular
  // slabs 10 or 15 degrees wide (70 mm at R).
  const double angle = 30 * pi / 180, R = 0.4, t0 = 1.00005e-3;
  const auto turn = [](double b, const Vec3& v) {
    return Vec3{v.x * std::cos(b) - v.y * std::sin(b), v.x * std::sin(b) + v.y * std::cos(b), v.z};
  };
  const ClumpShape shape = library_shape("elongated 2", 6e-3);
  const double c = std::abs(shape.members[0].centre.x), rm = shape.members[0].radius;
  const Quaternion along = rotation_about({0, 0, 1}, 0.5 * pi);
  const Vec3 va{0.02, 3.1, 0.01}, vb{-0.01, 2.9, -0.02}, wa{1, -4, 2.5}, wb{-1.5, 2, 3};
  const Vec3 touch_a{R, -0.2e-3, 0.05};
  const Vec3 front_a = touch_a + Vec3{0, c, 0};
  const Vec3 touch_b =
      front_a + Vec3{1.0e-3, std::sqrt(4 * rm * rm - 1.25e-6), 0.5e-3} + Vec3{0, c, 0};
  const Vec3 xa = turn(angle, touch_a - t0 * va), xb = touch_b - t0 * vb;
  const auto make = [&](System& s) {
    const int g = add_gravel(s, 0.5, 0.5, 0);
    s.settings.gravity = {};
    s.settings.periodic = {true, angle};
    s.settings.time_step = 2e-7;
    s.settings.skin = 2e-4;
    s.settings.domain = {{-1, -1, -1}, {1, 1, 1}};
    s.add_clump(shape, 2650, g, xa, rotation_about({0, 0, 1}, angle) * along, turn(angle, va),
                turn(angle, wa));
    s.add_clump(shape, 2650, g, xb, along, vb, wb);
  };
  const int n_ranks = world().n_ranks();
  const SlabDecomposition slabs =
      SlabDecomposition::angular(SlabDecomposition::uniform_slabs(0, angle, n_ranks), R);
  const auto ranked = run(true, make, 4, 15000, 100, slabs, ring());
  const auto plain = run(false, make, 4, 15000, 100, slabs, ring());
  std::vector<int> n_moves(2, 0);
  const double worst = departure(ranked, plain, 2, R, 3, 10, n_moves);
  INFO("largest relative departure from the one-rank run: " << worst);
  CHECK(worst <= 1e-12);
  if (n_ranks > 1)
    CHECK(n_moves[0] >= 1); // a wrapped into rank 0
  // The collision happened: it changed b's velocity.
  CHECK(meshes::norm(plain.back().v[2] - plain.front().v[2]) > 0.01);
}

namespace {
/// A pile of 12 'crushed stone 4' clumps (8 mm) in two layers on a floor across the cuts,
/// turned about fixed axes; without `bodies` the floor and materials only.
void clump_pile(System& s, bool bodies) {
  const int g = gravel_on_floor(s, true);
  if (!bodies)
    return;
  const ClumpShape shape = library_shape("crushed stone 4", 8e-3);
  for (int layer = 0; layer < 2; ++layer)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 2; ++j) {
        const int k = 6 * layer + 2 * i + j;
        const Quaternion q =
            rotation_about(meshes::normalized(Vec3{1.0 + k, 2.0 - j, 3.0}), 0.4 * k);
        s.add_clump(shape, 2650, g,
                    {-0.012 + 0.011 * i + 0.004 * layer, 0.011 * j, 0.005 + 0.01 * layer}, q, {},
                    {});
      }
}

/// `s` takes up `state` in one thread: its particles and bodies on the pile's floor, over
/// `link` and `slabs` when given.
void take_up(System& s, const SystemState& state, RankLink* link = nullptr,
             const SlabDecomposition* slabs = nullptr) {
  clump_pile(s, false);
  for (std::size_t i = 0; i < state.position.size(); ++i) {
    s.particles.add(state.position[i], state.velocity[i], state.radius[i], 2650, state.material[i]);
    s.particles.id.back() = state.id[i];
  }
  s.add_state_clumps(state.clumps);
  if (link)
    s.set_rank_link(link, slabs);
  s.setup();
  s.set_n_threads(1);
  s.import_state(state);
  s.add_wear_window(state);
}
} // namespace

TEST_CASE("a pile of clumps' parts merged go on in one process and over the ranks as if never "
          "stopped",
          "[dem_mpi][clump][merged]") {
  const SlabDecomposition slabs = x_slabs({{-1, 1}, {-1, 0.002, 1}, {-1, -0.006, 0.013, 1}});
  System a;
  clump_pile(a, true);
  const std::size_t n = a.particles.n_real;
  a.set_rank_link(&world(), &slabs);
  a.setup();
  a.set_n_threads(1);
  a.run(1500);
  const SystemState part = a.export_state();
  const std::vector<double> packed = pack_state(part);
  CHECK(pack_state(unpack_state(packed.data(), packed.size())) == packed);
  const SystemState merged = whole_state_on_every_rank(part, world());
  CHECK(merged.clumps.size() == 12);
  CHECK(merged.position.size() == n);
  a.run(1000);
  const BedState reference = gather(a, n, world());
  const auto check_bed = [&](const BedState& b) {
    for (std::size_t id = 0; id < n; ++id)
      CHECK(b.held[id] == 1);
    CHECK(max_difference(b.x, reference.x) <= 1e-12);
    CHECK(max_difference(b.v, reference.v) <= 1e-10);
  };
  // The bodies moved: the upper layer fell onto the lower one.
  System start;
  clump_pile(start, true);
  CHECK(max_difference(reference.x, by_id(start, n).x) > 1e-3);
  SECTION("in one process") {
    System one;
    take_up(one, merged);
    one.run(1000);
    check_bed(by_id(one, n));
    CHECK(one.clumps().size() == 12);
  }
  SECTION("over the ranks again") {
    System again;
    take_up(again, merged, &world(), &slabs);
    again.run(1000);
    check_bed(gather(again, n, world()));
    double bodies = double(again.clumps().size());
    world().sum_in_rank_order(&bodies, 1);
    CHECK(bodies == 12);
  }
}

// A bed decomposed over the ranks of the test (1, 2 or 3), its parts merged into the bed of
// one process (merge_rank_states) and taken up on another rank count, against the decomposed
// run going on: how a checkpoint written on N ranks continues on M.
// - A pile resting across the cuts on a wearing floor (static friction held in the pair and
//   wall histories): the merged bed in one process, and decomposed again over the ranks,
//   follows the run that was not stopped to 1e-12 m, and the wear window it carries (summed
//   over ranks and threads) gives the same window integrals to 1e-12 of their scale. Without
//   the pair histories the pile slips by 5e-7 m in these steps (the test fails).
// - The collisional gas across the seam of a periodic slab (pairs across the seam listed with
//   ghosts of the last rank on rank 0, images in the merged bed): momentum to 1e-12 of
//   sum m |v| and energies to 1e-9 of the total after 300 more steps.
// - The state of one process taken up over the ranks follows that process going on, with its
//   wear window.
// - The parts pack into a message and back bit for bit; parts from the wrong ranks are refused.
#include "dem/engine/rank_states.h"
#include "tests/dem_mpi/dem_mpi_fixtures.h"

#include <cstdint>
#include <string>

using namespace wear::dem;
using namespace wear::dem::testing;
namespace meshes = wear::meshes;

namespace {

/// Every rank's part, on every rank, in rank order (each message prefixed by its length).
std::vector<SystemState> all_parts(const SystemState& mine, RankLink& link) {
  std::vector<double> message = pack_state(mine), all;
  message.insert(message.begin(), double(message.size()));
  link.gather_in_rank_order(message, all);
  std::vector<SystemState> parts;
  for (std::size_t at = 0; at < all.size();) {
    const auto n = std::size_t(all[at]);
    parts.push_back(unpack_state(all.data() + at + 1, n));
    at += n + 1;
  }
  return parts;
}

/// The bed of `state` in s (whose walls and materials `make` set up), before setup().
template <class Make>
void take_bed(System& s, Make make, const SystemState& state) {
  make(s);
  s.particles = Particles{};
  for (std::size_t i = 0; i < state.position.size(); ++i) {
    s.particles.add(state.position[i], state.velocity[i], state.radius[i], 2650, state.material[i]);
    s.particles.id.back() = state.id[i];
  }
}

/// `s` takes up `state` in one thread: the bed (walls and materials from `make`), over `link`
/// and `slabs` when given, then the particles' state and the open wear window.
template <class Make>
void take_up(System& s, Make make, const SystemState& state, RankLink* link = nullptr,
             const SlabDecomposition* slabs = nullptr) {
  take_bed(s, make, state);
  if (link)
    s.set_rank_link(link, slabs);
  s.setup();
  s.set_n_threads(1);
  s.import_state(state);
  s.add_wear_window(state);
}

/// The pile on its wearing floor, and the gas periodic along x (dem_mpi_fixtures.h).
void wearing_pile(System& s) {
  pile(s, true);
}
void periodic_gas(System& s) {
  gas(s, true);
}

MpiRankLink& ring() {
  static MpiRankLink link(MPI_COMM_WORLD, true);
  return link;
}

} // namespace

TEST_CASE("a pile's parts merged go on in one process and over the ranks as if never stopped",
          "[dem_mpi][merged]") {
  const std::size_t n = 23;
  const SlabDecomposition slabs = x_slabs({{-1, 1}, {-1, 0.002, 1}, {-1, -0.006, 0.013, 1}});
  System a;
  wearing_pile(a);
  a.set_rank_link(&world(), &slabs);
  a.setup();
  a.set_n_threads(2);
  a.run(1500);
  const SystemState part = a.export_state();
  const std::vector<SystemState> parts = all_parts(part, world());
  SECTION("the parts pack and unpack bit for bit") {
    const std::vector<double> packed = pack_state(part);
    CHECK(pack_state(unpack_state(packed.data(), packed.size())) == packed);
    CHECK_THROWS_WITH(unpack_state(packed.data(), packed.size() - 1),
                      Catch::Contains("DEM state message"));
  }
  const SystemState merged = merge_rank_states(parts);
  CHECK(merged.position.size() == n);
  CHECK(merged.n_ranks == 1);
  a.run(1000);
  const BedState reference = gather(a, n, world());
  const WearIntegrals w_reference = a.wear_integrals_over_ranks(0);

  const auto check_window = [&](const WearIntegrals& w) {
    double scale = 0, diff = 0;
    for (std::size_t f = 0; f < w.normal_impulse.size(); ++f) {
      scale = std::max(scale, w_reference.normal_impulse[f]);
      diff = std::max(diff, std::abs(w.normal_impulse[f] - w_reference.normal_impulse[f]));
    }
    CHECK(scale > 0);
    CHECK(diff <= 1e-12 * scale);
    CHECK(w.total_archard == Approx(w_reference.total_archard).epsilon(1e-12));
  };
  SECTION("in one process") {
    System one;
    take_up(one, wearing_pile, merged);
    one.run(1000);
    const BedState b = by_id(one, n);
    CHECK(max_difference(b.x, reference.x) <= 1e-12);
    CHECK(max_difference(b.v, reference.v) <= 1e-10);
    check_window(one.wear_integrals(0));
  }
  SECTION("over the ranks again, one thread each") {
    System again;
    take_up(again, wearing_pile, merged, &world(), &slabs);
    again.run(1000);
    const BedState b = gather(again, n, world());
    for (std::size_t id = 0; id < n; ++id)
      CHECK(b.held[id] == 1);
    CHECK(max_difference(b.x, reference.x) <= 1e-12);
    CHECK(max_difference(b.v, reference.v) <= 1e-10);
    check_window(again.wear_integrals_over_ranks(0));
  }
  SECTION("parts out of order are refused") {
    if (parts.size() > 1) {
      std::vector<SystemState> swapped = parts;
      std::swap(swapped[0], swapped[1]);
      CHECK_THROWS_WITH(merge_rank_states(swapped), Catch::Contains("was written by rank 1"));
    }
  }
}

TEST_CASE("a pile's state of one process goes on over the ranks as in that process",
          "[dem_mpi][merged]") {
  // Every rank runs the same one-process pile; its state is taken up by the ranks together.
  const std::size_t n = 23;
  const SlabDecomposition slabs = x_slabs({{-1, 1}, {-1, 0.002, 1}, {-1, -0.006, 0.013, 1}});
  System one;
  wearing_pile(one);
  one.setup();
  one.set_n_threads(2);
  one.run(1500);
  const SystemState state = one.export_state();
  CHECK(state.n_ranks == 1);
  one.run(1000);
  System ranked;
  take_up(ranked, wearing_pile, state, &world(), &slabs);
  ranked.run(1000);
  const BedState a = gather(ranked, n, world()), b = by_id(one, n);
  for (std::size_t id = 0; id < n; ++id)
    CHECK(a.held[id] == 1);
  CHECK(max_difference(a.x, b.x) <= 1e-12);
  CHECK(max_difference(a.v, b.v) <= 1e-10);
  const WearIntegrals w = ranked.wear_integrals_over_ranks(0), w1 = one.wear_integrals(0);
  CHECK(w1.total_archard > 0);
  CHECK(w.total_archard == Approx(w1.total_archard).epsilon(1e-12));
}

TEST_CASE("a periodic gas's parts merged keep the momentum and energy of the run going on",
          "[dem_mpi][merged]") {
  const std::size_t n = 343;
  const SlabDecomposition thirds = x_slabs({{0, 0.1}, {0, 0.05, 0.1}, {0, 0.035, 0.065, 0.1}});
  System a;
  periodic_gas(a);
  a.set_rank_link(&ring(), &thirds);
  a.setup();
  a.set_n_threads(2);
  a.run(400);
  const SystemState merged = merge_rank_states(all_parts(a.export_state(), world()));
  a.run(300);
  const auto reference = over_ranks(momentum_and_energy(a), world());
  double mv = 0; // [kg m/s] sum of m |v|
  const BedState bed = gather(a, n, world());
  for (std::size_t id = 0; id < n; ++id)
    mv += merged.mass[0] * meshes::norm(bed.v[id]);
  const auto check = [&](const std::vector<double>& b) {
    INFO("momentum " << b[0] << " " << b[1] << " " << b[2] << " (going on " << reference[0] << " "
                     << reference[1] << " " << reference[2] << "); kinetic " << b[3] << " ("
                     << reference[3] << ")");
    for (int k = 0; k < 3; ++k)
      CHECK(std::abs(b[k] - reference[k]) <= 1e-12 * mv);
    const double total = reference[3] + reference[4] + reference[5];
    for (int k = 3; k < 6; ++k)
      CHECK(std::abs(b[k] - reference[k]) <= 1e-9 * total);
  };
  System one;
  take_up(one, periodic_gas, merged);
  one.run(300);
  check(momentum_and_energy(one));
  System again;
  take_up(again, periodic_gas, merged, &ring(), &thirds);
  again.run(300);
  check(over_ranks(momentum_and_energy(again), world()));
}

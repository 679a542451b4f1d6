// A scene's inlet and outlets: the requested mass flow reaches the bed, inserted = in the
// system + removed exactly, bad inlets are refused by name, and an inlet continues exactly
// from its saved state.
#include "dem/scene/inlet.h"
#include "dem/scene/outlet.h"
#include "dem_fixtures.h"
#include "meshes/constants.h"

#include <catch2/catch.hpp>

#include <unordered_map>

using namespace wear::dem;
using namespace wear::dem::testing;

namespace {

/// 8 and 6 mm gravel, half the mass each.
SizeDistribution gravel_psd() {
  SizeDistribution psd;
  psd.diameters = {0.008, 0.006};
  psd.mass_fractions = {0.5, 0.5};
  return psd;
}

/// A 0.2 m x 0.2 m inlet at z = 0.35 m over the middle of the box [0, 0.4]^3, particles
/// leaving it downwards at 0.5 m/s.
InletSpec falling_stream(double mass_flow) {
  InletSpec in;
  in.name = "hopper feed";
  in.corner = {0.1, 0.1, 0.35};
  in.edge_u = {0.2, 0, 0};
  in.edge_v = {0, 0.2, 0};
  in.mass_flow = mass_flow;
  in.velocity = {0, 0, -0.5};
  in.psd = gravel_psd();
  in.density = 2650;
  in.seed = 7;
  return in;
}

} // namespace

TEST_CASE("inlet: the requested mass flow crosses a plane below it, and every particle is "
          "counted once") {
  const double rate = 2.0; // [kg/s]
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.05);
  s.add_wall(MeshWall(box_walls(0.4), g, WallMotion{}, false, "box"));
  Inlet inlet(falling_stream(rate));
  // The floor but a strip along x = 0, where the system's first particle rests (set-up needs
  // one; an outlet that removed the last particle would stop the run).
  std::vector<Outlet> outlets{{"floor", {0.05, 0, 0}, {0.4, 0.4, 0.05}}};
  // The list reach, skin and time step come from the distribution, not that particle.
  s.particles.add({0.02, 0.02, 0.004}, {}, 0.003, 2650, g);
  s.settings.max_radius = 0.004;
  s.settings.skin = 0.0015;
  s.settings.time_step = 2e-5;
  s.setup();
  s.set_n_threads(1); // a few hundred particles: a second thread would only wait
  const std::size_t n_start = s.particles.n_real;
  std::size_t n_removed = 0;
  // Mass crossing z = 0.2 m downwards, by particle, between batches.
  std::unordered_map<std::int64_t, double> z_before;
  double crossed = 0;
  // The stream comes in batches, one per interval: the window spans whole intervals, so it
  // counts whole batches whatever their phase at the plane.
  const auto steps = std::uint64_t(std::llround(inlet.interval() / s.time_step()));
  const double period = double(steps) * s.time_step(), plane = 0.2;
  const double window_start = 12 * period, window_end = 24 * period;
  double max_owed = 0; // [kg] right after a batch
  while (s.time() < window_end - 1e-9) {
    s.insert_particles(inlet.batch(s.time(), s.particles));
    max_owed = std::max(max_owed, inlet.owed_mass(s.time()));
    n_removed += apply_outlets(s, outlets);
    for (std::uint64_t k = 0; k < steps; k += 20) {
      s.run(20);
      const auto& p = s.particles;
      for (std::size_t i = 0; i < p.n_real; ++i) {
        auto [it, first] = z_before.try_emplace(p.id[i], p.position[i].z);
        if (!first && it->second > plane && p.position[i].z <= plane &&
            s.time() > window_start + 1e-9)
          crossed += p.mass[i];
        it->second = p.position[i].z;
      }
    }
  }
  const double measured = crossed / (s.time() - window_start);
  INFO("inserted " << inlet.state().n_inserted << " particles, " << n_removed << " removed");
  CHECK(measured == Approx(rate).epsilon(0.02));
  CHECK(max_owed <= 0.5 * 2650 * wear::pi / 6 * 0.008 * 0.008 * 0.008); // half a particle
  // Inserted = in the system + removed, exactly in count.
  CHECK(n_start + inlet.state().n_inserted == s.particles.n_real + n_removed);
  CHECK(outlets[0].n_removed == n_removed);
  CHECK(n_removed > 100);
}

TEST_CASE("inlet: bad inlets are refused with their name") {
  InletSpec in = falling_stream(2);
  in.edge_v = {0.4, 0, 0}; // parallel to edge u
  CHECK_THROWS_WITH(Inlet(in), Catch::Contains("hopper feed") && Catch::Contains("no area"));
  in = falling_stream(2);
  in.velocity = {0.5, 0, 0}; // along the rectangle
  CHECK_THROWS_WITH(Inlet(in), Catch::Contains("hopper feed") && Catch::Contains("cross"));
  in = falling_stream(60); // a solid fraction of 1.1 in the insertion box
  CHECK_THROWS_WITH(Inlet(in), Catch::Contains("solid fraction"));
  in = falling_stream(-1);
  CHECK_THROWS_WITH(Inlet(in), Catch::Contains("Mass flow rate"));
  in = falling_stream(2);
  in.edge_u = {0.01, 0, 0};
  CHECK_THROWS_WITH(Inlet(in), Catch::Contains("narrower"));
}

TEST_CASE("inlet: it continues exactly from its saved state") {
  Inlet a(falling_stream(2)), b(falling_stream(2));
  Particles none;
  for (int k = 1; k <= 3; ++k)
    a.batch(0.03 * k, none);
  b.restore(a.state());
  const auto next_a = a.batch(0.12, none), next_b = b.batch(0.12, none);
  REQUIRE(next_a.size() == next_b.size());
  REQUIRE(!next_a.empty());
  for (std::size_t i = 0; i < next_a.size(); ++i) {
    CHECK(next_a[i].position == next_b[i].position);
    CHECK(next_a[i].radius == next_b[i].radius);
  }
}

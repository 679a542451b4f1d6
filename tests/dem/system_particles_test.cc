// Particles entering and leaving a running System (inlets and outlets): new ids, ballistic
// flight of an inserted particle, histories of the contacts that stay, exact counts, and
// bitwise reproducible runs and resumes with insertions and removals.
#include "dem_fixtures.h"

#include <catch2/catch.hpp>

#include <map>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::norm;

namespace {

/// A settled bed of 64 particles (r = 5 mm) in the closed box [0, 0.1]^3.
System settled_bed(int n_threads) {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.05);
  s.add_wall(MeshWall(box_walls(0.1), g, WallMotion{}, true, "box"));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        s.particles.add({0.015 + 0.023 * i, 0.015 + 0.023 * j, 0.008 + 0.0125 * k}, {}, 0.005, 2650,
                        g);
  // Reach, skin and time step fixed, not taken from the particles present at setup: a system
  // set up again from a state with inserted (smaller) particles must step the same way.
  s.settings.max_radius = 0.006;
  s.settings.skin = 0.0025;
  s.settings.time_step = 2e-5;
  s.setup();
  s.set_n_threads(n_threads);
  s.run(4000);
  return s;
}

/// Tangential histories of the pairs in contact, by their ids (lower, higher).
std::map<std::pair<std::int64_t, std::int64_t>, Vec3> histories_by_ids(const System& s) {
  const SystemState st = s.export_state();
  std::map<std::pair<std::int64_t, std::int64_t>, Vec3> h;
  for (std::size_t k = 0; k < st.pair_i.size(); ++k) {
    if (norm(st.pair_history[k]) == 0)
      continue;
    const std::int64_t a = st.id[st.pair_i[k]], b = st.id[st.pair_j[k]];
    h[{std::min(a, b), std::max(a, b)}] = a < b ? st.pair_history[k] : st.pair_history[k] * -1.0;
  }
  return h;
}

NewParticle dropped(const Vec3& x, const Vec3& v, int material) {
  NewParticle q;
  q.position = x;
  q.velocity = v;
  q.radius = 0.004;
  q.density = 2650;
  q.material = material;
  return q;
}

} // namespace

TEST_CASE("particles in and out: an inserted particle gets a new id and flies ballistically") {
  System s = settled_bed(1);
  const std::size_t n0 = s.particles.n_real;
  const std::int64_t first = s.next_id();
  CHECK(first == std::int64_t(n0));
  const Vec3 x0{0.05, 0.05, 0.09}, v0{0.1, -0.05, 0.2};
  s.insert_particles({dropped(x0, v0, 0)});
  REQUIRE(s.particles.n_real == n0 + 1);
  CHECK(s.next_id() == first + 1);
  std::size_t k = 0;
  while (s.particles.id[k] != first)
    ++k;
  CHECK(s.particles.force[k].z == Approx(-9.81 * s.particles.mass[k]));
  // Constant gravity, no contact for 0.02 s: velocity Verlet is exact for it.
  const double t0 = s.time();
  s.run(std::uint64_t(0.02 / s.time_step()));
  for (k = 0; s.particles.id[k] != first;)
    ++k;
  const double t = s.time() - t0;
  const Vec3 g{0, 0, -9.81};
  CHECK(norm(s.particles.position[k] - (x0 + v0 * t + g * (0.5 * t * t))) <= 1e-12);
  CHECK(norm(s.particles.velocity[k] - (v0 + g * t)) <= 1e-12);

  NewParticle bad = dropped(x0, v0, 0);
  bad.radius = -1;
  CHECK_THROWS_WITH(s.insert_particles({bad}), Catch::Contains("radius"));
  bad = dropped(x0, v0, 3);
  CHECK_THROWS_WITH(s.insert_particles({bad}), Catch::Contains("unknown material"));
  bad = dropped(x0, v0, 0);
  bad.radius = 0.01;
  CHECK_THROWS_WITH(s.insert_particles({bad}), Catch::Contains("largest particle at setup"));
}

TEST_CASE("particles in and out: removing particles keeps the histories of the contacts that "
          "stay") {
  System s = settled_bed(2);
  const auto before = histories_by_ids(s);
  const SystemState st = s.export_state();
  std::size_t n_in_outlet = 0;
  const auto outlet = [](const Vec3& x, double) { return x.x > 0.07; };
  for (std::size_t i = 0; i < st.position.size(); ++i)
    n_in_outlet += outlet(st.position[i], st.radius[i]) ? 1 : 0;
  REQUIRE(n_in_outlet > 0);
  const auto removed = s.remove_particles(outlet);
  CHECK(removed.size() == n_in_outlet);
  CHECK(s.particles.n_real + removed.size() == st.position.size());
  for (const auto& r : removed)
    CHECK(r.position.x > 0.07);
  const auto after = histories_by_ids(s);
  std::size_t n_kept = 0;
  for (const auto& [ids, h] : after) {
    REQUIRE(before.count(ids) == 1);
    CHECK(h == before.at(ids)); // carried bit for bit
    ++n_kept;
  }
  CHECK(n_kept > 20);
  // Every pair of two remaining particles that had a history still has it.
  std::map<std::int64_t, bool> gone;
  for (const auto& r : removed)
    gone[r.id] = true;
  for (const auto& [ids, h] : before)
    if (!gone.count(ids.first) && !gone.count(ids.second))
      CHECK(after.count(ids) == 1);
  s.run(500);                                             // and the bed runs on
  CHECK(s.next_id() == std::int64_t(st.position.size())); // ids are not reused
}

TEST_CASE("particles in and out: a run with inserts and removals is reproducible and resumes "
          "bit for bit") {
  // Every 400 steps a particle is dropped in at the top and those in a corner of the floor
  // (x < 30 mm, z < 12 mm) leave through an outlet: inserted = in the box + removed, exactly.
  const auto cycle = [](System& s, int c, std::size_t& n_removed) {
    s.insert_particles({dropped({0.02 + 0.006 * c, 0.05, 0.09}, {0, 0, -0.3}, 0)});
    n_removed +=
        s.remove_particles([](const Vec3& x, double) { return x.x < 0.03 && x.z < 0.012; }).size();
    s.run(400);
  };
  System a = settled_bed(2);
  const std::size_t n0 = a.particles.n_real;
  std::size_t removed_a = 0;
  for (int c = 0; c < 5; ++c)
    cycle(a, c, removed_a);
  const SystemState middle = a.export_state();
  const std::size_t removed_middle = removed_a;
  for (int c = 5; c < 10; ++c)
    cycle(a, c, removed_a);
  CHECK(removed_a > 0);
  CHECK(n0 + 10 == a.particles.n_real + removed_a);

  System b = settled_bed(2);
  std::size_t removed_b = 0;
  for (int c = 0; c < 10; ++c)
    cycle(b, c, removed_b);
  check_same_state(a, b);

  System c;
  const int g = add_gravel(c, 0.5, 0.5, 0.05);
  c.add_wall(MeshWall(box_walls(0.1), g, WallMotion{}, true, "box"));
  add_particles_of(c.particles, middle);
  c.settings.max_radius = 0.006;
  c.settings.skin = 0.0025;
  c.settings.time_step = 2e-5;
  c.setup();
  c.set_n_threads(2);
  c.resume_state(middle);
  CHECK(c.next_id() == middle.next_id);
  std::size_t removed_c = removed_middle;
  for (int k = 5; k < 10; ++k)
    cycle(c, k, removed_c);
  CHECK(removed_c == removed_a);
  check_same_particles(a, c);
}

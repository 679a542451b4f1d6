// Clumps inserted at random (dem/engine/filling.cc, insert_random_clumps): no member of one
// clump overlaps a member of another, every member lies in the region, each clump's volume is
// that of a PSD diameter, the orientations are uniform (the mean of a body axis over 400 clumps
// within 5 standard errors of zero), the same seed gives the same bed; the bed then settles in a
// box under gravity, its energy falling, every clump staying inside.
#include "dem/engine/clump_shape.h"
#include "dem/engine/filling.h"
#include "dem/engine/rank_states.h"
#include "dem/engine/snapshot.h"
#include "dem/engine/system.h"
#include "dem/scene/particle_shapes.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

using namespace wear::dem;
using wear::meshes::Vec3;

namespace {

constexpr double side = 0.06; // [m] the box

void fill(System& s, std::size_t n, std::uint64_t seed, std::size_t& inserted) {
  const int g = testing::add_gravel(s, 0.5, 0.5, 0);
  s.add_wall(MeshWall(testing::box_walls(side), g, {}, false, "box"));
  SizeDistribution psd;
  psd.diameters = {4e-3, 5e-3};
  psd.mass_fractions = {0.5, 0.5};
  const ClumpShape shape = clump_shape(named_clump_template("crushed stone 4", "test"));
  const double r_member = 1.0 * 5e-3 / shape.equivalent_diameter(); // the largest member
  inserted = insert_random_clumps(s, box_region({0, 0, 0}, {side, side, side}, r_member), psd,
                                  shape, n, 2650, g, seed);
}

} // namespace

TEST_CASE("clumps are inserted at random without overlap, with PSD volumes and uniform "
          "orientations",
          "[dem][clump]") {
  System s;
  std::size_t n = 0;
  fill(s, 400, 7, n);
  REQUIRE(n == 400);
  const auto& c = s.clumps();
  const auto& p = s.particles;
  REQUIRE(c.size() == 400);
  // Members of different bodies apart, every member inside the box.
  std::vector<int> body(p.n_real, -1);
  for (std::size_t b = 0; b < c.size(); ++b)
    for (auto k = c.member_begin[b]; k < c.member_begin[b + 1]; ++k)
      body[std::size_t(c.member_id[k])] = int(b); // ids are the slots before setup
  int n_overlaps = 0, n_outside = 0;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    for (int d = 0; d < 3; ++d)
      n_outside += p.position[i][d] - p.radius[i] < 0 || p.position[i][d] + p.radius[i] > side;
    for (std::size_t j = i + 1; j < p.n_real; ++j)
      if (body[i] != body[j]) {
        const double r = p.radius[i] + p.radius[j];
        n_overlaps += wear::meshes::norm2(p.position[i] - p.position[j]) < r * r;
      }
  }
  CHECK(n_overlaps == 0);
  CHECK(n_outside == 0);
  // Volumes of the PSD's diameters, in equal mass shares.
  const double pi = wear::pi;
  double mass_small = 0, mass_large = 0;
  Vec3 mean_axis;
  for (std::size_t b = 0; b < c.size(); ++b) {
    const double d = std::cbrt(6 * c.mass[b] / 2650 / pi);
    const bool small = std::abs(d - 4e-3) < 1e-6 * d, large = std::abs(d - 5e-3) < 1e-6 * d;
    CHECK((small || large));
    (small ? mass_small : mass_large) += c.mass[b];
    mean_axis += rotate(c.orientation[b], {1, 0, 0}) / double(c.size());
  }
  CHECK(std::abs(mass_small / (mass_small + mass_large) - 0.5) < 0.05);
  // Each component of a uniform unit vector has variance 1/3: standard error 1 / sqrt(3 n).
  CHECK(wear::meshes::norm(mean_axis) < 5 / std::sqrt(3.0 * 400));
  // The same seed, the same bed.
  System again;
  std::size_t n_again = 0;
  fill(again, 400, 7, n_again);
  CHECK(again.particles.position == s.particles.position);
}

TEST_CASE("a bed of clumps settles in a box", "[dem][clump]") {
  System s;
  std::size_t n = 0;
  fill(s, 150, 3, n);
  REQUIRE(n == 150);
  s.set_n_threads(2);
  s.setup();
  const double e0 = s.energy().total();
  s.run(std::uint64_t(0.2 / s.time_step()));
  const auto& c = s.clumps();
  for (std::size_t b = 0; b < c.size(); ++b) {
    CHECK(c.position[b].z > 0);
    CHECK(c.position[b].z < side);
  }
  double speed = 0;
  for (const auto& v : c.velocity)
    speed = std::max(speed, wear::meshes::norm(v));
  CAPTURE(speed, e0, s.energy().total());
  CHECK(s.energy().total() < e0);
  CHECK(speed < 1.0); // [m/s] the fall from 6 cm reaches 1.1 m/s
}

namespace {
// A system with the box of fill() and the particles and bodies of `st`, set up.
void rebuild_from(System& s, const SystemState& st) {
  const int g = testing::add_gravel(s, 0.5, 0.5, 0);
  s.add_wall(MeshWall(testing::box_walls(side), g, {}, false, "box"));
  add_state_particles(s.particles, st, false, 2650);
  s.add_state_clumps(st.clumps);
  s.set_n_threads(2);
  s.setup();
}

// Every particle and body of a and b carries the same bits.
void check_same_bits(const System& a, const System& b) {
  const auto &p = a.particles, &q = b.particles;
  REQUIRE(p.n_real == q.n_real);
  std::size_t n_differ = 0;
  for (std::size_t i = 0; i < p.n_real; ++i)
    n_differ += !(p.id[i] == q.id[i] && p.position[i] == q.position[i] &&
                  p.velocity[i] == q.velocity[i] && p.angular_velocity[i] == q.angular_velocity[i]);
  const auto &c = a.clumps(), &d = b.clumps();
  REQUIRE(c.size() == d.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    const auto &o = c.orientation[k], &r = d.orientation[k];
    n_differ += !(c.position[k] == d.position[k] && c.velocity[k] == d.velocity[k] &&
                  c.angular_momentum[k] == d.angular_momentum[k] && o.w == r.w && o.x == r.x &&
                  o.y == r.y && o.z == r.z &&
                  c.member_id[c.member_begin[k]] == d.member_id[d.member_begin[k]]);
  }
  CHECK(n_differ == 0);
}
} // namespace

TEST_CASE("a bed of clumps continues bit for bit from its exported state", "[dem][clump]") {
  // 300 bodies, 1,200 members: enough for the engine to sort the particles (and the bodies by
  // their members) every tenth rebuild. As a checkpoint does: resumed between two steps in a
  // new system, and exported and imported through a rebuild at a stage boundary.
  System a;
  std::size_t n = 0;
  fill(a, 300, 5, n);
  REQUIRE(n == 300);
  a.set_n_threads(2);
  a.setup();
  a.run(std::uint64_t(0.15 / a.time_step())); // landed: the pairs carry histories
  const SystemState middle = a.export_state();
  REQUIRE(middle.clumps.size() == 300);
  System b;
  rebuild_from(b, middle);
  b.resume_state(middle);
  a.run(1500);
  b.run(1500);
  CHECK(a.n_rebuilds() > middle.n_rebuilds);
  CHECK(a.n_pair_contacts() > 100);
  check_same_bits(a, b);

  const SystemState boundary = a.export_state();
  a.import_state(boundary);
  System c;
  rebuild_from(c, boundary);
  c.import_state(boundary);
  a.run(1000);
  c.run(1000);
  check_same_bits(a, c);

  // A state whose bodies the system lacks is refused by name.
  System d;
  const int g = testing::add_gravel(d, 0.5, 0.5, 0);
  d.add_wall(MeshWall(testing::box_walls(side), g, {}, false, "box"));
  add_state_particles(d.particles, boundary, false, 2650);
  d.setup();
  CHECK_THROWS_WITH(d.import_state(boundary), Catch::Contains("300 clumps"));
}

TEST_CASE("a snapshot of a bed of clumps names each member's body and its pose",
          "[dem][clump][vtu]") {
  System s;
  std::size_t n = 0;
  fill(s, 40, 9, n);
  s.set_n_threads(1);
  s.setup();
  s.run(200);
  write_particles_vtu(s.particles, "clump_snapshot.vtu", &s.clumps());
  // The "body" array: the text between its tag and the end of the array.
  std::ifstream in("clump_snapshot.vtu");
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  const auto array = [&text](const std::string& name) {
    const auto at = text.find("Name=\"" + name + "\"");
    REQUIRE(at != std::string::npos);
    const auto begin = text.find('>', at) + 1;
    std::istringstream values(text.substr(begin, text.find("</DataArray>", begin) - begin));
    return std::vector<double>{std::istream_iterator<double>(values), {}};
  };
  const auto body = array("body"), centre = array("body centre [m]");
  const auto& c = s.clumps();
  REQUIRE(body.size() == s.particles.n_real);
  REQUIRE(centre.size() == 3 * s.particles.n_real);
  std::size_t n_wrong = 0;
  for (std::size_t b = 0; b < c.size(); ++b)
    for (std::uint32_t k = c.member_begin[b]; k < c.member_begin[b + 1]; ++k) {
      const std::size_t i = c.member_slot[k];
      n_wrong += body[i] != double(b) || centre[3 * i] != c.position[b].x ||
                 centre[3 * i + 2] != c.position[b].z;
    }
  CHECK(n_wrong == 0);
  CHECK(std::count(body.begin(), body.end(), -1.0) == 0); // every particle is a member
}

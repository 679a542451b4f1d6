// A checkpoint gives back a bed of clumps bit for bit: the bodies' pose, motion, last force and
// mass properties, the member ranges, ids and body-frame offsets, beside the member particles
// (coupling/output/checkpoint.cc, /dem/clumps). Values with all 64 bits in use (not round
// numbers) so that a conversion through another type would show.
#include "coupling/output/checkpoint.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>

using namespace wear;

namespace {
bool same_bits(const dem::Vec3& a, const dem::Vec3& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
} // namespace

TEST_CASE("a checkpoint gives back a bed of clumps bit for bit", "[checkpoint][clump]") {
  coupling::Checkpoint c;
  c.parameters = "subsection DEM\nend\n";
  dem::SystemState& s = c.dem;
  const auto x = [](double k) { return dem::Vec3{std::sqrt(k), std::cbrt(k), std::log(k + 2)}; };
  for (int i = 0; i < 5; ++i) { // two bodies of 2 and 3 members
    s.position.push_back(x(i + 1));
    s.velocity.push_back(x(i + 7));
    s.angular_velocity.push_back(x(i + 13));
    s.force.push_back(x(i + 19));
    s.torque.push_back(x(i + 23));
    s.radius.push_back(1e-3 * std::sqrt(i + 2.0));
    s.mass.push_back(i < 2 ? 3.1e-5 : 4.7e-5);
    s.inertia.push_back(1e-11 * std::sqrt(i + 3.0));
    s.material.push_back(0);
    s.id.push_back(10 + i);
    s.reference_position.push_back(s.position.back());
    s.particle_cost.push_back(1);
  }
  s.wall_candidate_offset.assign(6, 0);
  s.n_threads = 1;
  dem::ClumpsState& k = s.clumps;
  for (int b = 0; b < 2; ++b) {
    k.position.push_back(x(31 + b));
    k.velocity.push_back(x(37 + b));
    k.orientation.push_back({std::sqrt(0.5), -std::sqrt(0.2), std::sqrt(0.2), std::sqrt(0.1)});
    k.angular_momentum.push_back(x(41 + b) * 1e-9);
    k.force.push_back(x(43 + b));
    k.torque.push_back(x(47 + b) * 1e-4);
    k.mass.push_back(b == 0 ? 3.1e-5 : 4.7e-5);
    k.moments.push_back(x(53 + b) * 1e-11);
  }
  k.member_begin = {0, 2, 5};
  k.member_id = {10, 11, 12, 13, 14};
  for (int m = 0; m < 5; ++m)
    k.member_offset.push_back(x(59 + m) * 1e-3);
  const std::string dir = "checkpoint-clumps-test";
  std::filesystem::create_directories(dir);
  coupling::write_checkpoint(dir + "/checkpoint.h5", c);
  const auto back = coupling::read_checkpoint(dir + "/checkpoint.h5").dem.clumps;
  REQUIRE(back.size() == 2);
  CHECK(back.member_begin == k.member_begin);
  CHECK(back.member_id == k.member_id);
  std::size_t n_differ = 0;
  for (std::size_t b = 0; b < 2; ++b) {
    const auto &q = back.orientation[b], &r = k.orientation[b];
    n_differ += !(same_bits(back.position[b], k.position[b]) &&
                  same_bits(back.velocity[b], k.velocity[b]) &&
                  same_bits(back.angular_momentum[b], k.angular_momentum[b]) &&
                  same_bits(back.force[b], k.force[b]) && same_bits(back.torque[b], k.torque[b]) &&
                  same_bits(back.moments[b], k.moments[b]) && back.mass[b] == k.mass[b] &&
                  q.w == r.w && q.x == r.x && q.y == r.y && q.z == r.z);
  }
  for (std::size_t m = 0; m < 5; ++m)
    n_differ += !same_bits(back.member_offset[m], k.member_offset[m]);
  CHECK(n_differ == 0);
  // A bed of spheres writes no clumps and reads none.
  c.dem.clumps = {};
  coupling::write_checkpoint(dir + "/checkpoint.h5", c);
  CHECK(coupling::read_checkpoint(dir + "/checkpoint.h5").dem.clumps.empty());
  std::filesystem::remove_all(dir);
}

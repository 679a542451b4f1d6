// The pair kernel (dem/engine/pair_kernel.cc) against the contact law one contact at a time:
// a block of pairs in every state the lanes meet (apart, touching with and without a
// tangential history, sliding, a history whose normal turned far since the last step, so
// that its rotation needs the exact scale and not the series the lanes take) gives each pair
// the forces, torques and updated history of hertz_mindlin<false> on the geometry written
// out here, to round-off.
#include "dem/engine/contact_law.h"
#include "dem/engine/pair_kernel.h"
#include "meshes/constants.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace wear::dem;
using wear::meshes::Vec3;

namespace {

double relative_difference(const Vec3& a, const Vec3& b) {
  return wear::meshes::norm(a - b) / std::max(wear::meshes::norm(b), 1e-30);
}

} // namespace

TEST_CASE("the pair kernel's lanes give every pair the contact law's forces and history, "
          "the exact rotation where the normal turned far",
          "[dem][contact]") {
  constexpr int n_pairs = 200;
  constexpr std::size_t n = 2 * n_pairs; // pair k is (2k, 2k + 1)
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto random_vector = [&](double scale) { return Vec3{u(rng), u(rng), u(rng)} * scale; };

  ContactParameters law;
  law.e_star = 2.7e7;
  law.g_star = 5.3e6;
  law.beta = -0.3;
  law.friction = 0.5;
  law.rolling_friction = 0.05;
  law.tangential_damping_ratio = std::sqrt(4 * law.g_star / law.e_star);
  const double dt = 3e-5;

  std::vector<PackedPosition> position(n);
  std::vector<PackedMotion> motion(n);
  std::vector<int> material(n, 0);
  std::vector<std::uint32_t> pair_i(n_pairs), pair_j(n_pairs);
  std::vector<Vec3> history(n_pairs);
  std::vector<std::uint8_t> touching(n_pairs);
  int n_far_turned = 0, n_apart = 0;
  for (int k = 0; k < n_pairs; ++k) {
    const std::uint32_t i = 2 * k, j = 2 * k + 1;
    pair_i[k] = i;
    pair_j[k] = j;
    const double ri = 0.003 * (1 + 0.3 * u(rng)), rj = 0.003 * (1 + 0.3 * u(rng));
    const Vec3 n_ij = wear::meshes::normalized(random_vector(1));
    // Every fifth pair apart, the others overlapping by up to 2 % of the radii.
    const double gap = k % 5 == 4 ? 1e-4 : -0.02 * (ri + rj) * (0.05 + 0.95 * std::abs(u(rng)));
    const Vec3 xj = random_vector(0.1);
    const Vec3 xi = xj + n_ij * (ri + rj + gap);
    position[i] = {xi.x, xi.y, xi.z, ri};
    position[j] = {xj.x, xj.y, xj.z, rj};
    for (std::uint32_t p : {i, j}) {
      const Vec3 v = random_vector(0.5), w = random_vector(50);
      const double r = position[p].r;
      motion[p] = {v.x, v.y, v.z, 2650 * 4.0 / 3.0 * wear::pi * r * r * r, w.x, w.y, w.z, 0};
    }
    // Histories: none, one in the tangent plane (the series is exact there), one whose normal
    // part is a quarter to nine tenths of its length (the normal turned far: the exact scale).
    const Vec3 t = wear::meshes::normalized(wear::meshes::cross(n_ij, random_vector(1)));
    const double length = 2e-5 * (1 + u(rng));
    switch (k % 3) {
    case 0:
      history[k] = {};
      break;
    case 1:
      history[k] = t * length;
      break;
    default: {
      const double s = 0.5 + 0.45 * u(rng);
      history[k] = (t * std::sqrt(1 - s * s) + n_ij * s) * length;
    }
    }
    touching[k] = 1;
    n_apart += gap > 0;
    n_far_turned += k % 3 == 2 && gap < 0;
  }
  REQUIRE(n_far_turned > 20);
  REQUIRE(n_apart > 20);

  // What the law gives each pair one at a time, the geometry written out (contact_law.h).
  std::vector<Vec3> f_expected(n_pairs), ti_expected(n_pairs), tj_expected(n_pairs),
      h_expected(n_pairs);
  for (int k = 0; k < n_pairs; ++k) {
    const PackedPosition &a = position[pair_i[k]], &b = position[pair_j[k]];
    const PackedMotion &ma = motion[pair_i[k]], &mb = motion[pair_j[k]];
    const Vec3 d{a.x - b.x, a.y - b.y, a.z - b.z};
    const double dist = wear::meshes::norm(d);
    if (dist >= a.r + b.r) {
      h_expected[k] = {}; // a pair that stops touching loses its history
      continue;
    }
    ContactGeometry g;
    g.normal = d / dist;
    g.overlap = a.r + b.r - dist;
    g.r_eff = a.r * b.r / (a.r + b.r);
    g.m_eff = ma.mass * mb.mass / (ma.mass + mb.mass);
    g.arm_i = a.r - 0.5 * g.overlap;
    g.arm_j = b.r - 0.5 * g.overlap;
    g.lever_i = a.r;
    g.lever_j = b.r;
    const Vec3 wi{ma.wx, ma.wy, ma.wz}, wj{mb.wx, mb.wy, mb.wz};
    g.v_contact = Vec3{ma.vx - mb.vx, ma.vy - mb.vy, ma.vz - mb.vz} -
                  wear::meshes::cross(wi * a.r + wj * b.r, g.normal);
    g.w_relative = wi - wj;
    Vec3 h = history[k];
    const ContactResult r = hertz_mindlin<false>(law, g, dt, h);
    f_expected[k] = r.force;
    ti_expected[k] = r.torque_i;
    tj_expected[k] = r.torque_j;
    h_expected[k] = h;
  }

  ForeignForces foreign;
  PairKernelData data{position.data(),
                      motion.data(),
                      material.data(),
                      pair_i.data(),
                      pair_j.data(),
                      &law,
                      1,
                      &law,
                      history.data(),
                      touching.data(),
                      nullptr,
                      n,
                      n,
                      0,
                      std::uint32_t(n),
                      &foreign,
                      1.0,
                      0.0,
                      dt};
  std::vector<Vec3> force(n), torque(n);
  PairBlock block;
  int n_contacts = 0;
  for (int k0 = 0; k0 < n_pairs; k0 += pair_block_size)
    n_contacts += pair_block_forces(data, std::size_t(k0), std::min(pair_block_size, n_pairs - k0),
                                    block, force.data(), torque.data());
  CHECK(n_contacts == n_pairs - n_apart);
  CHECK(foreign.n == 0);

  // Round-off only: the lanes may fuse multiplies and adds; a series in place of the exact
  // rotation is off by up to several per cent on the far-turned histories.
  const double tolerance = 1e-11;
  double worst = 0;
  for (int k = 0; k < n_pairs; ++k) {
    INFO("pair " << k);
    const std::uint32_t i = pair_i[k], j = pair_j[k];
    if (k % 5 == 4) {
      CHECK(wear::meshes::norm(force[i]) == 0);
      CHECK(wear::meshes::norm(history[k]) == 0);
      CHECK(touching[k] == 0);
      continue;
    }
    const double e = std::max({relative_difference(force[i], f_expected[k]),
                               relative_difference(force[j], -f_expected[k]),
                               relative_difference(torque[i], ti_expected[k]),
                               relative_difference(torque[j], tj_expected[k]),
                               relative_difference(history[k], h_expected[k])});
    worst = std::max(worst, e);
    CHECK(e < tolerance);
  }
  INFO("largest relative difference " << worst);
  CHECK(worst < tolerance);
}

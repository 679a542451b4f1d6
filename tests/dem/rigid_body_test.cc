// Free rotation of an asymmetric rigid body (dem/engine/rigid_body.cc) over 1e5 steps in zero
// gravity: the kinetic energy is kept to 1e-8 relative and the angular momentum (stored, hence
// exact) gives back the body's spin; a spin about the intermediate axis flips (the tennis-racket
// instability, Dzhanibekov effect), spins about the smallest and the largest axis stay.
#include "dem/engine/rigid_body.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace wear::dem;
using wear::meshes::Vec3;

namespace {

const Vec3 moments{1e-9, 2e-9, 3e-9}; // [kg m^2] a gravel grain's, in ratio 1 : 2 : 3

struct Spin {
  double max_energy_error = 0; ///< [-] relative
  int n_flips = 0;             ///< sign changes of the body-frame momentum along `axis`
  double min_share = 1;        ///< [-] smallest |l_axis| / |L| seen
};

/// 1e5 steps of dt from the spin omega (body frame, body aligned with space at start).
Spin spin(const Vec3& omega_body, double dt, int axis) {
  Quaternion q = rotation_about(wear::meshes::normalized(Vec3{1, 1, 0}), 0.3);
  const Vec3 L =
      rotate(q, {moments.x * omega_body.x, moments.y * omega_body.y, moments.z * omega_body.z});
  const double e0 = rotational_energy(q, moments, L);
  Spin s;
  double last = rotate_back(q, L)[axis];
  for (int n = 0; n < 100000; ++n) {
    rotate_freely(q, L, moments, dt);
    s.max_energy_error =
        std::max(s.max_energy_error, std::abs(rotational_energy(q, moments, L) - e0) / e0);
    const double l = rotate_back(q, L)[axis];
    if ((l > 0) != (last > 0))
      ++s.n_flips;
    last = l;
    s.min_share = std::min(s.min_share, std::abs(l) / wear::meshes::norm(L));
  }
  return s;
}

} // namespace

TEST_CASE("a torque-free asymmetric body keeps its energy to 1e-8 over 1e5 steps; about the "
          "intermediate axis it flips, about the others it stays",
          "[dem][clump][rotation]") {
  // 100 rad/s, a grain's spin in the tester's bed, at the bed's time step: |omega| dt = 1e-4,
  // 10 rad over the run (the energy error is O((|omega| dt)^2) and does not drift).
  const double dt = 1e-6;
  const Spin about_intermediate = spin({0.1, 100, 0.1}, 10 * dt, 1);
  const Spin about_smallest = spin({100, 0.1, 0.1}, dt, 0);
  const Spin about_largest = spin({0.1, 0.1, 100}, dt, 2);
  CAPTURE(about_intermediate.max_energy_error, about_smallest.max_energy_error,
          about_largest.max_energy_error);
  CHECK(about_smallest.max_energy_error < 1e-8);
  CHECK(about_largest.max_energy_error < 1e-8);
  // Over 100 rad (|omega| dt = 1e-3) the intermediate spin flips back and forth.
  CHECK(about_intermediate.n_flips >= 2);
  CHECK(about_intermediate.max_energy_error < 1e-6);
  CHECK(about_smallest.n_flips == 0);
  CHECK(about_largest.n_flips == 0);
  CHECK(about_smallest.min_share > 0.99);
  CHECK(about_largest.min_share > 0.99);
}

TEST_CASE("the body's angular velocity gives back its angular momentum after any rotation",
          "[dem][clump][rotation]") {
  Quaternion q = rotation_about(wear::meshes::normalized(Vec3{0.2, -1, 0.5}), 1.1);
  const Vec3 L{3e-7, -1e-7, 2e-7};
  for (int n = 0; n < 1000; ++n)
    rotate_freely(q, L, moments, 1e-4);
  const Vec3 w = angular_velocity(q, moments, L);
  const Vec3 wb = rotate_back(q, w);
  const Vec3 back = rotate(q, {moments.x * wb.x, moments.y * wb.y, moments.z * wb.z});
  CHECK(wear::meshes::norm(back - L) < 1e-12 * wear::meshes::norm(L));
  CHECK(std::abs(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z - 1) < 1e-14);
}

TEST_CASE("bodies rotated side by side turn as each one alone, bit for bit",
          "[dem][clump][rotation]") {
  // Seven bodies: a block of four and three alone in the engine's pass; each must give the
  // single call's orientation exactly, so that a body's path does not depend on its slot.
  // |omega| is 80 to 250 rad/s: at dt = 1e-3 the half-turns (0.02 to 0.06 rad) take the
  // library's cos and sin, at dt = 1e-5 (a bed's |omega| dt) the series.
  for (const double dt : {1e-3, 1e-5}) {
    CAPTURE(dt);
    std::vector<Quaternion> q, alone;
    std::vector<Vec3> L, I;
    for (int b = 0; b < 7; ++b) {
      q.push_back(rotation_about(wear::meshes::normalized(Vec3{0.3 * b - 1, 1, 0.1 * b}), 0.2 * b));
      L.push_back(Vec3{1e-7 * (b - 3), 2e-7, -3e-8 * b});
      I.push_back(moments * (1 + 0.1 * b));
    }
    alone = q;
    for (int n = 0; n < 100; ++n) {
      rotate_freely(q.size(), q.data(), L.data(), I.data(), dt);
      for (std::size_t b = 0; b < alone.size(); ++b)
        rotate_freely(alone[b], L[b], I[b], dt);
    }
    for (std::size_t b = 0; b < q.size(); ++b) {
      CAPTURE(b);
      CHECK(q[b].w == alone[b].w);
      CHECK(q[b].x == alone[b].x);
      CHECK(q[b].y == alone[b].y);
      CHECK(q[b].z == alone[b].z);
    }
    // The bodies did turn (by 0.08 to 25 rad over the 100 steps).
    CHECK(std::abs(q[6].w - rotation_about(wear::meshes::normalized(Vec3{0.8, 1, 0.6}), 1.2).w) >
          1e-4);
  }
}

// The threads' split of the force evaluation: each thread adds the forces on the particles it
// owns and keeps those on another thread's particles aside (dem/engine/pair_kernel.h,
// ForeignForces). A force lost or counted twice at a boundary between the threads' ranges or
// across the periodic cut would show as a particle whose force depends on the thread count.
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <omp.h>

#include <vector>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::Vec3;

namespace {
/// Forces and torques after setup() on `threads` threads of a dense, overlapping lattice of
/// 8 mm spheres in a 30-degree periodic sector (no walls, no gravity), indexed by stable id.
struct Loads {
  std::vector<Vec3> force, torque;
  std::size_t n_contacts = 0, n_ghosts = 0;
};

Loads loads_on(int threads) {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.1);
  s.settings.gravity = {0, 0, 0};
  s.settings.periodic = {true, 30 * pi / 180};
  s.settings.domain = {{-0.6, -0.6, -0.1}, {0.6, 0.6, 0.2}};
  // Spacing 0.97 d: every lattice neighbour overlaps by 3 % of a diameter (jitter 0.05 mm).
  const FillRegion region{{-0.5, -0.5, 0}, {0.5, 0.5, 0.06}, [](const Vec3& x) {
                            const double r = std::hypot(x.x, x.y), th = std::atan2(x.y, x.x);
                            return r > 0.3 && r < 0.48 && th > 0.0 && th < 30 * pi / 180 &&
                                   x.z > 0 && x.z < 0.06;
                          }};
  insert_lattice(s.particles, region, 0.97 * 8e-3, 8e-3, 2650, g, 5e-5, 7);
  // Velocities and spins that differ from particle to particle, so that the contacts carry
  // damping, tangential and rolling-friction forces and torques too.
  for (std::size_t i = 0; i < s.particles.n_real; ++i) {
    const double a = 0.37 * double(i);
    s.particles.velocity[i] = Vec3{std::sin(a), std::cos(1.3 * a), std::sin(0.7 * a)} * 0.1;
    s.particles.angular_velocity[i] = Vec3{std::cos(a), std::sin(1.9 * a), std::cos(0.3 * a)} * 20;
  }
  omp_set_num_threads(threads);
  s.setup();
  omp_set_num_threads(omp_get_num_procs());
  Loads l;
  const auto& p = s.particles;
  l.force.resize(p.n_real);
  l.torque.resize(p.n_real);
  for (std::size_t i = 0; i < p.n_real; ++i) {
    l.force[std::size_t(p.id[i])] = p.force[i];
    l.torque[std::size_t(p.id[i])] = p.torque[i];
  }
  l.n_contacts = s.n_pair_contacts();
  l.n_ghosts = s.n_ghosts();
  return l;
}
} // namespace

TEST_CASE("forces do not depend on how the threads split the particles", "[dem][threads]") {
  const Loads one = loads_on(1);
  REQUIRE(one.force.size() > 1000); // enough to be sorted spatially at the first rebuild
  REQUIRE(std::isfinite(one.force[0].x));
  CHECK(one.n_contacts > 2 * one.force.size());
  CHECK(one.n_ghosts > 50);
  double f_scale = 0, t_scale = 0;
  for (std::size_t i = 0; i < one.force.size(); ++i) {
    f_scale = std::max(f_scale, norm(one.force[i]));
    t_scale = std::max(t_scale, norm(one.torque[i]));
  }
  CHECK(t_scale > 1e-3 * f_scale * 4e-3); // torques of the order of a force times a radius
  for (int threads : {2, 3, 4}) {
    const Loads many = loads_on(threads);
    REQUIRE(many.force.size() == one.force.size());
    // Only the order of the sums differs: agreement to round-off of the largest force.
    double f_diff = 0, t_diff = 0;
    for (std::size_t i = 0; i < one.force.size(); ++i) {
      f_diff = std::max(f_diff, norm(many.force[i] - one.force[i]));
      t_diff = std::max(t_diff, norm(many.torque[i] - one.torque[i]));
    }
    INFO(threads << " threads: largest force difference " << f_diff << " N of " << f_scale
                 << " N, torque " << t_diff << " N m of " << t_scale << " N m");
    CHECK(f_diff <= 1e-12 * f_scale);
    CHECK(t_diff <= 1e-12 * t_scale);
  }
}

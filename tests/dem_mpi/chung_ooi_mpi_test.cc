// Chung & Ooi (2011) binary impacts with the contact across the cut between rank 0 and rank 1
// (slabs along x, the contact point at x = 0): sphere 0 is rank 0's, sphere 1 rank 1's, and
// rank 1 computes the pair with a ghost of sphere 0. Each impact is compared with the same
// impact in one plain System (every rank runs it) and with the published values the serial
// suite uses (tests/dem/chung_ooi_test.cc): Test 1 (Hertz, 0.5 %), Test 7 (symmetric spins,
// no tangential velocity to 1e-12), and an oblique impact with friction and spin whose
// tangential history lives on rank 1.
#include "tests/dem_mpi/dem_mpi_fixtures.h"

using namespace wear::dem;
using namespace wear::dem::testing;
namespace meshes = wear::meshes;

namespace {

struct Impact {
  double contact_time = 0, max_overlap = 0, max_force = 0; ///< [s], [m], [N]
  BedState end;                                            ///< after the impact
};

struct Sphere {
  Vec3 v, w; ///< [m/s], [rad/s]
};

/// Two equal spheres of radius r along x touching at x = 0 five steps after the start; no
/// gravity, dt = 1 % of the Rayleigh time, exact restitution mapping (as the serial suite).
Impact impact(bool ranked, double youngs, double poisson, double density, double r, Sphere a,
              Sphere b, double restitution, double friction) {
  System s;
  s.settings.gravity = {};
  s.settings.time_step_fraction = 0.01;
  s.settings.max_speed = 1000;
  s.materials.set_restitution_mapping(RestitutionMapping::exact);
  const int m = s.materials.add({"sphere", youngs, poisson, density});
  s.materials.set_pair(m, m, {restitution, friction, 0.0});
  s.particles.add({-r, 0, 0}, a.v, r, density, m);
  s.particles.add({r, 0, 0}, b.v, r, density, m);
  const double dt = 0.01 * s.rayleigh_time();
  s.particles.position[0] -= a.v * (5 * dt);
  s.particles.position[1] -= b.v * (5 * dt);
  s.particles.angular_velocity[0] = a.w;
  s.particles.angular_velocity[1] = b.w;
  // The reach is 2.5 r (skin r / 2): the middle of three slabs is 3 r wide.
  const SlabDecomposition slabs =
      x_slabs({{-100 * r, 100 * r}, {-100 * r, 0, 100 * r}, {-100 * r, 0, 3 * r, 100 * r}});
  if (ranked)
    s.set_rank_link(&world(), &slabs);
  s.setup();
  Impact res;
  double t_start = -1, t_end = -1, previous = -1, previous_t = 0;
  for (int k = 0; k < 200000 && t_end < 0; ++k) {
    s.step();
    const BedState st = ranked ? gather(s, 2, world()) : by_id(s, 2);
    const Vec3 d = st.x[1] - st.x[0];
    const double overlap = 2 * r - meshes::norm(d), t = s.time();
    const double force = -meshes::dot(st.f[0], d / meshes::norm(d));
    if (overlap > 0 && previous <= 0 && t_start < 0)
      t_start = previous_t + (t - previous_t) * (-previous) / (overlap - previous);
    if (overlap <= 0 && previous > 0)
      t_end = previous_t + (t - previous_t) * previous / (previous - overlap);
    if (overlap > 0) {
      res.max_overlap = std::max(res.max_overlap, overlap);
      res.max_force = std::max(res.max_force, force);
    }
    previous = overlap;
    previous_t = t;
  }
  res.contact_time = t_end - t_start;
  res.end = ranked ? gather(s, 2, world()) : by_id(s, 2);
  return res;
}

/// The ranked impact against the plain one: scalars and the final state to 1e-12 relative.
void check_same_impact(const Impact& ranked, const Impact& plain) {
  CHECK(ranked.end.held[0] == 1);
  CHECK(ranked.end.held[1] == 1);
  CHECK(ranked.contact_time == Approx(plain.contact_time).epsilon(1e-12));
  CHECK(ranked.max_overlap == Approx(plain.max_overlap).epsilon(1e-12));
  CHECK(ranked.max_force == Approx(plain.max_force).epsilon(1e-12));
  const double v = std::max(max_norm(plain.end.v), 1e-300),
               w = std::max(max_norm(plain.end.w), 1.0);
  CHECK(max_difference(ranked.end.v, plain.end.v) <= 1e-12 * v);
  CHECK(max_difference(ranked.end.w, plain.end.w) <= 1e-12 * w);
}

} // namespace

TEST_CASE("Chung & Ooi Test 1 across a slab cut", "[dem_mpi][chung-ooi]") {
  // Glass, r = 10 mm, 10 m/s each: Hertz at the relative speed 20 m/s.
  const double E = 4.8e10, nu = 0.2, rho = 2800, r = 0.010, v = 10;
  const Impact ranked = impact(true, E, nu, rho, r, {{v, 0, 0}, {}}, {{-v, 0, 0}, {}}, 1.0, 0.0);
  const Impact plain = impact(false, E, nu, rho, r, {{v, 0, 0}, {}}, {{-v, 0, 0}, {}}, 1.0, 0.0);
  check_same_impact(ranked, plain);
  const double e_star = E / (2 * (1 - nu * nu)), r_star = r / 2;
  const double m_star = rho * 4.0 / 3.0 * pi * r * r * r / 2, u = 2 * v;
  const double d = std::pow(15 * m_star * u * u / (16 * e_star * std::sqrt(r_star)), 0.4);
  CHECK(ranked.contact_time == Approx(2.9432 * d / u).epsilon(0.005));
  CHECK(ranked.max_overlap == Approx(d).epsilon(0.005));
  CHECK(ranked.max_force ==
        Approx(4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(d, 1.5)).epsilon(0.005));
  CHECK(ranked.end.v[0].x == Approx(-v).epsilon(1e-6));
}

TEST_CASE("Chung & Ooi Test 7 (symmetric spins) across a slab cut", "[dem_mpi][chung-ooi]") {
  const double E = 1.2e11, nu = 0.35, rho = 8900, w = 22.86; // copper
  const Impact ranked =
      impact(true, E, nu, rho, 0.1, {{0.2, 0, 0}, {0, w, 0}}, {{-0.2, 0, 0}, {0, -w, 0}}, 0.5, 0.4);
  const Impact plain = impact(false, E, nu, rho, 0.1, {{0.2, 0, 0}, {0, w, 0}},
                              {{-0.2, 0, 0}, {0, -w, 0}}, 0.5, 0.4);
  check_same_impact(ranked, plain);
  const BedState& e = ranked.end;
  CHECK(std::hypot(e.v[0].y, e.v[0].z) + std::hypot(e.v[1].y, e.v[1].z) <= 1e-12);
  CHECK(meshes::norm(e.w[0] - Vec3{0, w, 0}) + meshes::norm(e.w[1] - Vec3{0, -w, 0}) <= 1e-12);
}

TEST_CASE("an oblique impact with friction and spin across a slab cut", "[dem_mpi][chung-ooi]") {
  // Al alloy, sphere 0 spinning and moving obliquely onto sphere 1 at rest: the contact
  // sticks, then slides, through the tangential history rank 1 keeps.
  const double E = 7.0e10, nu = 0.33, rho = 2700;
  const Impact ranked =
      impact(true, E, nu, rho, 0.1, {{0.2, 0.05, 0}, {0, 5, 1}}, {{}, {}}, 0.5, 0.4);
  const Impact plain =
      impact(false, E, nu, rho, 0.1, {{0.2, 0.05, 0}, {0, 5, 1}}, {{}, {}}, 0.5, 0.4);
  check_same_impact(ranked, plain);
  // The friction turned sphere 1's spin and gave it a tangential velocity.
  CHECK(meshes::norm(ranked.end.w[1]) > 0.1);
  CHECK(std::abs(ranked.end.v[1].z) > 1e-3);
}

// Chung & Ooi (2011) single-impact benchmark through the full engine.
//
// Each scenario builds a System with one or two spheres (no gravity, dt = 1 % of the
// Rayleigh time) and, for sphere-plane impacts, a flat 4 x 4-quad triangle mesh whose spot
// under the sphere is a face interior, a shared edge or a shared vertex. The sphere starts
// five steps' travel above the contact spot so the contact begins exactly there. Contact
// time comes from the overlap sign change, interpolated linearly between steps. Expected
// values: Hertz theory (Tests 1-2), the input restitution (Test 3) and the rigid-body
// sliding relations of the paper (Tests 4-8).
#include "dem/validation/chung_ooi.h"

#include "meshes/constants.h"
#include "dem/engine/system.h"
#include "meshes/structured_grid.h"

#include <cmath>

namespace wear::dem::validation {

namespace {
using meshes::cross;
using meshes::dot;
using meshes::norm;

meshes::SurfaceMesh plane_mesh(double half) {
  return meshes::structured_grid(
      4, 4,
      [half](double u, double v) {
        return Vec3{-half + 2 * half * u, -half + 2 * half * v, 0};
      },
      false, meshes::label::wall, meshes::Diagonals::uniform);
}

struct Tracker {
  double t_start = -1, t_end = -1, max_overlap = 0, max_force = 0, prev_overlap = -1, prev_t = 0;
  void sample(double t, double overlap, double force) {
    if (overlap > 0 && prev_overlap <= 0 && t_start < 0)
      t_start = prev_t + (t - prev_t) * (-prev_overlap) / (overlap - prev_overlap);
    if (overlap <= 0 && prev_overlap > 0 && t_end < 0)
      t_end = prev_t + (t - prev_t) * prev_overlap / (prev_overlap - overlap);
    if (overlap > 0) {
      max_overlap = std::max(max_overlap, overlap);
      max_force = std::max(max_force, force);
    }
    prev_overlap = overlap;
    prev_t = t;
  }
  bool done() const { return t_end >= 0; }
};

// No gravity, dt = 1 % of the Rayleigh time, a speed limit above Test 5's 70 m/s.
void configure(System& s, RestitutionMapping mapping) {
  s.settings.gravity = {};
  s.settings.time_step_fraction = 0.01;
  s.settings.max_speed = 1000;
  s.materials.set_restitution_mapping(mapping);
}

void set_all_pairs(System& s, int a, int b, const PairProperties& pp) {
  s.materials.set_pair(a, a, pp);
  s.materials.set_pair(a, b, pp);
  s.materials.set_pair(b, b, pp);
}

ImpactResult result(const System& s, const Tracker& tr) {
  ImpactResult res;
  res.contact_time = tr.t_end - tr.t_start;
  res.max_overlap = tr.max_overlap;
  res.max_force = tr.max_force;
  res.v_after = s.particles.velocity[0];
  res.w_after = s.particles.angular_velocity[0];
  return res;
}

int add_material(System& s, const ImpactMaterial& m, const std::string& name) {
  return s.materials.add({name, m.youngs_modulus, m.poisson_ratio, m.density});
}
} // namespace

ImpactResult sphere_on_plane(const ImpactMaterial& m, double r, const Vec3& v, const Vec3& w,
                             double restitution, double friction, bool rigid_plane, PlaneSpot spot,
                             RestitutionMapping mapping) {
  System s;
  configure(s, mapping);
  const int mp = add_material(s, m, "sphere");
  const int mw = rigid_plane ? s.materials.add({"rigid", INFINITY, m.poisson_ratio, m.density})
                             : add_material(s, m, "plane");
  set_all_pairs(s, mp, mw, {restitution, friction, 0.0});
  const double half = 4 * r;
  s.add_wall(MeshWall(plane_mesh(half), mw, {}, false, "plane"));
  Vec3 target{-half / 4 - half / 8, half / 16, 0}; // inside a triangle, off every edge
  if (spot == PlaneSpot::edge)
    target = {half / 4, 0, 0}; // midpoint of an interior edge shared by two triangles
  if (spot == PlaneSpot::vertex)
    target = {0, 0, 0}; // interior vertex shared by six triangles
  // Start five steps' travel above the spot, along the incoming direction.
  s.particles.add({0, 0, r}, v, r, m.density, mp);
  const double dt = 0.01 * s.rayleigh_time();
  const double lead = 5 * dt;
  s.particles.position[0] = target + Vec3{0, 0, r} - v * lead;
  s.particles.angular_velocity[0] = w;
  s.setup();
  Tracker tr;
  for (int k = 0; k < 2000000 && !tr.done(); ++k) {
    s.step();
    tr.sample(s.time(), r - s.particles.position[0].z, s.particles.force[0].z);
  }
  ImpactResult res = result(s, tr);
  res.radius = r;
  return res;
}

ImpactResult sphere_on_sphere(const ImpactMaterial& m1, double r1, const Vec3& v1, const Vec3& w1,
                              const ImpactMaterial& m2, double r2, const Vec3& v2, const Vec3& w2,
                              double restitution, double friction, RestitutionMapping mapping) {
  System s;
  configure(s, mapping);
  const int a = add_material(s, m1, "sphere 1"), b = add_material(s, m2, "sphere 2");
  set_all_pairs(s, a, b, {restitution, friction, 0.0});
  s.particles.add({-r1, 0, 0}, v1, r1, m1.density, a);
  s.particles.add({r2, 0, 0}, v2, r2, m2.density, b);
  const double dt = 0.01 * s.rayleigh_time();
  s.particles.position[0] -= v1 * (5 * dt);
  s.particles.position[1] -= v2 * (5 * dt);
  s.particles.angular_velocity[0] = w1;
  s.particles.angular_velocity[1] = w2;
  s.setup();
  Tracker tr;
  for (int k = 0; k < 2000000 && !tr.done(); ++k) {
    s.step();
    const Vec3 d = s.particles.position[1] - s.particles.position[0];
    tr.sample(s.time(), r1 + r2 - norm(d), -dot(s.particles.force[0], d / norm(d)));
  }
  ImpactResult res = result(s, tr);
  res.v2_after = s.particles.velocity[1];
  res.w2_after = s.particles.angular_velocity[1];
  res.radius = r1;
  return res;
}

HertzPrediction hertz_prediction(double e_star, double r_star, double m_star, double v) {
  const double d = std::pow(15 * m_star * v * v / (16 * e_star * std::sqrt(r_star)), 0.4);
  return {2.9432 * d / v, d, 4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(d, 1.5)};
}

bool Row::passed() const {
  const double err =
      absolute ? std::abs(computed - expected) : std::abs(computed - expected) / std::abs(expected);
  return err <= tolerance;
}

namespace {
double mass(const ImpactMaterial& m, double r) {
  return m.density * 4.0 / 3.0 * pi * r * r * r;
}
double e_star_pair(const ImpactMaterial& a, const ImpactMaterial& b) {
  return 1 / ((1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
              (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
}
std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", x);
  return b;
}
// Tangential velocity of the contact point below a sphere on the plane z = 0.
Vec3 contact_point_velocity(const Vec3& v, const Vec3& w, double r) {
  const Vec3 u = v + cross(w, Vec3{0, 0, -r});
  return {u.x, u.y, 0};
}
} // namespace

std::vector<Row> run_suite() {
  std::vector<Row> rows;
  const auto exact = RestitutionMapping::exact;
  // Tests 1 and 2: Hertz (e = 1, no friction).
  const ImpactMaterial glass{4.8e10, 0.20, 2800}, limestone{2.0e10, 0.25, 2500};
  for (auto [name, m] : {std::pair{"glass", glass}, std::pair{"limestone", limestone}}) {
    const double r = 0.010, v = 10;
    const auto res = sphere_on_sphere(m, r, {v, 0, 0}, {}, m, r, {-v, 0, 0}, {}, 1.0, 0.0, exact);
    const auto h = hertz_prediction(e_star_pair(m, m), r / 2, mass(m, r) / 2, 2 * v);
    rows.push_back({"1", name, "contact time [s]", h.contact_time, res.contact_time, 0.005});
    rows.push_back({"1", name, "max overlap [m]", h.max_overlap, res.max_overlap, 0.005});
    rows.push_back({"1", name, "max force [N]", h.max_force, res.max_force, 0.005});
  }
  const ImpactMaterial al{7.0e10, 0.30, 2699}, mg{4.0e10, 0.35, 1800};
  for (auto [name, m] : {std::pair{"Al alloy", al}, std::pair{"Mg alloy", mg}})
    for (auto spot : {PlaneSpot::face, PlaneSpot::edge, PlaneSpot::vertex}) {
      const double r = 0.10, v = 0.2;
      const auto res = sphere_on_plane(m, r, {0, 0, -v}, {}, 1.0, 0.0, true, spot, exact);
      const auto h = hertz_prediction(m.youngs_modulus / (1 - m.poisson_ratio * m.poisson_ratio), r,
                                      mass(m, r), v);
      const std::string ex = std::string(name) + (spot == PlaneSpot::face   ? ", mesh face"
                                                  : spot == PlaneSpot::edge ? ", mesh edge"
                                                                            : ", mesh vertex");
      rows.push_back({"2", ex, "contact time [s]", h.contact_time, res.contact_time, 0.005});
      rows.push_back({"2", ex, "max overlap [m]", h.max_overlap, res.max_overlap, 0.005});
      rows.push_back({"2", ex, "max force [N]", h.max_force, res.max_force, 0.005});
    }
  // Test 3: restitution, exact mapping of e to the damping ratio.
  const ImpactMaterial alox{3.8e11, 0.23, 4000}, iron{1.0e11, 0.25, 7000};
  for (auto [name, m] : {std::pair{"Al oxide", alox}, std::pair{"cast iron", iron}})
    for (double e : {0.2, 0.4, 0.6, 0.8, 1.0}) {
      const auto res =
          sphere_on_plane(m, 0.0025, {0, 0, -3.9}, {}, e, 0.0, false, PlaneSpot::face, exact);
      rows.push_back({"3", std::string(name) + ", e = " + fmt(e), "rebound/impact speed", e,
                      res.v_after.z / 3.9, 0.01});
    }
  // Test 4: oblique impact, sliding regime (theta >= 40 deg).
  const ImpactMaterial al33{7.0e10, 0.33, 2700};
  for (auto [name, m] : {std::pair{"Al oxide", alox}, std::pair{"Al alloy", al33}})
    for (double th_deg : {40.0, 50.0, 60.0, 70.0, 80.0}) {
      const double mu = 0.092, en = 0.98, V = 3.9, r = 0.0025, th = th_deg * pi / 180;
      const auto res = sphere_on_plane(m, r, {V * std::sin(th), 0, -V * std::cos(th)}, {}, en, mu,
                                       false, PlaneSpot::face, exact);
      const std::string ex = std::string(name) + ", " + fmt(th_deg) + " deg";
      rows.push_back({"4", ex, "tangential restitution", 1 - mu * (1 + en) / std::tan(th),
                      res.v_after.x / (V * std::sin(th)), 0.02});
      rows.push_back({"4", ex, "|rebound spin| [rad/s]", 2.5 * mu * (1 + en) * V * std::cos(th) / r,
                      std::abs(res.w_after.y), 0.02});
      const Vec3 cp = contact_point_velocity(res.v_after, res.w_after, r);
      rows.push_back({"4", ex, "recoil angle [deg]",
                      std::atan(std::tan(th) / en - 3.5 * mu * (1 + 1 / en)) * 180 / pi,
                      std::atan2(cp.x, res.v_after.z) * 180 / pi, 0.02});
    }
  // Test 5: Vn = 5 m/s, e = 1, tangential speeds in the sliding regime.
  const ImpactMaterial steel{2.08e11, 0.30, 7850}, pe{1.0e9, 0.40, 1400};
  for (auto [name, m] : {std::pair{"steel", steel}, std::pair{"polyethylene", pe}})
    for (double vt : {15.0, 30.0, 50.0, 70.0}) {
      const double mu = 0.3, vn = 5, r = 1e-5;
      const auto res =
          sphere_on_plane(m, r, {vt, 0, -vn}, {}, 1.0, mu, false, PlaneSpot::face, exact);
      const Vec3 cp = contact_point_velocity(res.v_after, res.w_after, r);
      const std::string ex = std::string(name) + ", Vt = " + fmt(vt) + " m/s";
      rows.push_back(
          {"5", ex, "V'st / (mu V'cn)", vt / (mu * vn) - 7, cp.x / (mu * res.v_after.z), 0.02});
      rows.push_back(
          {"5", ex, "|r w' / (mu Vn)|", 5.0, std::abs(r * res.w_after.y / (mu * vn)), 0.02});
    }
  // Test 6: pure spin about y with normal approach; sliding for 3.5 mu (1 + e) Vn / Vs <= 1.
  const ImpactMaterial nylon{2.5e9, 0.40, 1000};
  for (auto [name, m] : {std::pair{"Al alloy", al33}, std::pair{"nylon", nylon}})
    for (double w : {5.0, 10.0, 15.0, 22.86}) {
      const double mu = 0.4, e = 0.5, vn = 0.2, r = 0.1, vs = r * w;
      const auto res =
          sphere_on_plane(m, r, {0, 0, -vn}, {0, w, 0}, e, mu, false, PlaneSpot::face, exact);
      const Vec3 cp = contact_point_velocity(res.v_after, res.w_after, r); // along -x initially
      const std::string ex = std::string(name) + ", w = " + fmt(w) + " rad/s";
      // The paper counts V'st against the incoming slip direction: beta_t < 0 means the slip
      // kept its direction.
      rows.push_back({"6", ex, "V'st / Vst (paper's signs)", -1 + 3.5 * mu * (1 + e) * vn / vs,
                      cp.x / vs, 0.02});
      rows.push_back({"6", ex, "V'st / V'cn", (vs / vn) / e - 3.5 * mu * (1 + 1 / e),
                      -cp.x / res.v_after.z, 0.02});
    }
  // Test 7: symmetric spins; no tangential force, exactly.
  const ImpactMaterial copper{1.2e11, 0.35, 8900};
  for (auto [name, m] : {std::pair{"Al alloy", al33}, std::pair{"copper", copper}})
    for (double w : {0.175, 5.0, 22.86}) {
      const auto res = sphere_on_sphere(m, 0.1, {0.2, 0, 0}, {0, w, 0}, m, 0.1, {-0.2, 0, 0},
                                        {0, -w, 0}, 0.5, 0.4, exact);
      const std::string ex = std::string(name) + ", w = " + fmt(w) + " rad/s";
      Row a{"7",
            ex,
            "|tangential velocity after| [m/s]",
            0,
            std::hypot(res.v_after.y, res.v_after.z) + std::hypot(res.v2_after.y, res.v2_after.z),
            1e-12};
      a.absolute = true;
      Row b{"7",
            ex,
            "|w' - w| [rad/s]",
            0,
            norm(res.w_after - Vec3{0, w, 0}) + norm(res.w2_after - Vec3{0, -w, 0}),
            1e-12};
      b.absolute = true;
      rows.push_back(a);
      rows.push_back(b);
    }
  // Test 8: small spinning sphere onto a big, heavy sphere at rest (case A: 1000x stiffer).
  for (auto [name, m] : {std::pair{"Al alloy", al33}, std::pair{"nylon", nylon}})
    for (double w : {5.0, 10.0, 22.86}) {
      const double mu = 0.4, e = 0.5, vn = 0.2, r = 0.1, vs = r * w;
      const ImpactMaterial big{m.youngs_modulus * 1000, m.poisson_ratio, m.density * 1000};
      const auto res =
          sphere_on_sphere(m, r, {vn, 0, 0}, {0, w, 0}, big, 5 * r, {}, {}, e, mu, exact);
      // Contact point of sphere 1 at +r x: velocity w x (r x) = -r w z.
      const double vst_after = res.v_after.z + (cross(res.w_after, Vec3{r, 0, 0})).z;
      const std::string ex = std::string(name) + " case A, w = " + fmt(w) + " rad/s";
      rows.push_back({"8", ex, "V'st / Vst (paper's signs)", -1 + 3.5 * mu * (1 + e) * vn / vs,
                      vst_after / vs, 0.02});
    }
  return rows;
}

} // namespace wear::dem::validation

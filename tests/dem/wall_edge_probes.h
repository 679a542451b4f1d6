#pragma once
// Probes of a sphere on a triangle-mesh wall's boundary for the wall-boundary tests
// (wall_edge_test.cc, wall_edge_driven_test.cc, wall_rim_test.cc): the analytic Hertz force,
// the meshes (plates, folds, fans, pyramids, polygonal orifices), a sphere pressed at rest and
// the reference contacts of a polygonal rim. Particle and wall of one material, E = 5e7 Pa,
// nu = 0.25, so E* = E / (2 (1 - nu^2)) = 2.667e7 Pa.
#include "tests/dem/dem_fixtures.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace wall_edge {

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::cross;
using wear::meshes::dot;
using wear::meshes::norm;
using wear::meshes::normalized;
using wear::meshes::SurfaceMesh;
using wear::meshes::Vec3;

constexpr double youngs = 5e7, poisson = 0.25; // the gravel of add_gravel
const double e_star = youngs / (2 * (1 - poisson * poisson));
constexpr double deg = pi / 180;

/// [N] Hertz force of a wall contact of overlap `overlap` [m] on a sphere of radius r.
inline double hertz(double overlap, double r) {
  return overlap > 0 ? 4.0 / 3.0 * e_star * std::sqrt(r) * std::pow(overlap, 1.5) : 0.0;
}

/// [J] Its elastic energy.
inline double hertz_energy(double overlap, double r) {
  return overlap > 0 ? 8.0 / 15.0 * e_star * std::sqrt(r) * std::pow(overlap, 2.5) : 0.0;
}

/// One OpenMP thread while it lives (setup() takes OpenMP's count; a particle needs no more).
struct OneThread {
  int before = omp_get_max_threads();
  OneThread() { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(before); }
};

inline SurfaceMesh mesh_of(std::vector<Vec3> v, std::vector<wear::meshes::Triangle> t) {
  SurfaceMesh m;
  m.vertices = std::move(v);
  m.triangles = std::move(t);
  m.face_labels.assign(m.triangles.size(), wear::meshes::label::wall);
  return m;
}

/// The square [x0, x0 + n a] x [y0, y0 + n a] at z = 0: n x n squares of side a, each cut by
/// its diagonal from (i, j) to (i + 1, j + 1), 2 n^2 triangles.
inline SurfaceMesh grid_plate(double x0, double y0, double a, int n) {
  std::vector<Vec3> v;
  std::vector<wear::meshes::Triangle> t;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      v.push_back({x0 + i * a, y0 + j * a, 0});
  const auto id = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh_of(v, t);
}

/// Two rectangles meeting along the x axis (x in [-L, L]), each L wide, sloping down from it
/// at `slope` on either side: a convex ridge for slope > 0, a valley for slope < 0. Faces at
/// y < 0 have the outward normal (0, -sin slope, cos slope), at y > 0 (0, sin slope, cos slope).
/// Two plates of one wall, 2 L square in all, a slit of width w along y between them, at z = 0.
inline SurfaceMesh slit_plate(double w, double L) {
  return mesh_of({{-L, -L, 0},
                  {-w / 2, -L, 0},
                  {-w / 2, L, 0},
                  {-L, L, 0},
                  {w / 2, -L, 0},
                  {L, -L, 0},
                  {L, L, 0},
                  {w / 2, L, 0}},
                 {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}});
}

inline SurfaceMesh fold(double slope, double L) {
  const double c = L * std::cos(slope), s = L * std::sin(slope);
  return mesh_of({{-L, 0, 0}, {L, 0, 0}, {L, -c, -s}, {-L, -c, -s}, {L, c, -s}, {-L, c, -s}},
                 {{0, 3, 2}, {0, 2, 1}, {0, 1, 4}, {0, 4, 5}});
}

/// n triangles about a vertex at the origin in z = 0 (the polygon of radius a around it).
inline SurfaceMesh fan(int n, double a) {
  std::vector<Vec3> v{{0, 0, 0}};
  std::vector<wear::meshes::Triangle> t;
  for (int k = 0; k < n; ++k) {
    v.push_back({a * std::cos(2 * pi * k / n), a * std::sin(2 * pi * k / n), 0});
    t.push_back({0, std::uint32_t(1 + k), std::uint32_t(1 + (k + 1) % n)});
  }
  return mesh_of(v, t);
}

/// A square pyramid, apex at the origin, its four faces sloping down at `slope`, L long.
inline SurfaceMesh pyramid(double slope, double L) {
  const double h = L * std::tan(slope);
  return mesh_of({{0, 0, 0}, {L, L, -h}, {-L, L, -h}, {-L, -L, -h}, {L, -L, -h}},
                 {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
}

/// Vertex k of the regular n-gon of circumradius R about the z axis in z = 0 (vertex 0 on +x).
inline Vec3 polygon_vertex(int n, double R, int k) {
  return {R * std::cos(2 * pi * k / n), R * std::sin(2 * pi * k / n), 0};
}

/// A plate in z = 0 with an orifice: the annulus between the n-gon of circumradius R (the rim,
/// free edges) and the n-gon of 2 R, one quad of two triangles per rim edge.
inline SurfaceMesh orifice_plate(int n, double R) {
  std::vector<Vec3> v;
  std::vector<wear::meshes::Triangle> t;
  for (int k = 0; k < n; ++k) {
    v.push_back(polygon_vertex(n, R, k));
    v.push_back(polygon_vertex(n, 2 * R, k));
  }
  for (int k = 0; k < n; ++k) {
    const std::uint32_t p = 2 * k, q = 2 * k + 1, p1 = 2 * ((k + 1) % n), q1 = p1 + 1;
    t.push_back({p, p1, q1});
    t.push_back({p, q1, q});
  }
  return mesh_of(v, t);
}

/// What a wall does to a sphere at rest: the force, the contacts kept (their normals) and
/// the wear's normal impulse per face over the setup's evaluation.
struct Probe {
  Vec3 force;
  std::vector<Vec3> normals;
  std::vector<double> face_impulse; ///< [N s] per face
  double total_impulse = 0;         ///< [N s] per contact, before the split
  /// [J] System::energy(): the Hertz energy of the contacts the force applies.
  double elastic = 0;
};

inline Probe press(const SurfaceMesh& mesh, const Vec3& centre, double r) {
  const OneThread one;
  System s;
  s.settings.gravity = {0, 0, 0};
  const int g = add_gravel(s, 0.5, 0.5, 0);
  s.add_wall(MeshWall(mesh, g, {}, true, "plate"));
  s.particles.add(centre, {}, r, 2650, g);
  s.setup();
  Probe p;
  p.force = s.particles.force[0];
  const auto state = s.export_state();
  for (std::size_t k = 0; k < state.slot_wall.size() && state.slot_wall[k] >= 0; ++k)
    p.normals.push_back(state.slot_normal[k]);
  const auto w = s.wear_integrals(0);
  p.face_impulse = w.normal_impulse;
  p.total_impulse = w.total_normal_impulse;
  p.elastic = s.energy().elastic;
  return p;
}

/// |a - b| / scale.
inline double off(const Vec3& a, const Vec3& b, double scale) {
  return norm(a - b) / scale;
}

/// The probe's elastic energy against one contact's of overlap `overlap`, relative.
inline double energy_off(const Probe& p, double overlap, double r) {
  return std::abs(p.elastic - hertz_energy(overlap, r)) / hertz_energy(overlap, r);
}

/// Closest point of segment [a, b] to c when it lies strictly inside the segment (a polygon's
/// edge as a local distance minimum), else false.
inline bool segment_foot(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& foot) {
  const Vec3 e = b - a;
  const double t = dot(c - a, e) / dot(e, e);
  foot = a + e * t;
  return t > 0 && t < 1;
}

/// One Hertz contact per rim edge of the n-gon orifice that the sphere (c, r) overlaps, for a
/// centre over the hole (no face of the plate nearer): the forces.
inline std::vector<Vec3> rim_contacts(int n, double R, const Vec3& c, double r) {
  std::vector<Vec3> f;
  for (int k = 0; k < n; ++k) {
    Vec3 p;
    if (!segment_foot(polygon_vertex(n, R, k), polygon_vertex(n, R, k + 1), c, p))
      continue;
    const double d = norm(c - p);
    if (d < r)
      f.push_back((c - p) / d * hertz(r - d, r));
  }
  return f;
}

/// Their sum; `n_touching`: how many.
inline Vec3 rim_force_sum(int n, double R, const Vec3& c, double r, int& n_touching) {
  const auto f = rim_contacts(n, R, c, r);
  n_touching = int(f.size());
  Vec3 sum{};
  for (const Vec3& x : f)
    sum += x;
  return sum;
}

/// How far `force` is, relative to the largest of the rim contacts, from the nearest of those
/// as deep as the deepest (to 1e-12): what the engine's merge of contacts within 25 degrees
/// keeps when all lie within it (on a tie, either).
inline double off_deepest(int n, double R, const Vec3& c, double r, const Vec3& force) {
  const auto f = rim_contacts(n, R, c, r);
  double largest = 0;
  for (const Vec3& x : f)
    largest = std::max(largest, norm(x));
  double best = 1e300;
  for (const Vec3& x : f)
    if (norm(x) >= largest * (1 - 1e-12))
      best = std::min(best, off(force, x, largest));
  return best;
}

// The static cases' sphere.
constexpr double r0 = 5e-3, delta0 = 5e-5, dist0 = r0 - delta0;
const double f0 = hertz(delta0, r0);

// The orifice cases: the hopper's (cases/hopper: a 50 mm orifice, 6 mm particles).
constexpr double rim_radius = 0.025, r_rim = 3e-3, delta_rim = 1e-5;

} // namespace wall_edge

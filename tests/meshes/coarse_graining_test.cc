// Coarse-grained wall loads (meshes/coarse_graining.h): the force and moment of hand-placed
// contacts on a curved two-label plate are kept to round-off; a single contact on a flat
// plate gives the analytic truncated-Gaussian traction at h and h/2; and a window of many
// contacts gives a traction that changes little between h and h/2, unlike the per-face one.
#include "meshes/coarse_graining.h"
#include "meshes/constants.h"
#include "meshes/structured_grid.h"
#include "meshes/surface_locator.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace wear::meshes;
using wear::pi;

namespace {

// A 60 x 40 mm plate with a 10 mm high Gaussian hill (radius 8 mm) at (30, 20) mm; the hill
// (z > 3 mm) is element C11, the rest the base.
SurfaceMesh hill_plate(int n_u, int n_v) {
  auto m = structured_grid(
      n_u, n_v,
      [](double u, double v) {
        const double x = 0.06 * u, y = 0.04 * v;
        const double r2 = (x - 0.03) * (x - 0.03) + (y - 0.02) * (y - 0.02);
        return Vec3{x, y, 0.01 * std::exp(-r2 / (2 * 0.008 * 0.008))};
      },
      false, label::base);
  const auto c = face_centroids(m);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (c[f].z > 0.003)
      m.face_labels[f] = label::convex_element(1, 1);
  return m;
}

// A flat L x L plate at z = 0, n x n quads.
SurfaceMesh flat_plate(double L, int n) {
  return structured_grid(
      n, n,
      [L](double u, double v) {
        return Vec3{L * u, L * v, 0};
      },
      false, label::base);
}

// Contacts of one window as per-face sources: each contact at a point of its face with a
// compressive impulse (normal part into the wall, tangential part up to half of it) and its
// moment about the origin, plus a small couple per contact.
struct Contact {
  std::size_t face;
  Vec3 point, impulse;
};

FaceSources sources_of(const SurfaceMesh& m, const std::vector<Contact>& contacts) {
  FaceSources s;
  s.impulse.assign(m.n_faces(), {});
  s.point.assign(m.n_faces(), {});
  s.moment.assign(m.n_faces(), {});
  std::vector<double> fn(m.n_faces(), 0);
  const auto n = face_normals(m);
  for (const auto& c : contacts) {
    s.impulse[c.face] += c.impulse;
    s.moment[c.face] += cross(c.point, c.impulse);
    const double w = -dot(c.impulse, n[c.face]);
    s.point[c.face] += c.point * w;
    fn[c.face] += w;
  }
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (fn[f] > 0)
      s.point[f] = s.point[f] / fn[f];
  return s;
}

// A point of face f at barycentric (a, b).
Vec3 point_on(const SurfaceMesh& m, std::size_t f, double a, double b) {
  const auto& t = m.triangles[f];
  if (a + b > 1) {
    a = 1 - a;
    b = 1 - b;
  }
  const Vec3 p0 = m.vertices[t[0]];
  return p0 + (m.vertices[t[1]] - p0) * a + (m.vertices[t[2]] - p0) * b;
}

std::vector<Contact> random_contacts(const SurfaceMesh& m, int n_contacts, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> face(0, m.n_faces() - 1);
  std::uniform_real_distribution<double> u(0, 1), t(-0.5, 0.5);
  std::exponential_distribution<double> magnitude(1e3); // [1/(N s)], mean 1 mN s
  const auto n = face_normals(m);
  std::vector<Contact> c;
  for (int k = 0; k < n_contacts; ++k) {
    const std::size_t f = face(rng);
    const Vec3 p = point_on(m, f, u(rng), u(rng));
    const double fn = magnitude(rng);
    const Vec3 tangent = normalized(cross(n[f], Vec3{t(rng), t(rng), t(rng)}));
    c.push_back({f, p, n[f] * (-fn) + tangent * (fn * t(rng))});
  }
  return c;
}

// The value over its face's area of the extensive field at the face nearest each point.
std::vector<Vec3> traction_at(const SurfaceMesh& m, const FaceField<Vec3>& force,
                              const std::vector<Vec3>& points) {
  const SurfaceLocator locator(m);
  const auto area = face_areas(m);
  std::vector<Vec3> t;
  for (const auto& p : points) {
    const auto hit = locator.nearest(p);
    t.push_back(force[std::size_t(hit.face)] / area[std::size_t(hit.face)]);
  }
  return t;
}

// Relative L2 difference of two sampled fields: |a - b|_2 / |b|_2.
double l2_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double d = 0, s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    d += norm2(a[k] - b[k]);
    s += norm2(b[k]);
  }
  return std::sqrt(d / s);
}
} // namespace

TEST_CASE("coarse-graining keeps the window's force (1e-10) and moment about the sample "
          "centre (1e-6) on a curved two-label plate",
          "[meshes][coarse-graining]") {
  const auto m = hill_plate(60, 40); // h = 1 mm
  const auto contacts = random_contacts(m, 400, 11);
  const auto s = sources_of(m, contacts);
  const Vec3 centre{0.03, 0.02, 0};
  Vec3 force{}, moment{};
  for (const auto& c : contacts) {
    force += c.impulse;
    moment += cross(c.point - centre, c.impulse);
  }
  for (const double w : {0.5e-3, 2e-3, 6e-3}) {
    const CoarseGraining cg(m, w, "test");
    const auto f = cg.spread_force(s, "coarse-grained impulse", "N s");
    const auto x = face_centroids(m);
    Vec3 cg_force{}, cg_moment{};
    std::size_t n_loaded = 0, n_sources = 0;
    for (std::size_t g = 0; g < m.n_faces(); ++g) {
      cg_force += f[g];
      cg_moment += cross(x[g] - centre, f[g]);
      n_loaded += norm(f[g]) > 0;
      n_sources += norm(s.impulse[g]) > 0;
    }
    CAPTURE(w);
    CHECK(norm(cg_force - force) / norm(force) < 1e-10);
    CHECK(norm(cg_moment - moment) / norm(moment) < 1e-6);
    CHECK(f.revision() == m.revision());
    // The loads are spread: many more faces than sources carry them.
    CHECK(n_loaded > 2 * n_sources);
  }
}

TEST_CASE("coarse-graining: a single contact on a flat plate gives the truncated Gaussian "
          "traction, face means within 2 % of the peak at h = w/2 and w/4, at fixed points to "
          "first order in h",
          "[meshes][coarse-graining]") {
  const double L = 0.04, w = 2e-3;
  const Vec3 p{0.0203, 0.0196, 0}, impulse{1e-4, -2e-4, -1e-3};
  // The continuum traction: I phi(r) / integral of phi over the plane inside 3w.
  const double mass = 2 * pi * w * w * (1 - std::exp(-4.5));
  std::vector<Vec3> points, exact;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      const Vec3 x = p + Vec3{i * 0.6e-3 + 0.13e-3, j * 0.6e-3 - 0.07e-3, 0};
      points.push_back(x);
      exact.push_back(impulse * (std::exp(-norm2(x - p) / (2 * w * w)) / mass));
    }
  std::vector<std::vector<Vec3>> sampled;
  for (const int n : {40, 80}) { // h = 1 mm, 0.5 mm
    const auto m = flat_plate(L, n);
    const SurfaceLocator locator(m);
    const std::size_t face = std::size_t(locator.nearest(p).face);
    const auto s = sources_of(m, {{face, p, impulse}});
    const auto f = CoarseGraining(m, w, "test").spread_force(s, "impulse", "N s");
    // Face means against the continuum value at the face centroid: the centroid rule.
    const auto x = face_centroids(m);
    const auto a = face_areas(m);
    double worst = 0;
    for (std::size_t g = 0; g < m.n_faces(); ++g) {
      const Vec3 t_exact =
          impulse *
          (norm2(x[g] - p) < 9 * w * w ? std::exp(-norm2(x[g] - p) / (2 * w * w)) / mass : 0.0);
      worst = std::max(worst, norm(f[g] / a[g] - t_exact));
    }
    CAPTURE(n);
    CHECK(worst / (norm(impulse) / mass) < 0.02);
    sampled.push_back(traction_at(m, f, points));
  }
  // At fixed points the face value stands for the traction over the whole face: an error of
  // about (h / w) |grad t| that halves with h.
  const double at_h = l2_difference(sampled[0], exact), at_h2 = l2_difference(sampled[1], exact);
  CHECK(at_h < 0.15);
  CHECK(at_h2 < 0.07);
  CHECK(at_h / at_h2 > 1.8);
  CHECK(l2_difference(sampled[1], sampled[0]) < 0.12);
}

TEST_CASE("coarse-graining: a window of many contacts on a flat plate changes by under 10 % "
          "between h and h/2 where the per-face traction changes by over 50 %",
          "[meshes][coarse-graining]") {
  // 40 x 40 mm, w = 2 mm (the mean particle radius near s = 1.5), 4000 contacts (2.5 per
  // mm^2, with exponentially distributed impulses): a window of a few thousand distinct
  // contacts. Sampled on a 60 x 60 grid of fixed points 3w inside the edges.
  const double L = 0.04, w = 2e-3;
  std::vector<Vec3> points;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j)
      points.push_back(
          {3 * w + (L - 6 * w) * (i + 0.5) / 60, 3 * w + (L - 6 * w) * (j + 0.5) / 60, 0});
  // The same physical contacts on both meshes: placed by position, then found on each mesh.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, L), t(-0.5, 0.5);
  std::exponential_distribution<double> magnitude(1e3);
  std::vector<std::pair<Vec3, Vec3>> placed;
  for (int k = 0; k < 4000; ++k) {
    const double fn = magnitude(rng);
    placed.push_back({{u(rng), u(rng), 0}, {fn * t(rng), fn * t(rng), -fn}});
  }
  std::vector<std::vector<Vec3>> per_face, coarse;
  for (const int n : {40, 80}) {
    const auto m = flat_plate(L, n);
    const SurfaceLocator locator(m);
    std::vector<Contact> contacts;
    for (const auto& [x, i] : placed)
      contacts.push_back({std::size_t(locator.nearest(x).face), x, i});
    const auto s = sources_of(m, contacts);
    FaceField<Vec3> raw("impulse", "N s", Extensivity::extensive, m);
    raw.values() = s.impulse;
    per_face.push_back(traction_at(m, raw, points));
    coarse.push_back(
        traction_at(m, CoarseGraining(m, w, "test").spread_force(s, "impulse", "N s"), points));
  }
  const double per_face_change = l2_difference(per_face[1], per_face[0]);
  const double coarse_change = l2_difference(coarse[1], coarse[0]);
  CHECK(per_face_change > 0.5);
  CHECK(coarse_change < 0.10);
}

TEST_CASE("coarse-graining of a scalar keeps each label's total and stays non-negative",
          "[meshes][coarse-graining]") {
  const auto m = hill_plate(60, 40);
  const auto contacts = random_contacts(m, 400, 3);
  const auto s = sources_of(m, contacts);
  FaceField<double> volume("wear-law volume", "m^3", Extensivity::extensive, m);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    volume[f] = 1e-12 * norm(s.impulse[f]) / 1e-3;
  const auto spread = CoarseGraining(m, 2e-3, "test").spread_scalar(volume, s.point);
  for (const int l : m.labels()) {
    double before = 0, after = 0;
    for (std::size_t f = 0; f < m.n_faces(); ++f)
      if (m.face_labels[f] == l) {
        before += volume[f];
        after += spread[f];
      }
    CAPTURE(l);
    CHECK(std::abs(after - before) < 1e-12 * before);
  }
  double smallest = 0;
  for (const double v : spread.values())
    smallest = std::min(smallest, v);
  CHECK(smallest == 0);
}

TEST_CASE("coarse-graining: a width that is not positive is refused, naming the parameter",
          "[meshes][coarse-graining]") {
  const auto m = flat_plate(0.01, 4);
  CHECK_THROWS_WITH(CoarseGraining(m, 0, "DEM/Coarse-graining width"),
                    Catch::Contains("DEM/Coarse-graining width"));
  CHECK_THROWS_WITH(CoarseGraining(m, std::nan(""), "DEM/Coarse-graining width"),
                    Catch::Contains("positive"));
}

// Stress measures (fem/stress_measures.h): on constructed linear stress fields the ball
// average and the percentiles against their analytic values, and under refinement of a
// loaded block the ball-averaged maximum against the quadrature-point maximum.
#include "fem/boundary_face_map.h"
#include "fem/elasticity.h"
#include "fem/stress_measures.h"
#include "meshes/constants.h"
#include "meshes/sample_generator.h"

#include <catch2/catch.hpp>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/grid_generator.h>

#include <array>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>

using namespace wear::fem;
using dealii::Point;
using dealii::SymmetricTensor;
using wear::meshes::Vec3;

namespace {

// Box [lo, hi] in tetrahedra (5 per hexahedron); bottom (z = lo.z) clamped (label 1), top
// label 3, sides label 2.
void make_box(dealii::Triangulation<3>& tria, const std::vector<unsigned int>& n,
              const Point<3>& lo, const Point<3>& hi) {
  dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(tria, n, lo, hi, false);
  const double tol = 1e-9 * (hi[2] - lo[2]);
  for (const auto& cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary()) {
        const double z = cell->face(f)->center()[2];
        cell->face(f)->set_boundary_id(z < lo[2] + tol ? 1 : (z > hi[2] - tol ? 3 : 2));
      }
}

// The quadrature points of the P1 solver's rule (Gauss simplex of degree 2) on `tria`, with
// the stress field `sigma` evaluated there.
StressSamples samples_of(const dealii::Triangulation<3>& tria,
                         const std::function<SymmetricTensor<2, 3>(const Point<3>&)>& sigma) {
  const dealii::MappingFE<3> mapping(dealii::FE_SimplexP<3>(1));
  const dealii::FE_SimplexP<3> fe(1);
  const dealii::QGaussSimplex<3> quadrature(2);
  dealii::FEValues<3> fv(mapping, fe, quadrature,
                         dealii::update_quadrature_points | dealii::update_JxW_values);
  StressSamples s;
  for (const auto& cell : tria.active_cell_iterators()) {
    fv.reinit(cell);
    for (unsigned int q = 0; q < quadrature.size(); ++q) {
      s.points.push_back(fv.quadrature_point(q));
      s.stress.push_back(sigma(fv.quadrature_point(q)));
      s.weights.push_back(fv.JxW(q));
    }
  }
  return s;
}

SymmetricTensor<2, 3> unit_xx() {
  SymmetricTensor<2, 3> t;
  t[0][0] = 1;
  return t;
}

double tensor_norm(const SymmetricTensor<2, 3>& t) {
  return std::sqrt(dealii::scalar_product(t, t));
}

} // namespace

TEST_CASE("stress measures: ball average and percentiles of linear fields are exact",
          "[fem][stress]") {
  // Box [-L, L]^3, 24^3 x 5 tetrahedra (h = L / 12), ball radius R = L / 4 = 3 h. The mean of
  // a linear field over a ball is its value at the centre; over the half ball below a flat
  // face it is the value at the half ball's centroid, 3 R / 8 below the centre. What the
  // quadrature points miss: cells cut by the sphere count by their points inside (measured
  // 2.3e-4 to 3.9e-4 of the stress; tolerance 2e-3).
  const double L = 0.01, R = L / 4;
  dealii::Triangulation<3> tria;
  make_box(tria, {24, 24, 24}, Point<3>(-L, -L, -L), Point<3>(L, L, L));
  SymmetricTensor<2, 3> s0, gx, gy, gz; // sigma(x) = s0 + gx x + gy y + gz z
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = i; j < 3; ++j) {
      s0[i][j] = 1e6 * (1 + i + 2 * j);
      gx[i][j] = 1e8 * (1.0 + i - j);
      gy[i][j] = 1e8 * (0.5 * i + j);
      gz[i][j] = -1e8 * (2.0 - i * j);
    }
  const auto linear = [&](const Point<3>& x) { return s0 + x[0] * gx + x[1] * gy + x[2] * gz; };
  const BallAverage ball(samples_of(tria, linear), R);
  CHECK(ball.radius() == R);
  const double scale = tensor_norm(linear(Point<3>(0, 0, 0))); // about 12 MPa
  for (const auto& c : {Point<3>(0, 0, 0), Point<3>(0.3 * L, -0.45 * L, 0.12 * L),
                        Point<3>(-0.7 * L, 0.7 * L, -0.7 * L)}) {
    const double error = tensor_norm(ball.mean_stress(c) - linear(c)) / scale;
    INFO("centre " << c << ": relative error " << error);
    CHECK(error < 2e-3);
  }
  // The solver groups the samples by cell (6 quadrature points a cell here): whole cells where
  // the ball holds them, single points where the sphere cuts a cell. The same samples as one
  // by one, summed in another order.
  const auto grouped = samples_of(tria, linear);
  const auto per_cell = unsigned(grouped.points.size() / tria.n_active_cells());
  REQUIRE(per_cell * tria.n_active_cells() == grouped.points.size());
  const BallAverage cells(grouped, R, per_cell);
  for (const auto& c : {Point<3>(0, 0, 0), Point<3>(0.3 * L, -0.45 * L, 0.12 * L),
                        Point<3>(-0.7 * L, 0.7 * L, -0.7 * L), Point<3>(0.2 * L, -0.1 * L, L)}) {
    const double difference = tensor_norm(cells.mean_stress(c) - ball.mean_stress(c)) / scale;
    INFO("grouped by cell, centre " << c << ": relative difference " << difference);
    CHECK(difference < 1e-12);
  }
  CHECK(cells.cell_volumes().size() == tria.n_active_cells());
  CHECK_THROWS_WITH(BallAverage(grouped, R, 7), Catch::Contains("whole groups"));
  // Half balls on the top face and on a side face.
  const Point<3> top(0.2 * L, -0.1 * L, L), side(L, 0.25 * L, -0.3 * L);
  const double top_error =
      tensor_norm(ball.mean_stress(top) - linear(Point<3>(top[0], top[1], top[2] - 3 * R / 8))) /
      scale;
  const double side_error = tensor_norm(ball.mean_stress(side) -
                                        linear(Point<3>(side[0] - 3 * R / 8, side[1], side[2]))) /
                            scale;
  INFO("half ball: relative error " << top_error << " (top), " << side_error << " (side)");
  CHECK(top_error < 2e-3);
  CHECK(side_error < 2e-3);

  // The tensor is averaged, then von Mises taken: for sigma_xx = k x the ball at x = 0 has
  // mean stress 0, while the mean of von Mises |k x| over it would be 3 k R / 8; the half ball
  // on the face x = -L has mean stress -k (L - 3 R / 8).
  const double k = 1e9; // [Pa/m]
  const auto signed_x = [&](const Point<3>& x) {
    SymmetricTensor<2, 3> t;
    t[0][0] = k * x[0];
    return t;
  };
  const BallAverage ball_x(samples_of(tria, signed_x), R);
  const auto vm = ball_x.von_mises_at({Point<3>(0, 0.1 * L, 0), Point<3>(-L, 0, 0)});
  INFO("von Mises of the ball average at x = 0: " << vm[0] << " Pa (mean of von Mises "
                                                  << 3 * k * R / 8 << "), at x = -L: " << vm[1]);
  CHECK(vm[0] < 2e-3 * k * R);
  CHECK(vm[1] == Approx(k * (L - 3 * R / 8)).epsilon(2e-3));

  // Volume-weighted percentiles: von Mises k (x + L) is uniform on [0, 2 k L] by volume, so
  // the p-th percentile is 2 k L p; to 0.3 %, since the quadrature points sit at a few x per
  // cell (the sampled distribution is a staircase of steps below h / 2L = 4 %).
  const auto samples =
      samples_of(tria, [&](const Point<3>& x) { return signed_x(x) + k * L * unit_xx(); });
  std::vector<double> values;
  for (const auto& t : samples.stress)
    values.push_back(von_mises(t));
  const auto pct = volume_percentiles(values, samples.weights, {0.5, 0.99, 0.999});
  INFO("percentiles 50, 99, 99.9: " << pct[0] << ", " << pct[1] << ", " << pct[2] << " Pa");
  CHECK(pct[0] == Approx(2 * k * L * 0.5).epsilon(3e-3));
  CHECK(pct[1] == Approx(2 * k * L * 0.99).epsilon(3e-3));
  CHECK(pct[2] == Approx(2 * k * L * 0.999).epsilon(3e-3));
  CHECK_THROWS_WITH(volume_percentiles(values, samples.weights, {1.5}),
                    Catch::Contains("outside (0, 1]"));
  CHECK_THROWS_WITH(BallAverage(samples, 0), Catch::Contains("radius must be positive"));
}

namespace {

struct Measures {
  double ball = 0, qp = 0, p999 = 0; ///< [Pa]
  unsigned int n_cells = 0;
};

// Block [0, W]^2 x [0, H] of n x n x n/2 hexahedra (5 tetrahedra each, h = W / n), P1,
// bottom clamped, loaded on the top face by the force per face `force(centroid, share)`,
// share = the face's area over that of the top faces touching the top face's centre (0 for
// the others).
Measures block_measures(unsigned int n, unsigned int degree, double R,
                        const std::function<Vec3(const Vec3&, double, double)>& force) {
  const double W = 0.02, H = 0.01;
  dealii::Triangulation<3> tria;
  make_box(tria, {n, n, n / 2}, Point<3>(0, 0, 0), Point<3>(W, W, H));
  const auto surface = extract_boundary_surface(tria, wear::meshes::sample_roles(false));
  BoundaryFaceMap map(tria, surface);
  wear::meshes::FaceField<Vec3> F("force", "N", wear::meshes::Extensivity::extensive, surface);
  const auto c = wear::meshes::face_centroids(surface);
  const auto a = wear::meshes::face_areas(surface);
  const Vec3 centre{W / 2, W / 2, H};
  std::vector<double> share(surface.n_faces(), 0);
  double centre_area = 0;
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    for (const auto v : surface.triangles[f])
      if (surface.face_labels[f] == 3 && norm(surface.vertices[v] - centre) < 1e-9 * W) {
        share[f] = a[f];
        centre_area += a[f];
        break;
      }
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    if (surface.face_labels[f] == 3)
      F[f] = force(c[f], a[f], share[f] / centre_area);
  ElasticityParameters p;
  p.averaging_radius = R;
  p.degree = degree;
  ElasticitySolver solver(tria, map, p);
  const auto r = solver.run(F);
  return {r.max_von_mises_ball, r.max_von_mises_qp, r.von_mises_p999, tria.n_active_cells()};
}

// Block of 20 x 20 x 10 mm, meshes of h = 1.67 and 0.83 mm (4,320 and 34,560 cells), ball
// radius R = 2.5 mm. Smooth load: Gaussian pressure p0 exp(-r^2 / s^2), p0 = 10 kPa,
// s = 4 mm, about the top face's centre. Point-like load: the same total force pi s^2 p0 on
// the top triangles touching the centre (their area shrinks 4 times per refinement).
struct RefinementCase {
  double p0 = 1e4, s = 4e-3, R = 2.5e-3, W = 0.02;
  Vec3 smooth(const Vec3& c, double area) const {
    const double r2 = (c.x - W / 2) * (c.x - W / 2) + (c.y - W / 2) * (c.y - W / 2);
    return Vec3{0, 0, -p0 * std::exp(-r2 / (s * s)) * area};
  }
  Vec3 point(double share) const { return Vec3{0, 0, -wear::pi * s * s * p0 * share}; }
  /// Coarse and fine measures of the smooth (point) load.
  std::array<Measures, 2> run(bool point_load, unsigned int degree) const {
    std::array<Measures, 2> m;
    for (const unsigned int k : {0u, 1u})
      m[k] = block_measures(12 * (k + 1), degree, R, [&](const Vec3& c, double a, double share) {
        return point_load ? point(share) : smooth(c, a);
      });
    return m;
  }
};

double change(const std::array<Measures, 2>& m, double Measures::*x) {
  return m[1].*x / (m[0].*x) - 1;
}

std::string describe(const std::array<Measures, 2>& m) {
  std::ostringstream o;
  o << "cells " << m[0].n_cells << " -> " << m[1].n_cells << ": ball max " << m[0].ball << " -> "
    << m[1].ball << " Pa (" << 100 * change(m, &Measures::ball) << " %), qp max " << m[0].qp
    << " -> " << m[1].qp << " Pa (" << 100 * change(m, &Measures::qp) << " %), p99.9 " << m[0].p999
    << " -> " << m[1].p999 << " Pa (" << 100 * change(m, &Measures::p999) << " %)";
  return o.str();
}

} // namespace

TEST_CASE("stress measures: under refinement the ball-averaged maximum of a smooth load "
          "converges, the quadrature-point maximum under a point load does not",
          "[fem][stress]") {
  const RefinementCase c;
  // Smooth load, P2: every measure converges; the ball average within 5 %.
  const auto smooth = c.run(false, 2);
  INFO("smooth load, P2: " << describe(smooth));
  CHECK(std::abs(change(smooth, &Measures::ball)) < 0.05);
  // Point load, P1 (the runs' default): the quadrature-point maximum follows the traction on
  // the loaded triangles, 4 times larger on the refined mesh; it must grow by more than 2x.
  const auto point = c.run(true, 1);
  INFO("point load, P1: " << describe(point));
  CHECK(change(point, &Measures::qp) > 1.0);
}

TEST_CASE("stress measures: under a point load the ball-averaged maximum converges (P2)",
          "[fem][stress][long]") {
  // The same point load with P2: the ball average within 5 %, the quadrature-point maximum
  // again 4 times larger.
  const auto point = RefinementCase().run(true, 2);
  INFO("point load, P2: " << describe(point));
  CHECK(std::abs(change(point, &Measures::ball)) < 0.05);
  CHECK(change(point, &Measures::qp) > 2.0);
}

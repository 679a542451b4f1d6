// Wear laws and the reference deformation: analytic Archard volume on a face interior, an
// edge and a vertex; mesh-size independence under a particle bed; uniform recession of a
// flat plate; fits and statistics of the evaluation.
#include "dem/evaluation/tester_evaluation.h"
#include "dem/wear/reference_deformation.h"
#include "dem/wear/wear_law.h"
#include "meshes/structured_grid.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::Vec3;

namespace {
// Volume worn by one particle resting by its weight on a face moving at v under it.
struct Held {
  double volume = 0, expected = 0, face_sum = 0;
  double normal_impulse = 0, expected_normal_impulse = 0; ///< [N s]
  int n_faces_hit = 0;
};
Held held_particle(const Vec3& where) {
  System s;
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {0.5, 0.0, 0.0}); // frictionless: the particle stays in place
  WallMotion conveyor;
  conveyor.surface_velocity = {0.3, 0, 0};
  const int w = s.add_wall(MeshWall(flat_square(0.02, 4), g, conveyor, true, "sample"));
  const double r = 4e-3, m = 2650 * 4.0 / 3.0 * pi * r * r * r;
  const double e_star = 1 / (2 * (1 - 0.0625) / 5e7);
  const double delta = std::pow(m * 9.81 / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);
  s.particles.add({where.x, where.y, r - delta}, {}, r, 2650, g);
  s.setup();
  s.run(2000);
  const auto law = make_wear_law({"archard", 5e-9, 0});
  const auto wi = s.wear_integrals(w);
  Held h;
  h.volume = law->total_removed_volume(wi);
  for (double v : law->removed_volume(wi)) {
    h.face_sum += v;
    h.n_faces_hit += v > 0;
  }
  h.expected = 5e-9 * m * 9.81 * 0.3 * s.time();
  h.normal_impulse = wi.total_normal_impulse;
  h.expected_normal_impulse = m * 9.81 * s.time();
  return h;
}
} // namespace

TEST_CASE("Archard volume alpha F v t of a held particle on a face, an edge and a vertex",
          "[dem][wear]") {
  // The grid has 10 mm quads over [-20, 20] mm, diagonals from (u0, v0) to (u1, v1).
  struct Case {
    const char* where;
    Vec3 x;
    int faces;
  } cases[] = {{"face interior", {0.013, 0.004, 0}, 1},
               {"edge", {0.010, 0.004, 0}, 2},
               {"vertex", {0.010, 0.000, 0}, 6}};
  for (const auto& c : cases) {
    INFO(c.where);
    const Held h = held_particle(c.x);
    CHECK(h.volume == Approx(h.expected).epsilon(0.005));
    CHECK(h.normal_impulse == Approx(h.expected_normal_impulse).epsilon(0.005));
    CHECK(h.face_sum == Approx(h.volume).epsilon(1e-12));
    CHECK(h.n_faces_hit == c.faces);
  }
}

TEST_CASE("wear volume under a particle bed is independent of the flat wall's mesh size",
          "[dem][wear]") {
  // A bed of three layers in a 40 mm box whose floor (the wearing face) slides at 0.2 m/s;
  // 0.5, 1 and 2 mm triangles (two diagonal patterns). Flat-wall contacts must not depend on
  // where the triangle edges are.
  std::vector<double> volumes;
  for (const auto& [n, diag] : {std::pair{80, wear::meshes::Diagonals::uniform},
                                std::pair{40, wear::meshes::Diagonals::alternating},
                                std::pair{20, wear::meshes::Diagonals::uniform}}) {
    System s;
    const int g = add_gravel(s, 0.5, 0.5, 0.1);
    WallMotion conveyor;
    conveyor.surface_velocity = {0.2, 0, 0};
    const double L = 0.02;
    const int w = s.add_wall(MeshWall(flat_square(L, n, 0, diag), g, conveyor, true, "floor"));
    auto box = box_walls(2 * L);
    for (auto& v : box.vertices)
      v = v - Vec3{L, L, 0.001};
    s.add_wall(MeshWall(box, g, {}, false, "box"));
    const double d = 4e-3;
    FillRegion region{{-L, -L, 0}, {L, L, 3 * 1.05 * d}, [&](const Vec3& x) {
                        return std::abs(x.x) < L - 0.6 * d && std::abs(x.y) < L - 0.6 * d &&
                               x.z > 0.55 * d && x.z < 3 * 1.05 * d;
                      }};
    insert_lattice(s.particles, region, 1.05 * d, d, 2650, g, 1e-4, 7);
    s.settings.time_step_fraction = 0.2;
    s.set_n_threads(1);
    s.setup();
    s.set_n_threads(1);
    s.run(2000); // settle and start sliding
    s.reset_wear_integrals();
    s.run(4000);
    volumes.push_back(
        make_wear_law({"archard", 5e-9, 0})->total_removed_volume(s.wear_integrals(w)));
  }
  INFO("0.5 mm " << volumes[0] << ", 1 mm " << volumes[1] << ", 2 mm " << volumes[2]);
  CHECK(volumes[0] > 0);
  CHECK(volumes[1] == Approx(volumes[0]).epsilon(0.03));
  CHECK(volumes[2] == Approx(volumes[0]).epsilon(0.03));
}

TEST_CASE("reference deformation: a uniformly loaded flat plate recedes uniformly", "[dem][wear]") {
  auto plate = flat_square(0.02, 16, 0, wear::meshes::Diagonals::alternating);
  plate.roles.set(wear::meshes::label::base, wear::meshes::FaceRole::wearing);
  ReferenceDeformation def(plate);
  const auto area = wear::meshes::face_areas(plate);
  const double depth = 1e-5; // per update [m]
  std::vector<double> removed(area.size());
  for (std::size_t f = 0; f < area.size(); ++f)
    removed[f] = depth * area[f];
  for (int k = 0; k < 10; ++k)
    def.update(removed, 0.1 * k);
  for (const auto& v : def.mesh().vertices)
    CHECK(v.z == Approx(-10 * depth).epsilon(1e-9));
  CHECK(def.swept_volume() == Approx(def.applied_volume()).epsilon(0.01));
  CHECK(def.applied_volume() == Approx(10 * depth * 0.04 * 0.04).epsilon(1e-12));
  CHECK_FALSE(def.first_distortion());
}

TEST_CASE("reference deformation: an update that folds the surface is reported and undone",
          "[dem][wear]") {
  // A 10 mm cube, outward, its top wearing: removing 2 cm of depth pushes the top below the
  // bottom, which turns the sides inside out.
  auto cube = box_walls(0.01);
  for (auto& t : cube.triangles)
    std::swap(t[1], t[2]);
  const auto n = wear::meshes::face_normals(cube);
  for (std::size_t f = 0; f < cube.n_faces(); ++f)
    cube.face_labels[f] = n[f].z > 0.5 ? wear::meshes::label::base : wear::meshes::label::side;
  cube.roles.set(wear::meshes::label::base, wear::meshes::FaceRole::wearing);
  ReferenceDeformation def(cube);
  std::vector<double> removed(cube.n_faces(), 0);
  for (std::size_t f = 0; f < cube.n_faces(); ++f)
    if (cube.face_labels[f] == wear::meshes::label::base)
      removed[f] = 0.02 * 0.5e-4; // 2 cm over half of the top each
  const auto before = def.mesh().vertices;
  def.update(removed, 0.5);
  REQUIRE(def.first_distortion());
  CHECK(def.first_distortion()->kind == "inverted face");
  CHECK(def.first_distortion()->label == wear::meshes::label::side);
  CHECK(def.first_distortion()->time == 0.5);
  CHECK(def.mesh().vertices == before);
  def.update(removed, 0.6); // frozen
  CHECK(def.mesh().vertices == before);
}

TEST_CASE("wear laws by name, bad names and coefficients", "[dem][wear]") {
  WearIntegrals w;
  w.archard = {2.0, 3.0};
  w.sliding_work = {1.0, 0.5};
  w.total_archard = 5.0;
  w.total_sliding_work = 1.5;
  const auto a = make_wear_law({"archard", 5e-9, 1e-8});
  CHECK(a->removed_volume(w)[1] == Approx(1.5e-8));
  CHECK(a->total_removed_volume(w) == Approx(2.5e-8));
  const auto f = make_wear_law({"frictional-work", 5e-9, 1e-8});
  CHECK(f->removed_volume(w)[0] == Approx(1e-8));
  CHECK(f->total_removed_volume(w) == Approx(1.5e-8));
  CHECK_THROWS_WITH(make_wear_law({"archrad", 5e-9, 0}),
                    Catch::Contains("Wear law/Model") && Catch::Contains("archard"));
  CHECK_THROWS_WITH(make_wear_law({"archard", -1, 0}), Catch::Contains("Archard coefficient"));
  CHECK(wear_law_catalogue().size() == 5);
  WearLawParameters oka;
  oka.model = "oka";
  oka.oka_n1 = -1;
  CHECK_THROWS_WITH(make_wear_law(oka), Catch::Contains("Wear law/Oka n1"));
  oka.oka_n1 = 0.71;
  oka.oka_k1 = -0.12; // an exponent may be negative
  CHECK_NOTHROW(make_wear_law(oka));
  CHECK(impact_measure(oka).kind == ImpactMeasure::Kind::oka);
  CHECK(impact_measure({"archard", 5e-9, 0}).kind == ImpactMeasure::Kind::none);
}

TEST_CASE("wear laws summed: the volumes of the laws add up per face and per mechanism",
          "[dem][wear][impact]") {
  WearIntegrals w;
  w.archard = {2.0, 3.0};
  w.sliding_work = {1.0, 0.5};
  w.impact_measure = {4.0, 0.0};
  w.impact_energy = {0.5, 1.0};
  w.total_archard = 5.0;
  w.total_sliding_work = 1.5;
  w.total_impact_measure = 4.0;
  w.total_impact_energy = 1.5;
  WearLawParameters p;
  p.archard_coefficient = 5e-9;
  p.finnie_coefficient = 1e-10;
  p.model = " archard +finnie ";
  const auto sum = make_wear_law(p);
  CHECK(sum->name() == "archard + finnie");
  CHECK(sum->removed_volume(w)[0] == Approx(2 * 5e-9 + 4 * 1e-10).epsilon(1e-14));
  CHECK(sum->removed_volume(w)[1] == Approx(3 * 5e-9).epsilon(1e-14));
  CHECK(sum->total_removed_volume(w) == Approx(5 * 5e-9 + 4 * 1e-10).epsilon(1e-14));
  const auto parts = sum->removed_by_mechanism(w);
  REQUIRE(parts.size() == 2);
  CHECK(parts[0].first == "sliding");
  CHECK(parts[1].first == "impact");
  CHECK(parts[1].second[0] == Approx(4e-10).epsilon(1e-14));
  CHECK(impact_measure(p).kind == ImpactMeasure::Kind::finnie);
  // Two sliding laws: one mechanism, added.
  p.model = "archard + frictional-work";
  p.work_coefficient = 1e-8;
  const auto both = make_wear_law(p)->removed_by_mechanism(w);
  REQUIRE(both.size() == 1);
  CHECK(both[0].second[1] == Approx(3 * 5e-9 + 0.5 * 1e-8).epsilon(1e-14));
  for (const char* bad : {"archard + oka + finnie", "archard + archard", "archard +", "+"}) {
    p.model = bad;
    INFO(bad);
    CHECK_THROWS_WITH(make_wear_law(p), Catch::Contains("Wear law/Model"));
  }
}

TEST_CASE("least-squares wear fits through the origin and statistics", "[dem][wear]") {
  std::vector<double> x{1, 2, 3, 4}, y;
  for (double v : x)
    y.push_back(0.5 * v * v + 2 * v);
  const auto f = fit_wear(x, y);
  CHECK(f.b == Approx(0.5).epsilon(1e-12));
  CHECK(f.c == Approx(2).epsilon(1e-12));
  CHECK(f.r2_quadratic == Approx(1).epsilon(1e-12));
  CHECK(f.r2_linear < 1);
  const auto g = fit_wear(x, {3, 6, 9, 12});
  CHECK(g.a == Approx(3).epsilon(1e-12));
  CHECK(g.r2_linear == Approx(1).epsilon(1e-12));
  const auto s = statistic({1, 2, 3, 4});
  CHECK(s.mean == Approx(2.5));
  CHECK(s.std == Approx(std::sqrt(5.0 / 3.0)));
  CHECK(s.cv() == Approx(std::sqrt(5.0 / 3.0) / 2.5));
}

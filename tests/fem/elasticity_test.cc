// Linear elasticity: patch test (uniform strain exact with P1 and P2), force balance at the
// clamped face, a cantilever fin against Timoshenko beam theory, bad input.
#include "fem/boundary_face_map.h"
#include "fem/elasticity.h"
#include "fem/volume_output.h"
#include "meshes/sample_generator.h"

#include <catch2/catch.hpp>

#include <map>

#include <deal.II/grid/grid_generator.h>

#include <cmath>

using namespace wear::fem;
using wear::meshes::Vec3;

namespace {
// Box [0, a] x [0, b] x [0, c] in tetrahedra; bottom (z = 0) gets the clamped label 1, the
// top the base label 3, the sides label 2.
void make_box(dealii::Triangulation<3>& tria, unsigned int nx, unsigned int ny, unsigned int nz,
              double a, double b, double c) {
  dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(
      tria, {nx, ny, nz}, dealii::Point<3>(0, 0, 0), dealii::Point<3>(a, b, c), false);
  for (const auto& cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary()) {
        const double z = cell->face(f)->center()[2];
        cell->face(f)->set_boundary_id(z < 1e-9 * c ? 1 : (z > (1 - 1e-9) * c ? 3 : 2));
      }
}

// Face forces of a uniform stress state: F_f = sigma n_f A_f on every face but the bottom.
wear::meshes::FaceField<Vec3> uniform_stress_forces(const wear::meshes::SurfaceMesh& s,
                                                    const double sigma[3][3]) {
  wear::meshes::FaceField<Vec3> F("force", "N", wear::meshes::Extensivity::extensive, s);
  const auto n = wear::meshes::face_normals(s);
  const auto a = wear::meshes::face_areas(s);
  for (std::size_t f = 0; f < s.n_faces(); ++f) {
    if (s.face_labels[f] == 1)
      continue;
    for (int i = 0; i < 3; ++i)
      F[f][i] = (sigma[i][0] * n[f].x + sigma[i][1] * n[f].y + sigma[i][2] * n[f].z) * a[f];
  }
  return F;
}

// Face forces of a uniform traction t on the top (label 3): F_f = t A_f, zero elsewhere.
wear::meshes::FaceField<Vec3> top_traction_forces(const wear::meshes::SurfaceMesh& s,
                                                  const Vec3& t) {
  wear::meshes::FaceField<Vec3> F("force", "N", wear::meshes::Extensivity::extensive, s);
  const auto a = wear::meshes::face_areas(s);
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_labels[f] == 3)
      F[f] = a[f] * t;
  return F;
}
// A box of height c under a top pressure p, held laterally (and clamped or held underneath)
// with the default PE1000 constants: uniaxial strain, u = (0, 0, -p z / M), sigma_zz = -p,
// sigma_xx = sigma_yy = -p lambda / M in every cell, and the supports carry the whole load.
void check_uniaxial_strain(const ElasticitySolver& solver, const ElasticityResult& r,
                           unsigned int n_cells, double pressure, double c) {
  const ElasticityParameters defaults;
  const double E = defaults.youngs_modulus, nu = defaults.poisson_ratio;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double M = lambda + 2 * mu;
  CHECK(r.reaction_force.z == Approx(-r.applied_force.z).epsilon(1e-8));
  CHECK(r.max_displacement == Approx(pressure * c / M).epsilon(1e-8));
  for (unsigned int k = 0; k < n_cells; ++k) {
    CHECK(solver.principal_stresses()[0][k] == Approx(-pressure * lambda / M).epsilon(1e-8));
    CHECK(solver.principal_stresses()[2][k] == Approx(-pressure).epsilon(1e-8));
  }
}

} // namespace

TEST_CASE("elasticity patch test: uniform strain is exact with P1 and P2", "[fem][elasticity]") {
  // u = (0, 0, e z) satisfies the clamp at z = 0; its stress is sigma_xx = sigma_yy =
  // lambda e, sigma_zz = (lambda + 2 mu) e, applied as tractions on the sides and the top.
  const double E = 700e6, nu = 0.4, e = 1e-3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double sigma[3][3] = {
      {lambda * e, 0, 0}, {0, lambda * e, 0}, {0, 0, (lambda + 2 * mu) * e}};
  for (unsigned int degree : {1u, 2u}) {
    INFO("P" << degree);
    dealii::Triangulation<3> tria;
    make_box(tria, 3, 2, 2, 0.03, 0.02, 0.01);
    const auto surface = extract_boundary_surface(tria, wear::meshes::sample_roles(false));
    BoundaryFaceMap map(tria, surface);
    ElasticityParameters p;
    p.degree = degree;
    p.relative_tolerance = 1e-13;
    ElasticitySolver solver(tria, map, p);
    const auto r = solver.run(uniform_stress_forces(surface, sigma));
    const double vm = std::abs(sigma[2][2] - sigma[0][0]); // von Mises of this state
    CHECK(r.max_von_mises_qp == Approx(vm).epsilon(1e-8));
    for (unsigned int c = 0; c < tria.n_active_cells(); ++c) {
      CHECK(solver.principal_stresses()[0][c] == Approx(sigma[2][2]).epsilon(1e-8));
      CHECK(solver.principal_stresses()[2][c] == Approx(sigma[0][0]).epsilon(1e-8));
    }
    CHECK(r.max_displacement == Approx(e * 0.01).epsilon(1e-8));
    // The volume output carries the same fields: vertex displacement (0, 0, e z), cell
    // von Mises stress.
    const auto grid = volume_grid(tria, &solver);
    REQUIRE(grid.point_data.size() == 1);
    const auto& u = grid.point_data[0].values;
    for (std::size_t v = 0; v < grid.points.size(); ++v) {
      CHECK(std::abs(u[3 * v]) < 1e-8 * e * 0.01);
      CHECK(std::abs(u[3 * v + 1]) < 1e-8 * e * 0.01);
      CHECK(u[3 * v + 2] == Approx(e * grid.points[v].z).margin(1e-8 * e * 0.01));
    }
    for (const auto& a : grid.cell_data)
      if (a.name == "von Mises")
        for (const double x : a.values)
          CHECK(x == Approx(vm).epsilon(1e-8));
    // The clamp carries exactly the applied load.
    CHECK(std::abs(r.reaction_force.z + r.applied_force.z) < 1e-8 * std::abs(r.applied_force.z));
  }
}

TEST_CASE("elasticity: a sample pressed in its holder is in uniaxial strain, exactly",
          "[fem][elasticity][holder]") {
  // Clamped bottom, sides held at zero normal displacement and free to slide (the holder's
  // support), a uniform pressure p on the top: u = (0, 0, -p z / M) with the constrained
  // modulus M = lambda + 2 mu, sigma_zz = -p, sigma_xx = sigma_yy = -p lambda / M. Linear in
  // z, so P1 and P2 hold it to the solver's tolerance (1e-8 relative here). The supports
  // carry the whole load: the reaction is -(applied force). Traction-free sides (no holder)
  // let the sample bulge: the top then sinks measurably further (checked > 1 % more).
  const double E = 700e6, nu = 0.4, pressure = 1.2e3, c = 0.01;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double M = lambda + 2 * mu;
  for (unsigned int degree : {1u, 2u}) {
    dealii::Triangulation<3> tria;
    make_box(tria, 3, 2, 2, 0.03, 0.02, c);
    auto surface = extract_boundary_surface(tria, wear::meshes::sample_roles(false));
    double u_free = 0;
    for (const bool held : {true, false}) {
      INFO("P" << degree << (held ? ", held sides" : ", free sides"));
      surface.roles = wear::meshes::sample_roles(held);
      BoundaryFaceMap map(tria, surface);
      const auto F = top_traction_forces(surface, Vec3{0, 0, -pressure});
      ElasticityParameters p;
      p.degree = degree;
      p.relative_tolerance = 1e-13;
      ElasticitySolver solver(tria, map, p);
      const auto r = solver.run(F);
      CHECK(r.reaction_force.z == Approx(-r.applied_force.z).epsilon(1e-8));
      CHECK(std::abs(r.reaction_force.x) < 1e-8 * std::abs(r.applied_force.z));
      CHECK(std::abs(r.reaction_force.y) < 1e-8 * std::abs(r.applied_force.z));
      if (!held) {
        u_free = r.max_displacement;
        continue;
      }
      check_uniaxial_strain(solver, r, tria.n_active_cells(), pressure, c);
    }
    CHECK(u_free > 1.01 * pressure * c / M);
  }
}

TEST_CASE("elasticity: a part held on its sides and bottom by their roles, whatever their "
          "numbers, is in uniaxial strain",
          "[fem][elasticity][holder]") {
  // A scene part's labels (S1-held = 4001 on the sides, S5-held = 4005 underneath, S6 = 1006
  // on top): no face is clamped, the bottom rests on a support normal to z and the sides on
  // supports normal to x and y, all free to slide. A pressure p on top gives the uniaxial
  // strain of the sample in its holder, u = (0, 0, -p z / M): what holds the faces is the
  // role each label carries, not its number. The same labels without roles hold nothing,
  // and the solver refuses to start.
  const double pressure = 1.2e3, c = 0.01;
  dealii::Triangulation<3> tria;
  make_box(tria, 3, 2, 2, 0.03, 0.02, c);
  using wear::meshes::FaceRole;
  namespace label = wear::meshes::label;
  const std::map<int, int> part_label{{1, label::part_surface(FaceRole::held, 5)},
                                      {2, label::part_surface(FaceRole::held, 1)},
                                      {3, label::part_surface(FaceRole::wearing, 6)}};
  for (const auto& cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        cell->face(f)->set_boundary_id(
            dealii::types::boundary_id(part_label.at(int(cell->face(f)->boundary_id()))));
  wear::meshes::LabelRoles no_roles;
  const auto bare = extract_boundary_surface(tria, no_roles);
  BoundaryFaceMap bare_map(tria, bare);
  CHECK_THROWS_WITH(ElasticitySolver(tria, bare_map, ElasticityParameters{})
                        .run(wear::meshes::FaceField<Vec3>(
                            "force", "N", wear::meshes::Extensivity::extensive, bare)),
                    Catch::Contains("clamped"));
  wear::meshes::LabelRoles roles;
  roles.set(part_label.at(1), FaceRole::held);
  roles.set(part_label.at(2), FaceRole::held);
  roles.set(part_label.at(3), FaceRole::wearing);
  const auto surface = extract_boundary_surface(tria, roles);
  BoundaryFaceMap map(tria, surface);
  wear::meshes::FaceField<Vec3> F("force", "N", wear::meshes::Extensivity::extensive, surface);
  const auto a = wear::meshes::face_areas(surface);
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    if (surface.face_wears(f))
      F[f] = Vec3{0, 0, -pressure * a[f]};
  for (unsigned int degree : {1u, 2u}) {
    INFO("P" << degree);
    ElasticityParameters p;
    p.degree = degree;
    p.relative_tolerance = 1e-13;
    ElasticitySolver solver(tria, map, p);
    check_uniaxial_strain(solver, solver.run(F), tria.n_active_cells(), pressure, c);
  }
}

TEST_CASE("elasticity: reaction at the clamped face balances an arbitrary load",
          "[fem][elasticity]") {
  dealii::Triangulation<3> tria;
  make_box(tria, 4, 3, 2, 0.04, 0.03, 0.01);
  const auto surface = extract_boundary_surface(tria, wear::meshes::sample_roles(false));
  BoundaryFaceMap map(tria, surface);
  wear::meshes::FaceField<Vec3> F("force", "N", wear::meshes::Extensivity::extensive, surface);
  const auto c = wear::meshes::face_centroids(surface);
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    if (surface.face_labels[f] == 3) // a non-uniform load on the wear face
      F[f] = {0.3 * std::sin(100 * c[f].x), 0.2, -1 - 50 * c[f].y};
  for (unsigned int degree : {1u, 2u}) {
    ElasticityParameters p;
    p.degree = degree;
    p.relative_tolerance = 1e-12;
    ElasticitySolver solver(tria, map, p);
    const auto r = solver.run(F);
    const double scale = norm(r.applied_force);
    CHECK(norm(r.reaction_force + r.applied_force) < 1e-8 * scale);
    CHECK(r.iterations < 200);
  }
}

TEST_CASE("elasticity: a cantilever fin under a tip load follows beam theory",
          "[fem][elasticity]") {
  // Fin of 4 x 4 mm section, 40 mm tall, clamped at the bottom, shear load P on the top.
  // Timoshenko: d = P L^3 / (3 E I) + P L / (k G A), k = 10 (1 + nu) / (12 + 11 nu).
  const double b = 4e-3, L = 40e-3, P = 1.0, E = 700e6, nu = 0.4;
  const double I = b * b * b * b / 12, A = b * b, G = E / (2 * (1 + nu));
  const double k = 10 * (1 + nu) / (12 + 11 * nu);
  const double expected = P * L * L * L / (3 * E * I) + P * L / (k * G * A);
  std::vector<double> deflection;
  for (unsigned int n : {2u, 4u}) {
    dealii::Triangulation<3> tria;
    make_box(tria, n, n, 10 * n, b, b, L);
    const auto surface = extract_boundary_surface(tria, wear::meshes::sample_roles(false));
    BoundaryFaceMap map(tria, surface);
    const auto F = top_traction_forces(surface, Vec3{P / A, 0, 0});
    ElasticityParameters p;
    p.degree = 2;
    ElasticitySolver solver(tria, map, p);
    const auto r = solver.run(F);
    deflection.push_back(r.max_displacement);
  }
  INFO("beam theory " << expected << ", P2 " << deflection[0] << " (n = 2), " << deflection[1]
                      << " (n = 4)");
  CHECK(deflection[1] == Approx(expected).epsilon(0.02));
  CHECK(std::abs(deflection[1] - expected) <=
        std::abs(deflection[0] - expected) + 1e-12 * expected);
}

TEST_CASE("elasticity: bad input is refused with a message", "[fem][elasticity]") {
  dealii::Triangulation<3> tria;
  make_box(tria, 2, 2, 1, 0.02, 0.02, 0.01);
  const auto surface = extract_boundary_surface(tria, wear::meshes::sample_roles(false));
  BoundaryFaceMap map(tria, surface);
  ElasticityParameters p;
  p.degree = 3;
  CHECK_THROWS_WITH(ElasticitySolver(tria, map, p), Catch::Contains("Degree"));
  p.degree = 1;
  ElasticitySolver solver(tria, map, p);
  auto other = surface;
  other.bump_revision();
  wear::meshes::FaceField<Vec3> stale("force", "N", wear::meshes::Extensivity::extensive, other);
  CHECK_THROWS_WITH(solver.run(stale), Catch::Contains("revision"));
  wear::meshes::FaceField<Vec3> pressure("pressure", "Pa", wear::meshes::Extensivity::intensive,
                                         surface);
  CHECK_THROWS_WITH(solver.run(pressure), Catch::Contains("extensive"));
  auto relabelled = surface;
  relabelled.face_labels[0] = 7;
  CHECK_THROWS_WITH(BoundaryFaceMap(tria, relabelled), Catch::Contains("label"));
}

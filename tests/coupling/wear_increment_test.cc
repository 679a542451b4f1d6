// The wear increment of a stage on a flat wear face (a plate of 2 x 2 squares at z = 0, all
// labelled base top) against hand-computed values:
// - dV_f = A s V_f exactly, with s = 1 + c (sigma / sigma_ref)^m of the stress-informed law;
// - the vertex depth is sum(dV) / sum(area) around the vertex, against its longest edge;
// - adaptive amplification lowers A so the deepest vertex meets the cap (to 1e-9), and a
//   stage over the cap without it is refused naming the parameters.
#include "coupling/loop/wear_increment.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear;
using namespace wear::coupling;

namespace {
// 3 x 3 vertices at spacing h, 8 triangles, all on the wear face.
meshes::SurfaceMesh plate(double h) {
  meshes::SurfaceMesh m;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      m.vertices.push_back({i * h, j * h, 0});
  for (std::uint32_t j = 0; j < 2; ++j)
    for (std::uint32_t i = 0; i < 2; ++i) {
      const std::uint32_t a = 3 * j + i;
      m.triangles.push_back({a, a + 1, a + 4});
      m.triangles.push_back({a, a + 4, a + 3});
    }
  m.face_labels.assign(m.triangles.size(), meshes::label::base);
  m.roles.set(meshes::label::base, meshes::FaceRole::wearing);
  return m;
}

meshes::FaceField<double> uniform(const meshes::SurfaceMesh& m, const char* name,
                                  meshes::Extensivity kind, double value) {
  return {name, "-", kind, m, value};
}
} // namespace

TEST_CASE("wear increment: amplified, stress-scaled Archard volume per face", "[wear_increment]") {
  const double h = 1e-3, V = 2e-12; // [m], [m^3] per face
  const auto m = plate(h);
  CouplingParameters p;
  p.amplification = 20;
  p.max_depth_fraction = 10;
  const auto volume = uniform(m, "V", meshes::Extensivity::extensive, V);
  SECTION("no stress law: dV = A V") {
    const auto stress = uniform(m, "vM", meshes::Extensivity::intensive, 3e6);
    const auto w = wear_increment(m, volume, stress, p, true);
    for (std::size_t f = 0; f < m.n_faces(); ++f)
      CHECK(w.removed[f] == 20 * V);
    CHECK(w.dem_wear_volume == Approx(8 * V).epsilon(1e-15));
    CHECK(w.mean_stress_factor == 1);
    CHECK_FALSE(w.lowered);
    // Every face has area h^2 / 2, so each vertex recedes by A V / (h^2 / 2); the longest
    // edge at the centre vertex is the diagonal, at a corner vertex with one diagonal too.
    CHECK(w.depth.max_depth == Approx(20 * V / (h * h / 2)).epsilon(1e-12));
  }
  SECTION("stress-informed: s = 1 + c (sigma / sigma_ref)^m") {
    p.stress_informed = {true, 0.5, 2e6, 2.0};
    const auto stress = uniform(m, "vM", meshes::Extensivity::intensive, 3e6);
    const double s = 1 + 0.5 * std::pow(3e6 / 2e6, 2.0);
    const auto w = wear_increment(m, volume, stress, p, true);
    for (std::size_t f = 0; f < m.n_faces(); ++f)
      CHECK(w.removed[f] == Approx(20 * s * V).epsilon(1e-15));
    CHECK(w.mean_stress_factor == Approx(s).epsilon(1e-14));
  }
}

TEST_CASE("wear increment: the depth cap, with and without adaptive amplification",
          "[wear_increment]") {
  const double h = 1e-3;
  const auto m = plate(h);
  CouplingParameters p;
  p.amplification = 100;
  p.max_depth_fraction = 0.5;
  p.min_amplification = 1;
  // A volume that recedes every vertex by 0.1 mm at A = 1: 10 mm at A = 100.
  const auto volume = uniform(m, "V", meshes::Extensivity::extensive, 1e-4 * h * h / 2);
  const auto stress = uniform(m, "vM", meshes::Extensivity::intensive, 0);
  const auto declared = wear_increment(m, volume, stress, p, false);
  CHECK(declared.depth.max_depth == Approx(1e-2).epsilon(1e-12));
  CHECK(declared.depth.max_fraction > p.max_depth_fraction);
  try {
    check_depth_cap(declared, p, 3);
    FAIL("a stage over the cap was accepted");
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    CHECK(what.find("stage 3") != std::string::npos);
    CHECK(what.find("Coupling/Maximum depth fraction") != std::string::npos);
    CHECK(what.find("Coupling/Adaptive amplification") != std::string::npos);
  }
  p.adaptive_amplification = true;
  const auto adapted = wear_increment(m, volume, stress, p, true);
  REQUIRE(adapted.lowered);
  CHECK(adapted.declared_amplification == 100);
  CHECK(adapted.depth.max_fraction == Approx(p.max_depth_fraction).epsilon(1e-8));
  CHECK(adapted.depth.max_fraction <= p.max_depth_fraction);
  CHECK(adapted.amplification ==
        Approx(100 * p.max_depth_fraction / declared.depth.max_fraction).epsilon(1e-8));
  CHECK_NOTHROW(check_depth_cap(adapted, p, 3));
  // The removed volume scales with the amplification exactly as the depth does.
  CHECK(adapted.removed.sum() / declared.removed.sum() ==
        Approx(adapted.amplification / 100).epsilon(1e-12));
}

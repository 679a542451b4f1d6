// What is left of a part, against a shape whose figures are known: a round half-ellipsoid
// element (radius 4 mm, height 3 mm) on a 5 mm block. Its height above its foot is the
// element's height, its volume the half-ellipsoid's above the foot's plane to the
// discretisation's error, and the part's thinnest point is the base's height over the clamped
// bottom.
#include "meshes/constants.h"
#include "meshes/part_life.h"
#include "meshes/sample_generator.h"
#include "test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear::meshes;

TEST_CASE("a part's life figures: an element's height and volume, the part's thinnest point",
          "[part_life]") {
  const double r = 4e-3, c = 3e-3, base = 5e-3;
  const auto inside = [&](double x, double y) {
    return (std::pow(x - 8e-3, 2) + std::pow(y - 8e-3, 2)) / (r * r);
  };
  auto s = testing::height_field_block(
      64, 64, 16e-3, 16e-3,
      [&](double x, double y) { return base + c * std::sqrt(std::max(0.0, 1 - inside(x, y))); },
      [&](double x, double y) {
        return inside(x, y) < 1 ? label::convex_element(1, 1) : label::base;
      });
  s.roles = sample_roles(true);
  const auto life = part_life(s, 0.25e-3);
  REQUIRE(life.elements.size() == 1);
  const auto& e = life.elements.at(label::convex_element(1, 1));
  INFO("top " << e.top * 1e3 << " mm, foot " << e.foot * 1e3 << " mm, volume " << e.volume * 1e9
              << " mm^3");
  CHECK(e.top == Approx(base + c).epsilon(1e-12)); // the grid has a vertex at the centre
  // The foot: vertices on the element's rim, up to one grid step (0.25 mm) inside the circle.
  CHECK(e.foot >= base);
  CHECK(e.foot < base + 0.5e-3);
  // Above the foot's plane, t over the base: pi r^2 ((c - t) - (c^3 - t^3) / (3 c^2)).
  const double t = e.foot - base;
  const double above_foot = wear::pi * r * r * ((c - t) - (c * c * c - t * t * t) / (3 * c * c));
  CHECK(e.volume == Approx(above_foot).epsilon(0.02));
  CHECK(e.volume < 2.0 / 3.0 * wear::pi * r * r * c); // the half-ellipsoid's
  CHECK(life.n_standing == 1);
  CHECK(part_life(s, 4e-3).n_standing == 0); // nothing stands 4 mm high
  CHECK(life.thinnest == Approx(base).epsilon(1e-12));
  CHECK(life.volume == Approx(enclosed_volume(s)).epsilon(1e-15));
  CHECK(life.clamped_area == Approx(16e-3 * 16e-3).epsilon(1e-12));
}

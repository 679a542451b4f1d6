// What is left of a part, against shapes whose figures are known: a round half-ellipsoid
// element (radius 4 mm, height 3 mm) on a 5 mm block, labelled out to 0.3 mm beyond its
// rim so that its boundary lies on the base. Its height above its foot is the element's
// height, its volume the half-ellipsoid's to the discretisation's error, and the part's
// thinnest point is the base's height over the clamped bottom. On a base tilted by 0.15 the
// element keeps its height and volume; a remnant flush with that base stands at no height, a
// hollow in it at none either with a negative volume. Measured on the unworn footprint, the
// element keeps its volume when the worn surface's labels move up its flank.
#include "meshes/constants.h"
#include "meshes/part_life.h"
#include "meshes/sample_generator.h"
#include "test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear::meshes;

namespace {

const double r = 4e-3, c = 3e-3, base = 5e-3;
const int element = label::convex_element(1, 1);

// The block 16 mm x 16 mm on a 0.25 mm grid, its top base + slope x plus `bump` times the
// half-ellipsoid about (8, 8) mm; the faces whose centroid lies within r + 0.3 mm of the
// centre labelled as the element.
SurfaceMesh block(double slope, double bump, double label_radius = r + 0.3e-3) {
  const auto inside = [](double x, double y) {
    return (std::pow(x - 8e-3, 2) + std::pow(y - 8e-3, 2)) / (r * r);
  };
  auto s = testing::height_field_block(
      64, 64, 16e-3, 16e-3,
      [=](double x, double y) {
        return base + slope * x + bump * c * std::sqrt(std::max(0.0, 1 - inside(x, y)));
      },
      [=](double x, double y) {
        return std::sqrt(inside(x, y)) * r < label_radius ? element : label::base;
      });
  s.roles = sample_roles(true);
  return s;
}

} // namespace

TEST_CASE("a part's life figures: an element's height and volume, the part's thinnest point",
          "[part_life]") {
  const auto s = block(0, 1);
  const auto life = part_life(s, 0.25e-3);
  REQUIRE(life.elements.size() == 1);
  const auto& e = life.elements.at(element);
  INFO("height " << e.height * 1e3 << " mm, volume " << e.volume * 1e9 << " mm^3");
  CHECK(e.height == Approx(c).epsilon(1e-12)); // the grid has a vertex at the centre
  const double half_ellipsoid = 2.0 / 3.0 * wear::pi * r * r * c;
  CHECK(e.volume == Approx(half_ellipsoid).epsilon(0.02));
  CHECK(e.volume < half_ellipsoid); // the faces are chords
  CHECK(e.neighbours.size() == 1);
  CHECK(e.neighbours.count(label::base) == 1);
  CHECK(life.n_standing == 1);
  CHECK(part_life(s, 4e-3).n_standing == 0); // nothing stands 4 mm high
  CHECK(life.thinnest == Approx(base).epsilon(1e-12));
  CHECK(life.volume == Approx(enclosed_volume(s)).epsilon(1e-15));
  CHECK(life.clamped_area == Approx(16e-3 * 16e-3).epsilon(1e-12));
}

TEST_CASE("an element's foot follows a tilted base: the element keeps its height and volume, "
          "a remnant flush with the base or a hollow in it stands at no height",
          "[part_life]") {
  // A slope of 0.15 lifts the base by about 1.3 mm across the element's labelled footprint:
  // the mean height of its boundary as the foot would leave the flush remnant about 0.65 mm
  // high.
  const double slope = 0.15;
  const auto flat = convex_element_standing(block(0, 1)).at(element);
  const auto tilted = convex_element_standing(block(slope, 1)).at(element);
  CHECK(tilted.height == Approx(flat.height).epsilon(1e-9));
  CHECK(tilted.volume == Approx(flat.volume).epsilon(1e-9));
  const auto flush = convex_element_standing(block(slope, 0)).at(element);
  CHECK(flush.height == Approx(0).margin(1e-12));
  CHECK(flush.volume == Approx(0).margin(1e-18));
  const auto hollow = convex_element_standing(block(slope, -1)).at(element);
  CHECK(hollow.height == Approx(0).margin(1e-12));
  CHECK(hollow.volume == Approx(-flat.volume).epsilon(1e-9));
  auto s = block(slope, 0);
  CHECK(part_life(s, 0.25e-3).n_standing == 0);
}

TEST_CASE("an element measured on its unworn footprint does not move with the labels",
          "[part_life]") {
  // The element labelled out to 0.3 mm beyond its rim on the first surface; on a later one
  // the base's label has crept 1.5 mm up the flank (labelled to 2.5 mm from the centre). The
  // foot the labels span rises with them and the labelled volume falls by about 45 %; the
  // footprint's stays the element's. On the base tilted by 0.15 the footprint gives the flat
  // base's figures (the interpolant reproduces a plane); a flush remnant stands at none.
  const auto footprints = element_footprints(block(0, 1));
  REQUIRE(footprints.size() == 1);
  const auto flat = convex_element_standing(block(0, 1)).at(element);
  const auto first = footprint_standing(block(0, 1), footprints).at(element);
  CHECK(first.height == Approx(flat.height).epsilon(1e-12));
  CHECK(first.volume == Approx(flat.volume).epsilon(1e-12));
  const auto relabelled = block(0, 1, 2.5e-3);
  const auto by_labels = convex_element_standing(relabelled).at(element);
  INFO("labelled volume " << by_labels.volume * 1e9 << " mm^3, element " << flat.volume * 1e9
                          << " mm^3");
  CHECK(by_labels.volume < 0.7 * flat.volume); // the measure that moves with the labels
  const auto kept = footprint_standing(relabelled, footprints).at(element);
  CHECK(kept.volume == Approx(flat.volume).epsilon(1e-12));
  CHECK(kept.height == Approx(flat.height).epsilon(1e-12));
  const auto tilted = footprint_standing(block(0.15, 1, 2.5e-3), footprints).at(element);
  CHECK(tilted.volume == Approx(flat.volume).epsilon(1e-9));
  CHECK(tilted.height == Approx(flat.height).epsilon(1e-9));
  const auto flush = footprint_standing(block(0.15, 0), footprints).at(element);
  CHECK(flush.volume == Approx(0).margin(1e-18));
  CHECK(flush.height == Approx(0).margin(1e-12));
}

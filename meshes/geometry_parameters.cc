// Validation of geometry parameters. Every message names the case-file parameter.
//
// Pattern fit: all footprints are equal, axis-aligned ellipses; scaling the radial axis by
// semi_y / semi_x turns them into circles of radius semi_y, so two footprints overlap (or
// touch, which would make a non-manifold solid) exactly when their scaled centre distance
// is at most 2 semi_y. A footprint must also keep a gap to the base edges.
#include "meshes/geometry_parameters.h"

#include "meshes/constants.h"
#include "meshes/sample_generator.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace wear::meshes {

namespace {
void require(bool ok, const std::string& parameter, const std::string& why) {
  if (!ok)
    throw std::invalid_argument("parameter '" + parameter + "': " + why);
}
void positive(double v, const std::string& parameter) {
  require(std::isfinite(v) && v > 0, parameter,
          "must be a positive length in metres, got " + std::to_string(v));
}
} // namespace

void validate(const SampleGeometry& s) {
  const std::string S = "Geometry/Sample/", P = "Geometry/Sample/Pattern/";
  positive(s.length, S + "Length");
  positive(s.width, S + "Width");
  positive(s.thickness, S + "Thickness");
  positive(s.mesh_size, S + "Mesh size");
  positive(s.mesh_size_bottom, S + "Mesh size bottom");
  require(s.mesh_size >= 0.05e-3 && s.mesh_size <= 5e-3, S + "Mesh size",
          "must lie in [5e-5, 5e-3] m (0.25 to 2 mm is supported); got " +
              std::to_string(s.mesh_size) + " (a value in mm instead of m?)");
  require(s.mesh_size_bottom >= s.mesh_size, S + "Mesh size bottom",
          "must not be smaller than 'Mesh size'");
  if (!s.convex)
    return;
  const auto& p = s.pattern;
  positive(p.a, P + "a");
  positive(p.b, P + "b");
  positive(p.c, P + "c");
  positive(p.d, P + "d");
  positive(p.h, P + "h");
  require(p.n_columns >= 1 && p.n_columns <= 9, P + "Number of columns", "must be 1..9");
  require(p.elements_per_column >= 1 && p.elements_per_column <= 9, P + "Elements per column",
          "must be 1..9");
  require(!p.stagger || p.elements_per_column >= 2 || p.n_columns == 1, P + "Stagger",
          "needs at least 2 elements per column");
  require(p.first_column_offset >= 0, P + "First column offset", "must not be negative");
  const auto sites = element_sites(s);
  const double edge_gap = 0.1e-3;
  for (const auto& e : sites) {
    const std::string which =
        " (element C" + std::to_string(e.column) + std::to_string(e.element) + ")";
    require(std::abs(e.x) + e.semi_x <= s.width / 2 - edge_gap, e.semi_x == p.a ? P + "a" : P + "c",
            "the pattern does not fit radially on the base" + which);
    require(std::abs(e.y) + e.semi_y <= s.length / 2 - edge_gap,
            (e.semi_y == p.a ? P + "a" : P + "d"),
            "the pattern does not fit along the flow on the base" + which +
                "; check also 'First column offset' and 'Number of columns'");
  }
  for (std::size_t i = 0; i < sites.size(); ++i)
    for (std::size_t j = i + 1; j < sites.size(); ++j) {
      const double dx = (sites[i].x - sites[j].x) * sites[i].semi_y / sites[i].semi_x;
      const double dy = sites[i].y - sites[j].y;
      const bool same_column = sites[i].column == sites[j].column;
      require(std::hypot(dx, dy) > 2 * sites[i].semi_y * (1 + 1e-3),
              same_column ? P + "c" : P + "d",
              "elements C" + std::to_string(sites[i].column) + std::to_string(sites[i].element) +
                  " and C" + std::to_string(sites[j].column) + std::to_string(sites[j].element) +
                  " overlap");
    }
}

void validate(const GeometryParameters& g) {
  validate(g.sample);
  const std::string T = "Geometry/Tester/";
  const auto& t = g.tester;
  positive(t.inner_radius, T + "Inner radius");
  require(t.outer_radius > t.inner_radius, T + "Outer radius", "must exceed 'Inner radius'");
  require(t.sector_angle_deg > 0 && t.sector_angle_deg <= 360, T + "Sector angle",
          "must lie in (0, 360] degrees");
  positive(t.wall_height, T + "Wall height");
  positive(t.wall_mesh_size, T + "Wall mesh size");
  if (t.consolidator) {
    require(t.consolidator_height > 0 && t.consolidator_height < t.wall_height,
            T + "Consolidator height", "must lie between the floor and the wall top");
    require(t.consolidator_extent_deg > 0 && t.consolidator_extent_deg < t.sector_angle_deg,
            T + "Consolidator extent", "must be positive and smaller than the sector");
  }
  // The holder's frame adds its rim width around and under the sample.
  if (t.holder)
    require(std::isfinite(t.holder_rim_width) && t.holder_rim_width > 0, T + "Holder rim width",
            "must be a positive length in metres, got " + std::to_string(t.holder_rim_width) +
                " (or set Geometry/Tester/Holder = none)");
  const double rim = t.holder ? t.holder_rim_width : 0;
  const std::string what = t.holder ? "the sample in its holder" : "the sample";
  const std::string L = "Geometry/Placement/";
  const auto& p = g.placement;
  require(p.radius - g.sample.width / 2 - rim > t.inner_radius &&
              p.radius + g.sample.width / 2 + rim < t.outer_radius,
          L + "Radius", what + " must lie between the inner and outer walls");
  require(std::abs(p.incline_deg) < 30, L + "Incline", "must be below 30 degrees");
  // The lowest point: the bottom (of the holder) at the lower end of the inclined sample.
  const double half = g.sample.length / 2 + rim, depth = g.sample.thickness + rim;
  const double incline = std::abs(p.incline_deg) * pi / 180;
  require(p.wear_face_height - depth * std::cos(incline) - half * std::sin(incline) > 0,
          L + "Wear face height", what + " would cut through the floor");
}

} // namespace wear::meshes

// A clump fitted to a closed surface by greedy sphere packing.
//
// The solid's signed distance phi is sampled on a grid (the sign from meshes::signed_distance,
// the distance from meshes::SurfaceLocator; negative inside); a node x inside holds the largest
// inscribed sphere about it, of radius -phi(x). The candidates are the nodes where -phi is a local
// maximum over the 26 neighbours (the grid's trace of the medial axis: centres of maximal inscribed
// spheres). Each round adds the candidate whose sphere covers the most inside nodes that no member
// covers yet (candidates taken by falling radius, so that those whose whole ball holds fewer nodes
// than the best gain so far are skipped), its centre then moved within the grid cell about it to
// the point farthest from the surface (a pattern search on the exact distance, so that the member
// does not lose the node's offset from the medial axis, up to a spacing, from its radius), until
// the union's volume (integrated exactly, clump_shape) is within the stated error of the solid's
// (meshes::enclosed_volume) or the member count is reached. Every member is inscribed, so the
// union lies inside the solid to the grid's spacing and its volume approaches the solid's from
// below; an angular solid's corners are what the few spheres leave out.
#include "dem/scene/clump_fit.h"

#include "meshes/level_set_grid.h"
#include "meshes/surface_locator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace wear::dem {

namespace {

/// The point within h of x (a cube) farthest from the surface, as a sphere touching it: a
/// pattern search on the exact distance, steps h/2 down to h/256.
ClumpMember deepest_point_near(const meshes::SurfaceLocator& locator, const Vec3& x, double h) {
  ClumpMember best{x, locator.nearest(x).distance};
  for (double step = 0.5 * h; step > h / 256; step *= 0.5) {
    bool moved = true;
    while (moved) {
      moved = false;
      for (int d = 0; d < 3; ++d)
        for (const double sign : {-1.0, 1.0}) {
          Vec3 y = best.centre;
          y[d] += sign * step;
          if (std::abs(y[d] - x[d]) > h)
            continue;
          const double r = locator.nearest(y).distance;
          if (r > best.radius)
            best = {y, r}, moved = true;
        }
    }
  }
  return best;
}

} // namespace

ClumpFit fit_clump(const meshes::SurfaceMesh& s, const ClumpFitParameters& p,
                   const std::string& what) {
  if (p.max_spheres < 1 || p.max_spheres > 64)
    throw std::invalid_argument(what + ": the clump fit takes 1 to 64 spheres, not " +
                                std::to_string(p.max_spheres));
  if (!(p.volume_error > 0 && p.volume_error < 1))
    throw std::invalid_argument(what + ": the fit's volume error must lie in (0, 1), not " +
                                std::to_string(p.volume_error));
  if (p.cells_per_extent < 8 || p.cells_per_extent > 512)
    throw std::invalid_argument(what +
                                ": the fit's grid takes 8 to 512 cells along the "
                                "largest extent, not " +
                                std::to_string(p.cells_per_extent));
  ClumpFit fit;
  fit.solid_volume = meshes::enclosed_volume(s);
  if (!(fit.solid_volume > 0))
    throw std::invalid_argument(what + " encloses no volume (" + std::to_string(fit.solid_volume) +
                                " m^3): a clump is fitted to a closed, outward-oriented surface");
  const meshes::BoundingBox box = meshes::bounding_box(s.vertices.data(), s.vertices.size());
  const Vec3 ext = box.extent();
  const double h = std::max({ext.x, ext.y, ext.z}) / p.cells_per_extent;
  meshes::LevelSetGrid grid(box, h, 2 * h);
  // The sign from a narrow band, the distance of the inside nodes from the locator (a band as
  // wide as the solid would visit every node from every face).
  meshes::signed_distance(s, grid, 2 * h);
  const meshes::SurfaceLocator locator(s);
  auto& phi = grid.value;
#pragma omp parallel for schedule(static)
  for (std::size_t n = 0; n < phi.size(); ++n)
    if (phi[n] < 0)
      phi[n] = -locator.nearest(grid.node(n)).distance;
  std::vector<std::size_t> candidates;
  std::vector<char> inside(phi.size(), 0);
  for (int k = 1; k + 1 < grid.n(2); ++k)
    for (int j = 1; j + 1 < grid.n(1); ++j)
      for (int i = 1; i + 1 < grid.n(0); ++i) {
        const std::size_t n = grid.index(i, j, k);
        if (phi[n] >= 0)
          continue;
        inside[n] = 1;
        bool ridge = true;
        for (int dk = -1; dk <= 1 && ridge; ++dk)
          for (int dj = -1; dj <= 1 && ridge; ++dj)
            for (int di = -1; di <= 1 && ridge; ++di)
              ridge = phi[grid.index(i + di, j + dj, k + dk)] >= phi[n];
        if (ridge)
          candidates.push_back(n);
      }
  if (candidates.empty())
    throw std::invalid_argument(what + " is thinner than the fit's grid spacing (" +
                                std::to_string(h) + " m): raise the cells per extent");
  // By falling radius, ties by index (the order decides the fit, so it is total).
  std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
    return phi[a] < phi[b] || (phi[a] == phi[b] && a < b);
  });
  std::vector<char> covered(phi.size(), 0);
  // Visits the inside nodes within the sphere of candidate c.
  const auto for_ball = [&](std::size_t c, auto&& visit) {
    const Vec3 x = grid.node(c);
    const double r = -phi[c];
    int first[3], last[3];
    grid.node_range(x - Vec3{r, r, r}, x + Vec3{r, r, r}, first, last);
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i) {
          const std::size_t n = grid.index(i, j, k);
          if (inside[n] && meshes::norm2(grid.node(i, j, k) - x) <= r * r)
            visit(n);
        }
  };
  fit.clump.name = what;
  fit.volume_error = 1;
  while (int(fit.clump.members.size()) < p.max_spheres && fit.volume_error > p.volume_error) {
    std::size_t best = candidates.front(), best_gain = 0;
    for (const std::size_t c : candidates) {
      const double r_cells = -phi[c] / h; // the ball holds at most (2 r/h + 1)^3 nodes
      if (std::pow(2 * r_cells + 1, 3) < double(best_gain))
        break;
      std::size_t gain = 0;
      for_ball(c, [&](std::size_t n) { gain += !covered[n]; });
      if (gain > best_gain)
        best = c, best_gain = gain;
    }
    if (best_gain == 0)
      break; // every inside node is covered: more spheres add nothing at this grid
    for_ball(best, [&](std::size_t n) { covered[n] = 1; });
    fit.clump.members.push_back(deepest_point_near(locator, grid.node(best), h));
    fit.volume_error =
        std::abs(clump_shape(fit.clump).volume - fit.solid_volume) / fit.solid_volume;
  }
  if (fit.volume_error > p.volume_error)
    throw std::runtime_error(what + ": " + std::to_string(fit.clump.members.size()) +
                             " inscribed spheres leave a volume error of " +
                             std::to_string(fit.volume_error) + ", above the " +
                             std::to_string(p.volume_error) +
                             " asked for: allow more spheres or a larger error");
  return fit;
}

} // namespace wear::dem

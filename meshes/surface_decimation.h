#pragma once
// Coarsening of a fine triangle surface (the zero set of a grid, millions of faces, many of
// them slivers) into one that gmsh can reparametrise: edges collapsed in order of the error
// they cause, each vertex kept where it was (so plane regions stay exactly plane), label
// boundaries kept as curves.
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace wear::meshes {

struct DecimationParameters {
  /// Root-mean-square distance of a kept vertex to the planes of the input faces it now
  /// stands for (and, on a label boundary, to the boundary's edges) must stay below this. [m]
  double max_error = 0.02e-3;
  double max_edge = 1e-3; ///< [m] no collapse makes an edge longer
  /// A collapse may turn no face's normal by more than acos(this).
  double min_normal_cos = 0.7;
  /// A collapse may leave no face of quality 4 sqrt(3) A / (sum of squared edges) below this,
  /// unless it improves the worst face it replaces.
  double min_quality = 0.1;
};

struct DecimationReport {
  std::size_t n_faces_before = 0, n_faces_after = 0;
  std::size_t n_collapses = 0;
  double seconds = 0;
};

/// Coarsens `m` in place where it is flat (flat_region_coarsening limits) with the edges in
/// `curves` (vertex pairs: sharp edges inside a label, as isotropic_remesh returns them) kept
/// as the label boundaries are: each region bounded by curves and label boundaries is
/// coarsened as a label of its own, so no face comes to span a curve (a side's vertical
/// corner cut into a face normal to no axis). The faces keep their labels.
DecimationReport
coarsen_flat_regions(SurfaceMesh& m,
                     const std::vector<std::pair<std::uint32_t, std::uint32_t>>& curves,
                     double max_edge, double max_error);

/// The limits that coarsen an isotropic surface where it is flat and keep it where it curves:
/// edges up to `max_edge` [m], a kept vertex within `max_error` [m] (root mean square) of the
/// planes it stands for, no face below quality 0.3 (as an isotropic remeshing leaves them:
/// a volume mesher keeps its triangles). A feature narrower than max_edge is not collapsed
/// away, as a remeshing at that edge length would (a cone 1.5 mm wide under 2 mm edges).
DecimationParameters flat_region_coarsening(double max_edge, double max_error);

/// Coarsens the closed, labelled surface `m` in place by half-edge collapses (a vertex moves
/// onto a neighbour), cheapest first by the quadric error of Garland and Heckbert, under the
/// limits of `p`: the link condition keeps it a closed manifold, a vertex where three labels
/// meet or a label boundary turns is never removed, a boundary vertex only along the boundary.
/// Rounds of collapses alternate with Delaunay flips in nearly flat regions.
DecimationReport decimate(SurfaceMesh& m, const DecimationParameters& p);

} // namespace wear::meshes

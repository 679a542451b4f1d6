#pragma once
// Local mending of folds in a triangle surface: an edge whose two faces turn back onto each
// other is removed by an edge flip, or by collapsing or moving one of its vertices.
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <vector>

namespace wear::meshes {

struct FoldMendingParameters {
  /// An edge folds when the cosine of the angle between its two faces' normals is below this
  /// (-0.5: the faces turn back by more than 120 degrees).
  double fold_cos = -0.5;
  /// [m] a flip or a collapse may move the surface by at most this: the distance of the
  /// collapsed vertex from its new faces, the height of the tetrahedron a flip sweeps.
  double max_shift = 0.25e-3;
  int max_passes = 8; ///< rounds of finding the folds and mending each once
};

struct FoldMending {
  std::size_t n_folds_before = 0; ///< folded edges found at the start
  std::size_t n_folds_after = 0;  ///< folded edges left (none could be mended)
  std::size_t n_flips = 0, n_collapses = 0, n_moves = 0;
  /// old vertex index -> new one (vertices are renumbered after a collapse); a collapsed
  /// vertex maps to the vertex it went into, a vertex no face used to no_vertex
  std::vector<std::uint32_t> new_index;
};

/// Mends the folded edges of the closed, consistently oriented surface `m` in place. For each
/// face at a fold the candidates are: the flip of each of its edges between two faces of one
/// label, and for each of its vertices that is `removable` (per vertex) and whose faces all
/// have one label its collapse into each vertex next to it (the link condition kept) and its
/// move a quarter, half, three quarters or all the way to its neighbours' centroid. A
/// candidate is taken when no face it makes folds against its neighbours, none is degenerate
/// and the surface moves by at most `max_shift` (which keeps a sharp edge from being flipped
/// away); among them the one with the largest sum of the smallest angle cosine across the
/// edges it touches and the worst triangle quality, if that sum beats the face's own. A collapse
/// that leaves a sliver (triangle quality below 0.1) is followed by the flip that mends it under
/// the same rules. Labels, closedness and orientation are kept; the revision is bumped when
/// anything changed.
FoldMending mend_folds(SurfaceMesh& m, const std::vector<char>& removable,
                       const FoldMendingParameters& p);

} // namespace wear::meshes

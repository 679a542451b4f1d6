#pragma once
// The shape of a patch of a triangulated surface, as gmsh's reparametrisation of discrete
// surfaces sees it, and the cuts that turn a patch with holes into pieces without holes.
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace wear::fem {

struct PatchShape {
  std::size_t n_faces = 0;
  int n_loops = 0; ///< boundary loops: 1 for a disk, 1 + holes otherwise (genus 0 assumed)
  /// [-] largest distance of a corner from the least-squares plane of the corners, over the
  /// diagonal of their bounding box (gmsh's planarity measure)
  double relative_deviation = 0;
  /// [-] smallest cosine between a face normal and that plane's normal (oriented along the
  /// patch's area vector): above 0, the patch projects onto the plane without folding
  double min_normal_cos = 1;
};

/// The shape of the patch made of `faces` of `m` (connected, consistently oriented).
PatchShape patch_shape(const meshes::SurfaceMesh& m, const std::vector<std::uint32_t>& faces);

using Edge = std::pair<std::uint32_t, std::uint32_t>; ///< vertex indices, smaller first

/// Interior edges of the patch `faces` along which to cut it so that no piece keeps a hole:
/// from every hole two vertex-disjoint shortest paths to the longest boundary loop or an
/// earlier cut, so each hole opens into the boundary of the two pieces beside it. Empty for
/// a patch without holes; a hole no path leaves is left uncut.
std::vector<Edge> hole_cuts(const meshes::SurfaceMesh& m, const std::vector<std::uint32_t>& faces);

} // namespace wear::fem

#pragma once
// Putting the implicit recession's new surface back onto the old one where the front has not
// passed (and onto the clamped and held faces everywhere), and the volume its chords cut off
// back where they cut it (meshes/implicit_recession.h).
#include "meshes/level_set_grid.h"
#include "meshes/surface_mesh.h"

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace wear::meshes {

/// The old sharp edges between two patches of a surface (`patch` per face), by pair of
/// patches.
class PatchSeams {
public:
  PatchSeams(const SurfaceMesh& s, const std::vector<int>& patch);
  /// The point of the edges between patches p and q nearest x, and its distance [m]
  /// (infinity where the two patches do not meet).
  std::pair<Vec3, double> nearest(int p, int q, const Vec3& x) const;

private:
  const SurfaceMesh& surface_;
  std::map<std::pair<int, int>, std::vector<std::pair<std::uint32_t, std::uint32_t>>> edges_;
};

/// Vertices of `fresh` go back onto the old surface `old` where the front did not reach it
/// (`reached`, at an old point), and those between clamped and held patches only wherever it
/// did: onto their patch (`old_patch` per old face, `patch_of_face` per new face), onto the old
/// edges between their two patches, or onto the old corner of their three or more; moves
/// longer than `reach` [m] are not made. Returns, per vertex, whether it was moved.
std::vector<char> snap_untouched_vertices(const SurfaceMesh& old, const std::vector<int>& old_patch,
                                          const PatchSeams& seams,
                                          const std::vector<int>& patch_of_face,
                                          const std::function<bool(const Vec3&)>& reached,
                                          double reach, SurfaceMesh& fresh);

/// The vertices of the clamped and held faces of `fresh` (those not `restored`) go back onto
/// the nearest clamped or held face of `old`, when it lies within `reach` [m].
void snap_fixed_vertices(const SurfaceMesh& old, double reach, const std::vector<char>& restored,
                         SurfaceMesh& fresh);

struct ChordRestoration {
  double uniform_offset = 0; ///< [m] the uniform offset of the movable vertices, outward
  /// vertex rings around a fold within which the vertices were held still (0: nowhere)
  int held_rings = 0;
  /// [m^3] enclosed volume above `target` left because every offset folded (0: none)
  double volume_not_restored = 0;
};

/// Each `movable` vertex of `m` moves along its normal by the area-weighted mean gap of its
/// faces to `reference` (the finer surface its vertices lie on), then all of them by one
/// uniform offset, so that `m` encloses `target` [m^3]. Where that folds `m` (an edge whose
/// faces' normals have a cosine below `fold_cos`, a crossing or an inverted face), the
/// vertices within 1, 2, 4, 8 rings of the fold stay still; when it folds even then, `m` is
/// left as it was.
ChordRestoration chord_restoring_offset(SurfaceMesh& m, const SurfaceMesh& reference,
                                        const std::vector<char>& movable, double target,
                                        double fold_cos);

} // namespace wear::meshes

#pragma once
// Putting the implicit recession's new surface back onto the old one where the front has not
// passed (and onto the clamped and held faces everywhere), and the volume its chords cut off
// back where they cut it (meshes/implicit_recession.h).
#include "meshes/level_set_grid.h"
#include "meshes/surface_mesh.h"

#include <vector>

namespace wear::meshes {

/// Whether the front changed the part in the grid cell of x (a corner where psi != phi).
bool front_passed(const LevelSetGrid& phi, const LevelSetGrid& psi, const Vec3& x);

/// Vertices of `fresh` where the front has not passed, and those between clamped and held
/// patches only wherever it passed, go back onto the old surface `old`:
/// onto their patch (`old_patch` per old face, `patch_of_face` per new face), onto the old
/// edges between their two patches, or onto the old corner of their three or more; moves
/// longer than the grid spacing are not made. Returns, per vertex, whether it was moved.
std::vector<char> snap_untouched_vertices(const SurfaceMesh& old, const std::vector<int>& old_patch,
                                          const LevelSetGrid& phi, const LevelSetGrid& psi,
                                          const std::vector<int>& patch_of_face,
                                          SurfaceMesh& fresh);

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
/// faces lie on each other, a crossing or an inverted face), the vertices within 1, 2, 4, 8
/// rings of the fold stay still; when it folds even then, `m` is left as it was.
ChordRestoration chord_restoring_offset(SurfaceMesh& m, const SurfaceMesh& reference,
                                        const std::vector<char>& movable, double target);

} // namespace wear::meshes

#pragma once
// The recession of a worn surface: how far, and along what, its vertices move for a removed
// volume per face. One home for both deformation schemes: the reference node-moving scheme
// (dem/wear/reference_deformation) moves the vertices by area_weighted_recession as it is;
// the staged scheme (fem/) keeps the vertices shared with the unworn surface on it and scales
// the field until the enclosed volume drops by exactly the removed volume
// (volume_exact_recession), and gives back the volume a remesh cut off with the same field
// (volume_restoring_offset). Where a recession would fold, the removed volume is spread over
// the fold's neighbourhood first (spread_removed_volume).
#include "meshes/mesh_quality.h"
#include "meshes/surface_mesh.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace wear::meshes {

/// Per vertex: the area-weighted mean depth D_v = sum_f V_f / sum_f A_f over the wearing
/// faces f around the vertex (labels base and C<j><k>) [m]; zero for vertices without
/// wearing faces (or whose wearing faces have no area). `removed_volume` is per face [m^3],
/// extensive.
std::vector<double> area_weighted_depth(const SurfaceMesh& m,
                                        const std::vector<double>& removed_volume);

/// Per vertex: -n_v * D_v (area_weighted_depth), n_v the normalized area-weighted normal of
/// the wearing faces around the vertex; zero for vertices without wearing faces. The node
/// displacement of the reference scheme, and the direction field of the staged one.
std::vector<Vec3> area_weighted_recession(const SurfaceMesh& m,
                                          const std::vector<double>& removed_volume);

/// The scale s of the displacement field `unit` [m per unit of s] at which the enclosed
/// volume drops by `target` [m^3] (negative: grows), by secant steps from s = first_guess and
/// s = 0 (first_guess 0: a linearised first step), to round-off of the volume; the drop
/// reached goes to `achieved`.
double scale_to_volume_loss(const SurfaceMesh& surface, const std::vector<Vec3>& unit,
                            double target, double* achieved, double first_guess = 1);

struct Recession {
  std::vector<Vec3> displacement; ///< [m] per surface vertex (zero off the wear face)
  double removed_volume = 0;      ///< [m^3] requested (sum of the field)
  double swept_volume = 0;        ///< [m^3] enclosed-volume loss after correction
  double scale = 1;               ///< correction applied to the area-weighted depths
  /// The secant scaling can end short of the target (an offset that stops sweeping volume):
  /// true when the swept volume misses the requested one by more than 1e-4 of it.
  bool missed_target() const {
    return std::abs(swept_volume - removed_volume) > 1e-4 * std::abs(removed_volume);
  }
};

/// The staged scheme's recession: area_weighted_recession with the vertices the wear face
/// shares with the unworn surface kept on that surface (meshes::sliding_constraints: down a
/// flat side, along a crease), then scaled (a few secant steps) so that the enclosed volume of
/// the closed surface drops by exactly the removed volume. Unlike the reference scheme, the
/// volume is exact and the unworn surface keeps its shape. Throws for a field of the wrong
/// size or a negative volume.
Recession volume_exact_recession(const SurfaceMesh& surface,
                                 const std::vector<double>& removed_volume);

/// A uniform offset of the wear face along its inward vertex normals (outward for a negative
/// scale; the staged recession of a uniform depth) that brings the enclosed volume to
/// `target_volume`: gives back the volume a remeshing cut off as chords across curved
/// regions. removed_volume = current - target. Faces marked in `held_faces` (one flag per
/// face) do not move, and the rest takes their share.
Recession volume_restoring_offset(const SurfaceMesh& surface, double target_volume,
                                  const std::vector<char>* held_faces = nullptr);

/// Per face: 1 for the seeds and the faces within `rings` vertex rings of them, else 0.
std::vector<char> faces_within_rings(const SurfaceMesh& m, const std::vector<std::uint32_t>& seeds,
                                     int rings);

/// An offset of the vertices of `m` that folds it (beside a low remnant of a worn element, at
/// a concave corner) is held still near the fold while the rest of the surface takes its
/// share. `attempt(held)` makes the offset with the vertices of the faces marked in `held`
/// (one flag per face of m) kept still, and returns its candidate's quality; the first valid
/// candidate is the one taken. Tried with no face held, then with the faces within 1, 2, 4
/// and 8 vertex rings of every fold found so far held. Returns the rings held at the attempt
/// taken (0: none), or -1 when every attempt folded.
int hold_still_around_folds(const SurfaceMesh& m,
                            const std::function<SurfaceQuality(const std::vector<char>&)>& attempt);

/// Spreads removed volume [m^3 per face] around `seeds` (e.g. the faces where a recession
/// folds): within `rings` vertex rings of a seed, over wearing faces only, the depth V_f / A_f
/// diffuses between faces sharing an edge (rings^2 explicit steps, so about `rings` faces
/// far). The total is kept to round-off and no face goes negative. Returns the volume moved
/// between faces [m^3].
double spread_removed_volume(const SurfaceMesh& m, std::vector<double>& removed_volume,
                             const std::vector<std::uint32_t>& seeds, int rings);

} // namespace wear::meshes

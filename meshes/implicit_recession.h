#pragma once
// The recession of a worn part on an implicit representation: the part's signed distance on a
// grid, the removed material as a union of balls around the receding faces, the new surface
// as the zero set of both. It cannot fold: a crest recedes, an element worn away vanishes, a
// plate worn through opens a hole, and two hollows that meet merge. Used where the explicit
// recession (meshes/recession.h) would fold or a topology must change.
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace wear::meshes {

struct ImplicitRecessionParameters {
  double spacing = 0.25e-3; ///< [m] grid spacing: the tolerance of the new worn shape
  /// A convex element (label C<j><k>) whose top stands at most this far above the wearing
  /// faces around it is worn away: its faces join the label around it. [m]
  double vanish_height = 0.25e-3;
  /// Relative tolerance of each wearing label's removed volume against the asked one.
  double volume_tolerance = 1e-4;
  /// true: the depth is scaled per label so that each label loses the volume asked of it (up
  /// to 1.5 times its depth; a label asked for more than lies under it, an element worn away,
  /// leaves the rest to a common factor); false: one common factor for the total only, every
  /// face receding by its own depth times it (a uniform depth recedes uniformly).
  bool volume_per_label = true;
  int max_iterations = 12; ///< of the per-label depth scaling
  /// Faces of one label meeting at more than this angle belong to different patches of the
  /// old surface; the new faces keep their patch, and the edges between patches are handed to
  /// the remesher as feature curves (the grid's zero set cuts sharp edges into chamfers
  /// whose own angles would split them into slivers of patches). [deg]
  double feature_angle_deg = 60;
  /// The zero set is coarsened (meshes/surface_decimation.h) to edges of at most this
  /// length, each vertex within a tenth of the spacing of the planes it stands for. [m]
  double max_edge = 1e-3;
  /// The coarsened zero set is then remeshed isotropically (meshes/isotropic_remeshing.h) to
  /// edges of about this length, so that a volume mesher can keep its triangles. [m]
  double target_edge = 1e-3;
  /// 0: target_edge everywhere. Longer: the remeshed surface is then coarsened where that
  /// changes its shape by little (meshes/surface_decimation.h, flat_region_coarsening), to
  /// edges up to this length on flat regions, while curved ones (a worn element's remnant
  /// narrower than this, a rounded crest) keep their target_edge triangles. [m]
  double flat_edge = 0;
  /// The coarsening's error limit, the root-mean-square distance of a kept vertex to the
  /// planes of the faces it stands for, as a fraction of the spacing.
  double flat_error_fraction = 0.5;
};

struct ImplicitRecession {
  SurfaceMesh surface;              ///< closed, outward, labelled; revision = input's + 1
  double asked_volume = 0;          ///< [m^3] sum of the removed volume asked
  double removed_volume = 0;        ///< [m^3] enclosed volume before minus after
  std::map<int, double> asked;      ///< [m^3] per wearing label
  std::map<int, double> removed;    ///< [m^3] per label, as the grid books the removed material
  std::size_t n_restored = 0;       ///< vertices put back onto the old surface (front not there)
  std::size_t n_projected = 0;      ///< vertices of the grid's zero set put onto the exact front
  std::size_t n_teeth_joined = 0;   ///< faces of no width joined to the label beside them
  std::size_t n_folds_mended = 0;   ///< folded edges the remeshing left, mended (fold_mending.h)
  std::size_t n_folds_left = 0;     ///< folded edges the mending could not mend
  std::vector<int> vanished_labels; ///< labels worn away (their faces joined a neighbour)
  /// closed pieces of the grid's zero set under 8 spacing^3 dropped (fragments the front cut
  /// off the part), and the volume they enclosed [m^3], removed with the asked volume (it is
  /// in removed_volume)
  std::size_t n_fragments = 0;
  double fragment_volume = 0;
  double worn_through_area = 0; ///< [m^2] clamped area removed (a hole through the part)
  /// [m^3] volume the grid's zero set of the input loses against it (the chords of the
  /// interpolant across edges and curved faces), given back where the front has not passed
  /// by putting the surface back onto the old one, and where it has by the offset below
  double grid_loss = 0;
  /// [m^3] enclosed volume the coarsening and remeshing cut off where the front passed (their
  /// chords, and the grid's own), given back by an offset of each vertex there by its faces'
  /// gap to the grid's zero set, then a uniform one
  double coarsening_loss = 0;
  double uniform_offset = 0; ///< [m] that uniform offset of the wearing vertices, outward
  /// vertex rings around a fold within which that offset was held still (0: nowhere)
  int restore_held_rings = 0;
  /// [m^3] volume the offset did not give back because it folded at 8 rings (0: none)
  double volume_not_restored = 0;
  std::size_t n_nodes = 0;
  std::size_t n_fine_faces = 0; ///< of the grid's zero set, before coarsening
  double min_face_quality = 0;  ///< of the new surface (4 sqrt(3) A / sum of squared edges)
  int n_iterations = 0;
  double seconds = 0;
};

/// Recedes the closed, outward surface `s` by `removed_volume` [m^3 per face, extensive] on its
/// wearing faces: each face f by the depth s_L V_f / A_f, s_L per label chosen so that every
/// label's removed volume matches its asked volume, the union of the balls of those radii
/// around the faces removed. New faces take the label of the old face they lie on or, on the
/// receded front, of the face that removed the material there. Throws for a field of the wrong
/// size, a negative volume or an open surface.
ImplicitRecession implicit_recession(const SurfaceMesh& s,
                                     const std::vector<double>& removed_volume,
                                     const ImplicitRecessionParameters& p);

} // namespace wear::meshes

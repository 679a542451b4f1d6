#pragma once
// The sample as it wears: its tetrahedral mesh, boundary surface and face map, advanced by
// one stage of removed volume at a time, moved or remeshed so that no inverted or degenerate
// cell is ever passed on, with the accumulated wear carried across remeshes.
#include "fem/boundary_face_map.h"
#include "fem/mesh_motion.h"
#include "fem/remesher.h"
#include "meshes/face_field.h"
#include "meshes/implicit_recession.h"

#include <deal.II/grid/tria.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace wear::meshes {
class FaceTransfer; // meshes/face_transfer.h
} // namespace wear::meshes

namespace wear::fem {

/// How a stage's wear moves the worn surface.
enum class SurfaceEvolution {
  /// Vertices recede along their normals (meshes::volume_exact_recession) in increments,
  /// halved and spread where the surface would fold; the stage stops where it still folds.
  explicit_only,
  /// As explicit_only, and where the surface would still fold, the rest of the stage is
  /// taken by the implicit recession (meshes::implicit_recession) and remeshed.
  explicit_then_implicit,
  /// Every stage by the implicit recession and a remesh: crests, vanishing elements and
  /// holes in any stage.
  implicit,
};

/// Defaults declared here only; the FEM subsection of a case file sets some fields
/// (FemParameters, fem/fem_parameters.h).
struct WornSampleParameters {
  SurfaceEvolution evolution = SurfaceEvolution::explicit_then_implicit;
  meshes::ImplicitRecessionParameters implicit; ///< grid and tolerances of the implicit path
  /// 0: the implicit path takes what a stage leaves it in one recession. Positive: in as many
  /// recessions as make the deepest face recede at most this far in each, the wear still to
  /// take carried from each new surface onto the next (meshes::FaceTransfer). One recession
  /// removes a union of balls; where faces of different depths meet at a concave edge (an
  /// element's foot) the deeper faces' balls reach past the shallower faces' depth, by an
  /// amount that grows with the square of the depth: smaller steps make that error smaller
  /// in proportion. [m]
  double implicit_step_depth = 0;
  /// Remesh when the smallest scaled Jacobian after mesh motion falls below this (and
  /// whenever a cell inverts). [-]
  double remesh_min_scaled_jacobian = 0.01;
  RemeshParameters remesh;
  std::string mesh_directory = "."; ///< where remeshed .msh files are written
  /// A stage whose recession would fold the surface is applied in up to 2^this increments.
  int max_halvings = 5;
  /// After this many halvings, a fold first spreads the stage's remaining wear around the
  /// folding faces (meshes::spread_removed_volume over 2, 4, 8, ... rings) before halving on,
  /// and again at every smaller increment.
  int halvings_before_spreading = 2;
  int max_spreadings = 6; ///< spreading attempts per fold and increment size (2 ... 64 rings)
  /// A wearing face with a vertex closer than this to the clamped bottom is worn through:
  /// no material is left there, so the wear asked of it is recorded, not removed. [m]
  double worn_through_thickness = 1e-3;
};

struct WearStageReport {
  double removed_volume = 0; ///< [m^3] requested on the wearing faces
  double volume_change = 0;  ///< [m^3] mesh volume before minus after
  int increments = 0;        ///< recession steps the stage was applied in
  int n_remeshes = 0;
  int n_first_attempt_remeshes = 0; ///< remeshes of the stage whose first attempt succeeded
  int n_spreadings = 0;             ///< spreading steps taken where the recession folded
  /// times the surface relaxation was halved because it alone folded the surface (the
  /// sixth halving turns it off for the rest of the stage)
  int n_relaxation_halvings = 0;
  double spread_volume = 0; ///< [m^3] removed volume moved between faces by spreading
  /// [m^3] asked of faces worn through (within worn_through_thickness of the bottom): not
  /// removed; volume_change = removed_volume - worn_through_volume
  double worn_through_volume = 0;
  int n_worn_through = 0; ///< faces worn through when the stage ended
  /// remeshes whose volume-restoring offset was held still around a fold it would make
  int n_held_restorations = 0;
  /// [m^3] chord volume the remeshes did not give back: every restoring offset folded, or the
  /// valid one fell short of the target (new - worn surface)
  double volume_not_restored = 0;
  int n_implicit = 0;          ///< implicit recessions taken (each followed by a remesh)
  double implicit_seconds = 0; ///< [s] spent in them
  /// [m^3] grid volume the implicit recessions took from the wear (their grid_loss)
  double implicit_grid_loss = 0;
  /// fragments the implicit recessions dropped (pieces the front cut off the part) and the
  /// volume they held [m^3], removed beside the wear
  std::size_t n_fragments = 0;
  double fragment_volume = 0;
  /// faces of no width the implicit recessions joined to the label beside them
  std::size_t n_teeth_joined = 0;
  /// folded edges the implicit recessions' remeshing left: mended, and left unmended
  std::size_t n_folds_mended = 0, n_folds_left = 0;
  /// why each remesh of an explicit increment failed with every attempt (in explicit then
  /// implicit the implicit recession then took the rest of the stage from the surface before
  /// the increment)
  std::vector<std::string> explicit_remesh_failures;
  /// why each implicit recession that failed did (in explicit then implicit the explicit path
  /// then went on, and stopped the stage only where it folds)
  std::vector<std::string> implicit_failures;
  std::vector<int> vanished_labels; ///< convex elements worn away in the stage
  double worn_through_area = 0;     ///< [m^2] clamped area the implicit recessions removed
  RemeshReport last_remesh;         ///< valid when n_remeshes > 0
  /// RemeshReport::failed_attempts of each remesh in the stage that needed more than one
  /// attempt (the refused inputs are kept beside the meshes)
  std::vector<std::string> remesh_refusals;
  VolumeQuality quality; ///< of the mesh handed on
  double motion_seconds = 0, remesh_seconds = 0;
};

/// A worn sample as plain arrays, for checkpoints: the volume mesh, its boundary surface
/// (with the revision the face fields refer to) and the accumulated fields. The volume mesh
/// may be left out (vertices, tetrahedra and boundary arrays empty: a run carried between
/// machines keeps the surface and its fields, a fraction of the size); the sample is then
/// meshed anew from its surface when it is read back.
struct WornSampleState {
  std::vector<double> vertices;                   ///< [m] n x 3, sample frame
  std::vector<std::int64_t> tetrahedra;           ///< n x 4 vertex indices
  std::vector<std::int64_t> boundary_faces;       ///< n x 3 vertex indices
  std::vector<int> boundary_ids;                  ///< label of each boundary face
  meshes::SurfaceMesh surface;                    ///< face order of the fields below
  std::vector<double> removed_volume, wear_depth; ///< [m^3], [m] per surface face
  int n_remeshes = 0;
};

/// The state of a sample meshed by `tria` (boundary ids = labels) whose boundary is `surface`,
/// with no wear accumulated on it (the face fields are zero).
WornSampleState triangulation_state(const dealii::Triangulation<3>& tria,
                                    const meshes::SurfaceMesh& surface);

struct StageSplit;     // fem/stage_increment.h
struct Verdict;        // fem/stage_increment.h
struct StageIncrement; // fem/stage_increment.h

class WornSample {
public:
  /// Reads the sample mesh; its boundary surface comes from the triangulation, its labels
  /// taking `roles`.
  WornSample(const std::string& msh_path, const meshes::LabelRoles& roles,
             const WornSampleParameters& p);
  /// Reads the sample mesh and maps `surface` (the same triangles, e.g. from
  /// meshes::read_msh_surface, so per-face fields keep their indices, and its roles) onto it.
  /// Every constructor throws when no face of the surface is clamped.
  WornSample(const std::string& msh_path, const meshes::SurfaceMesh& surface,
             const WornSampleParameters& p);

  /// Rebuilds a sample from its state (state()); bit for bit the same mesh and fields.
  WornSample(const WornSampleState& state, const WornSampleParameters& p);
  WornSampleState state() const;

  const dealii::Triangulation<3>& triangulation() const { return *tria_; }
  const meshes::SurfaceMesh& surface() const { return map_->surface(); }
  const BoundaryFaceMap& face_map() const { return *map_; }
  /// Accumulated removed volume per face [m^3] (extensive).
  const meshes::FaceField<double>& removed_volume() const { return removed_; }
  /// Accumulated wear depth per face [m] (intensive: sum of stage volume / face area).
  const meshes::FaceField<double>& wear_depth() const { return depth_; }
  int n_remeshes() const { return n_remeshes_; }
  const WornSampleParameters& parameters() const { return p_; }

  /// Applies one stage of removed volume per face (extensive, on the current surface):
  /// recession, mesh motion, and remeshing when the moved mesh holds an inverted or poor
  /// cell. A stage that would fold the surface (depth beyond the local radius of curvature)
  /// is split into increments, each on the surface the previous one produced; where it
  /// still folds, the wear is spread over the neighbourhood of the fold (the total is kept).
  /// Throws when the field belongs to another revision, or the surface folds even then.
  WearStageReport apply_wear(const meshes::FaceField<double>& removed);

  /// Remeshes now (e.g. on request) and restores the enclosed volume lost to chords.
  RemeshReport remesh();

private:
  /// The accumulated fields and a stage's remaining volume at one moment: put back when a
  /// step that changed them fails (the sample itself is unchanged then, the remesher throws
  /// before it changes).
  struct FieldSnapshot {
    meshes::FaceField<double> removed, depth, remaining;
  };
  FieldSnapshot snapshot(const meshes::FaceField<double>& remaining) const {
    return {removed_, depth_, remaining};
  }
  void restore(const FieldSnapshot& s, meshes::FaceField<double>& remaining) {
    removed_ = s.removed, depth_ = s.depth, remaining = s.remaining;
  }
  void set_surface(const meshes::SurfaceMesh& surface);
  /// The sample of a state kept without its volume mesh: meshed from its surface, the fields
  /// carried onto the result.
  void mesh_kept_surface(const WornSampleState& st);
  /// Takes an increment the verdict accepted: accumulates its wear (and takes it off
  /// `remaining`), moves the mesh, and remeshes when the moved mesh holds an inverted or poor
  /// cell; `remaining` follows onto the new surface. In explicit then implicit, a remesh that
  /// fails with every attempt is taken back and the implicit recession takes the rest of the
  /// stage instead; then true is returned (the stage is done).
  bool take_increment(const StageIncrement& inc, meshes::FaceField<double>& remaining,
                      WearStageReport& r);
  /// Changes the split (or `remaining`, by spreading) as the verdict on an increment asks;
  /// throws when the stage gives up.
  void retry_increment(const Verdict& verdict, const StageIncrement& inc, StageSplit& split,
                       std::vector<double>& remaining, WearStageReport& r) const;
  /// Adds `part` [m^3 per face of `on`, the surface the fields stand on: the current one, or
  /// an implicit step's] to the accumulated fields and takes it off `remaining` (which may be
  /// `part` itself).
  void accumulate(const std::vector<double>& part, std::vector<double>& remaining,
                  const meshes::SurfaceMesh& on);
  /// Takes the whole of `remaining` by the implicit recession and remeshes the result; the
  /// accumulated fields follow onto the new surface.
  void take_implicit(meshes::FaceField<double>& remaining, WearStageReport& r);
  /// How many implicit recessions take `remaining` [m^3 per face of `worn`]: 1, or as many
  /// as keep each within implicit_step_depth on its deepest face, at most max_implicit_steps.
  int implicit_steps(const meshes::SurfaceMesh& worn, const std::vector<double>& remaining) const;
  static constexpr int max_implicit_steps = 16;
  /// take_implicit, or, when it throws, the sample, its fields, `remaining` and `r` as they
  /// were with the failure added to r.implicit_failures; returns whether it took the stage.
  bool try_implicit(meshes::FaceField<double>& remaining, WearStageReport& r);
  /// Remeshes the volume bounded by `surface`, its triangles kept when it is `isotropic`
  /// (fem::remesh_sample).
  RemeshReport remesh_from(const meshes::SurfaceMesh& surface,
                           SurfaceKind kind = SurfaceKind::worn);
  /// Transfers the accumulated fields from `worn` (the current surface or its moved copy) to
  /// the remeshed surface `fresh`.
  void carry_fields(const meshes::SurfaceMesh& worn, const meshes::SurfaceMesh& fresh);
  /// The same by a transfer already made from `worn` (one step of the implicit path, whose
  /// stage's remaining wear goes by it too).
  void carry_fields(const meshes::SurfaceMesh& worn, const meshes::FaceTransfer& to_fresh);
  /// Writes the surface before a failing increment and the folded candidate, bad faces
  /// marked, for diagnosis; returns the paths.
  std::string write_failed_increment(const meshes::SurfaceMesh& before,
                                     const meshes::SurfaceMesh& after,
                                     const std::vector<std::uint32_t>& bad_faces) const;

  WornSampleParameters p_;
  std::unique_ptr<dealii::Triangulation<3>> tria_;
  std::unique_ptr<BoundaryFaceMap> map_;
  meshes::FaceField<double> removed_, depth_;
  int n_remeshes_ = 0;
};

} // namespace wear::fem

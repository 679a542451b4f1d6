#pragma once
// Coarse-graining of point loads on a triangulated surface (Weinhart et al. 2012, as in
// MercuryDPM's MercuryCG): each source's impulse spread over the faces around it with a
// Gaussian kernel of width w, corrected so that every source keeps its resultant and its
// moment exactly. The result is a field of extensive per-face values, the integral of the
// coarse-grained traction (or density) over each face; it does not depend on the
// triangulation beyond the quadrature of the kernel over the faces (docs/theory.md).
#include "meshes/face_field.h"
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wear::meshes {

/// Per face of a surface, the loads that act there: an impulse (or force) at a point with a
/// moment about the origin, in the surface's frame. A face with a zero impulse is no source.
struct FaceSources {
  std::vector<Vec3> impulse; ///< [N s] (or [N])
  std::vector<Vec3> point;   ///< [m] where the impulse acts (on or near the face)
  std::vector<Vec3> moment;  ///< [N s m] (or [N m]) about the origin
};

class CoarseGraining {
public:
  /// The kernel exp(-r^2 / (2 w^2)) cut at r = 3w over the faces of `mesh` (copied: its
  /// centroids, areas, normals, labels and a grid of cell size >= 3w). Throws
  /// std::invalid_argument naming `what` when w is not positive and finite.
  CoarseGraining(const SurfaceMesh& mesh, double width, const std::string& what);

  double width() const { return width_; } ///< [m]
  std::uint64_t revision() const { return revision_; }
  std::size_t n_faces() const { return centroid_.size(); }

  /// The per-face force of the coarse-grained traction of `sources` (extensive, named
  /// `name` with unit `unit`): per source, the kernel over the faces around its point whose
  /// normals lie within 120 degrees of its own face's, of any label, with the rigid first-
  /// order correction that makes the source's resultant and moment exact. A source whose
  /// kernel holds fewer than three faces not on one line stays on its own face.
  FaceField<Vec3> spread_force(const FaceSources& sources, const std::string& name,
                               const std::string& unit) const;

  /// The coarse-grained density of the extensive per-face `value` (the same name and unit),
  /// face f's value acting at point[f]: per source, the normalised kernel over the faces of
  /// its own label around it (normals within 120 degrees), which keeps each source's value
  /// exactly, so every label's total, and every face's share non-negative.
  FaceField<double> spread_scalar(const FaceField<double>& value,
                                  const std::vector<Vec3>& point) const;

private:
  /// Into `faces` and `weight`: the faces within the cut-off 3w of `p` whose normals lie
  /// within 120 degrees of face `source`'s (of its label only if `same_label`), and their
  /// area x kernel [m^2]; face `source` always, even beyond the cut-off.
  void neighbours(std::size_t source, const Vec3& p, bool same_label,
                  std::vector<std::uint32_t>& faces, std::vector<double>& weight) const;
  /// A face-less mesh of the kernel's revision, to tag the fields it makes.
  SurfaceMesh tag() const;
  double width_ = 0; ///< [m]
  std::uint64_t revision_ = 0;
  std::vector<Vec3> centroid_, normal_; ///< [m], unit
  std::vector<double> area_;            ///< [m^2]
  std::vector<int> label_;
  Vec3 origin_;     ///< [m] lower corner of the grid
  double cell_ = 1; ///< [m]
  int n_[3] = {1, 1, 1};
  std::vector<std::uint32_t> offset_; ///< CSR: faces of cell c at offset_[c] .. offset_[c + 1]
  std::vector<std::uint32_t> faces_;
};

} // namespace wear::meshes

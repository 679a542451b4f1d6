// Reference deformation (docs/theory.md section 5), the node-moving method of the reference study.
//
// Per update, every node moves by the area-weighted node recession of the update's removed
// volume, x_v -= D_v n_v with D_v = sum dV_f / sum A_f and n_v the area-weighted normal over the
// wearing faces around v (meshes::area_weighted_recession, shared with the staged scheme, which
// also scales it to the exact volume). Non-wearing faces (sides, bottom) never move on their own.
// Swept volume per update: sum_f |dp_c,f| A_f with dp_c,f the centroid displacement.
// After each update the surface is checked for inverted faces (normal turned by more than
// 90 degrees from the unworn one), degenerate faces and self-intersections; the first
// distortion is kept with its time, face and label, that update is undone and the surface
// stays frozen from then on (the reference method's validity ends there; the bed runs on).
#include "dem/wear/reference_deformation.h"

#include "meshes/recession.h"

#include <cmath>
#include <stdexcept>

namespace wear::dem {

using meshes::Vec3;

ReferenceDeformation::ReferenceDeformation(const meshes::SurfaceMesh& mesh)
    : mesh_(mesh), initial_normals_(meshes::face_normals(mesh)) {
  wears_.resize(mesh_.n_faces());
  std::size_t n_wearing = 0;
  for (std::size_t f = 0; f < mesh_.n_faces(); ++f) {
    wears_[f] = mesh_.face_wears(f);
    n_wearing += wears_[f];
  }
  if (n_wearing == 0)
    throw std::invalid_argument("reference deformation: the wall has no wearing faces (labels "
                                "base or C<j><k>)");
  initial_volume_ = meshes::enclosed_volume(mesh_);
}

double ReferenceDeformation::enclosed_volume_loss() const {
  return initial_volume_ - meshes::enclosed_volume(mesh_);
}

ReferenceDeformationState ReferenceDeformation::state() const {
  return {mesh_.vertices, swept_volume_, applied_volume_, n_updates_, distortion_};
}

void ReferenceDeformation::resume(const ReferenceDeformationState& s) {
  if (s.vertices.size() != mesh_.n_vertices())
    throw std::invalid_argument("reference deformation: a state of " +
                                std::to_string(s.vertices.size()) + " vertices for a mesh of " +
                                std::to_string(mesh_.n_vertices()));
  mesh_.vertices = s.vertices;
  mesh_.bump_revision();
  swept_volume_ = s.swept_volume;
  applied_volume_ = s.applied_volume;
  n_updates_ = s.n_updates;
  distortion_ = s.distortion;
  quality_ = meshes::surface_quality(mesh_, &initial_normals_);
}

std::string ReferenceDeformation::distortion_text() const {
  if (!distortion_)
    return {};
  const Distortion& d = *distortion_;
  return d.kind + " at face " + std::to_string(d.face) + " (" + meshes::label::name(d.label) +
         "), t = " + std::to_string(d.time) + " s";
}

const std::vector<Vec3>& ReferenceDeformation::update(const std::vector<double>& removed_volume,
                                                      double time) {
  const std::size_t nf = mesh_.n_faces(), nv = mesh_.n_vertices();
  if (removed_volume.size() != nf)
    throw std::invalid_argument("reference deformation: " + std::to_string(removed_volume.size()) +
                                " face volumes for a mesh of " + std::to_string(nf) + " faces");
  if (distortion_)
    return mesh_.vertices; // frozen at the last valid surface
  const auto area = meshes::face_areas(mesh_);
  const auto old_centroids = meshes::face_centroids(mesh_);
  const std::vector<Vec3> previous = mesh_.vertices;
  const auto recession = meshes::area_weighted_recession(mesh_, removed_volume);
  for (std::size_t v = 0; v < nv; ++v)
    mesh_.vertices[v] += recession[v];
  mesh_.bump_revision();
  quality_ = meshes::surface_quality(mesh_, &initial_normals_);
  if (!quality_.valid()) {
    Distortion d;
    d.kind = quality_.n_inverted
                 ? "inverted face"
                 : (quality_.n_degenerate ? "degenerate face" : "self-intersection");
    d.face = quality_.first_bad_face;
    d.label = d.face >= 0 ? mesh_.face_labels[std::size_t(d.face)] : 0;
    d.time = time;
    distortion_ = d;
    mesh_.vertices = previous;
    mesh_.bump_revision();
    return mesh_.vertices;
  }
  const auto new_centroids = meshes::face_centroids(mesh_);
  for (std::size_t f = 0; f < nf; ++f)
    if (wears_[f]) {
      swept_volume_ += meshes::norm(new_centroids[f] - old_centroids[f]) * area[f];
      applied_volume_ += removed_volume[f];
    }
  ++n_updates_;
  return mesh_.vertices;
}

} // namespace wear::dem

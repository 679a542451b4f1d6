// Face-field transfer between two triangulations of one surface.
//
// Each old face f is cut into n^2 congruent sub-triangles (n subdivisions per edge); the
// centroid of each carries 1/n^2 of f's area. Every centroid is sent to the new face nearest
// it among the faces of f's label, so no quantity crosses a label boundary (the wear of an
// element stays on that element). A new face's value is the area-weighted mean over the
// samples it received (for an extensive field, of the density value / area); the resolution
// is the sub-triangle size h / n. Extensive fields are then corrected per label by spreading
// the difference of the label's sums by area: conservation exact to round-off, and the
// correction is as small as the sampling error (a few per cent of the field at most).
#include "meshes/face_transfer.h"

#include <algorithm>
#include <stdexcept>

namespace wear::meshes {

FaceTransfer::FaceTransfer(const SurfaceMesh& from, const SurfaceMesh& to, int subdivisions)
    : from_(from), to_(to), n_sub_(subdivisions), from_area_(face_areas(from)),
      to_area_(face_areas(to)), to_label_area_(area_per_label(to)) {
  if (subdivisions < 1)
    throw std::invalid_argument("FaceTransfer: subdivisions must be at least 1");
  const SurfaceLocator to_locator(to);
  const auto to_labels = to.labels();
  const int n = n_sub_;
  target_.resize(from.n_faces() * static_cast<std::size_t>(n) * n);
  for (std::size_t f = 0; f < from.n_faces(); ++f) {
    const auto& t = from.triangles[f];
    const Vec3 a = from.vertices[t[0]], u = (from.vertices[t[1]] - a) * (1.0 / n),
               v = (from.vertices[t[2]] - a) * (1.0 / n);
    const int label = from.face_labels[f];
    const bool present = std::binary_search(to_labels.begin(), to_labels.end(), label);
    std::size_t s = f * static_cast<std::size_t>(n) * n;
    // Sub-triangles of the n x n split: "up" (i, j), (i+1, j), (i, j+1) with i + j < n and
    // "down" (i+1, j), (i+1, j+1), (i, j+1) with i + j < n - 1; centroids below.
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        const Vec3 up = a + u * (i + 1.0 / 3) + v * (j + 1.0 / 3);
        const auto hit = to_locator.nearest(up, present ? label : -1);
        target_[s++] = static_cast<std::uint32_t>(hit.face);
        if (i + j < n - 1) {
          const Vec3 down = a + u * (i + 2.0 / 3) + v * (j + 2.0 / 3);
          const auto hit2 = to_locator.nearest(down, present ? label : -1);
          target_[s++] = static_cast<std::uint32_t>(hit2.face);
        }
      }
    if (!present)
      n_relabelled_ += static_cast<std::size_t>(n) * n;
  }
  const SurfaceLocator from_locator(from);
  const auto centroid = face_centroids(to);
  fallback_.resize(to.n_faces());
  for (std::size_t g = 0; g < to.n_faces(); ++g) {
    auto hit = from_locator.nearest(centroid[g], to.face_labels[g]);
    if (hit.face < 0)
      hit = from_locator.nearest(centroid[g]);
    fallback_[g] = static_cast<std::uint32_t>(hit.face);
  }
}

} // namespace wear::meshes

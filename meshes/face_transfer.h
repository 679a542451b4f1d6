#pragma once
// Per-face fields carried from one triangulation of a surface to another (after remeshing):
// extensive fields conservatively per label, intensive ones as area-weighted averages.
#include "meshes/face_field.h"
#include "meshes/surface_locator.h"

#include <map>
#include <type_traits>

namespace wear::meshes {

/// Where each sample point of the old surface lands on the new one: every old face is split
/// into n^2 congruent sub-triangles whose centroids are assigned to the nearest new face of
/// the same label (of any label when the new surface lacks it).
class FaceTransfer {
public:
  FaceTransfer(const SurfaceMesh& from, const SurfaceMesh& to, int subdivisions = 4);

  /// Intensive: the new face's value is the area-weighted mean of the samples it received,
  /// or the value of the old face nearest its centroid when it received none. Extensive: the
  /// density (value / area) is carried the same way and multiplied by the new area; then the
  /// difference of each label's sum is spread over the label's new faces by area, so the sum
  /// per label (and the total) is kept to round-off.
  template <typename T>
  FaceField<T> apply(const FaceField<T>& field) const;

  std::size_t n_relabelled() const { return n_relabelled_; } ///< samples sent to another label

private:
  const SurfaceMesh& from_;
  const SurfaceMesh& to_;
  int n_sub_;
  std::vector<std::uint32_t> target_;   ///< new face of sample s of old face f: [f * n^2 + s]
  std::vector<std::uint32_t> fallback_; ///< old face nearest each new face's centroid
  /// Label whose new faces receive old face f's samples (its own, or the nearest face's
  /// label when the new surface lacks it).
  int label_of_sample(std::size_t f) const { return to_.face_labels[target_[f * n_sub_ * n_sub_]]; }

  std::vector<double> from_area_, to_area_;
  std::map<int, double> to_label_area_;
  std::size_t n_relabelled_ = 0;
};

template <typename T>
FaceField<T> FaceTransfer::apply(const FaceField<T>& field) const {
  field.check_matches(from_);
  FaceField<T> out(field.name(), field.unit(), field.kind(), to_);
  const std::size_t n = static_cast<std::size_t>(n_sub_) * n_sub_;
  const bool extensive = field.extensive();
  // Area-weighted mean of the density (extensive) or value (intensive) the samples carry.
  std::vector<double> weight(to_.n_faces(), 0);
  for (std::size_t f = 0; f < from_.n_faces(); ++f) {
    const T value = extensive ? field[f] * (1 / from_area_[f]) : field[f];
    for (std::size_t s = 0; s < n; ++s) {
      const auto g = target_[f * n + s];
      out[g] += value * from_area_[f];
      weight[g] += from_area_[f];
    }
  }
  for (std::size_t g = 0; g < to_.n_faces(); ++g) {
    const T mean = weight[g] > 0 ? out[g] * (1 / weight[g])
                                 : (extensive ? field[fallback_[g]] * (1 / from_area_[fallback_[g]])
                                              : field[fallback_[g]]);
    out[g] = extensive ? mean * to_area_[g] : mean;
  }
  if (!extensive)
    return out;
  // Conservation of each label's sum. A non-negative scalar field (a removed volume) is
  // scaled per label, which keeps every face non-negative; otherwise the per-label residual
  // goes back by area.
  std::map<int, T> residual; // the label's sum before, then minus its sum after
  for (std::size_t f = 0; f < from_.n_faces(); ++f)
    residual[label_of_sample(f)] += field[f];
  if constexpr (std::is_same_v<T, double>) {
    bool non_negative = true;
    for (std::size_t f = 0; f < from_.n_faces() && non_negative; ++f)
      non_negative = field[f] >= 0;
    if (non_negative) {
      std::map<int, double> after;
      for (std::size_t g = 0; g < to_.n_faces(); ++g)
        after[to_.face_labels[g]] += out[g];
      bool scalable = true;
      for (const auto& [label, sum] : residual)
        scalable = scalable && (sum == 0 || after[label] > 0);
      if (scalable) {
        for (std::size_t g = 0; g < to_.n_faces(); ++g) {
          const double a = after[to_.face_labels[g]];
          out[g] = a > 0 ? out[g] * (residual[to_.face_labels[g]] / a) : 0.0;
        }
        return out;
      }
    }
  }
  for (std::size_t g = 0; g < to_.n_faces(); ++g)
    residual[to_.face_labels[g]] -= out[g];
  for (std::size_t g = 0; g < to_.n_faces(); ++g) {
    const auto it = residual.find(to_.face_labels[g]);
    out[g] += it->second * (to_area_[g] / to_label_area_.at(to_.face_labels[g]));
  }
  return out;
}

} // namespace wear::meshes

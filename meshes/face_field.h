#pragma once
// One value per face of a SurfaceMesh, tied to the revision it was computed on.
// Extensive fields (forces, impulses, volumes) are conserved under transfer: their sum is
// the physical total. Intensive fields (pressures, depths) are averages and are derived
// where they are used.
#include "meshes/surface_mesh.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace wear::meshes {

enum class Extensivity { extensive, intensive };

template <typename T>
class FaceField {
public:
  FaceField() = default;
  FaceField(std::string name, std::string unit, Extensivity kind, const SurfaceMesh& mesh,
            const T& initial = T{})
      : name_(std::move(name)), unit_(std::move(unit)), kind_(kind), revision_(mesh.revision()),
        values_(mesh.n_faces(), initial) {}

  const std::string& name() const { return name_; }
  const std::string& unit() const { return unit_; }
  Extensivity kind() const { return kind_; }
  bool extensive() const { return kind_ == Extensivity::extensive; }
  std::uint64_t revision() const { return revision_; }
  std::size_t size() const { return values_.size(); }

  T& operator[](std::size_t f) { return values_[f]; }
  const T& operator[](std::size_t f) const { return values_[f]; }
  std::vector<T>& values() { return values_; }
  const std::vector<T>& values() const { return values_; }

  /// Throws when the field was computed on another revision or face count of `mesh`:
  /// geometry-derived data must never be applied to a mesh it does not describe.
  void check_matches(const SurfaceMesh& mesh) const {
    if (revision_ != mesh.revision() || values_.size() != mesh.n_faces())
      throw std::runtime_error(
          "face field '" + name_ + "' belongs to mesh revision " + std::to_string(revision_) +
          " with " + std::to_string(values_.size()) + " faces, but the mesh is at " + "revision " +
          std::to_string(mesh.revision()) + " with " + std::to_string(mesh.n_faces()) + " faces");
  }

  /// Re-tags the field for a new revision of the same triangles (vertices moved, topology
  /// kept): per-face values stay with their faces. Throws when the face count differs.
  void follow(const SurfaceMesh& moved) {
    if (values_.size() != moved.n_faces())
      throw std::runtime_error("face field '" + name_ + "' has " + std::to_string(values_.size()) +
                               " faces and cannot follow a mesh of " +
                               std::to_string(moved.n_faces()) + " faces; transfer it instead");
    revision_ = moved.revision();
  }

  /// Sum over faces: the conserved total of an extensive field.
  T sum() const {
    T s{};
    for (const auto& v : values_)
      s += v;
    return s;
  }

private:
  std::string name_, unit_;
  Extensivity kind_ = Extensivity::extensive;
  std::uint64_t revision_ = 0;
  std::vector<T> values_;
};

} // namespace wear::meshes

#pragma once
// The two frames of the wear tester and the map between them.
//
// Sample frame: x radial (outward), y along the flow (downstream), z up; origin at the centre
// of the sample's clamped bottom face. Tester frame: z the rotation axis, the floor at z = 0,
// the sector from theta = 0. The map is a proper rotation (incline about the radial axis
// through the wear-face centre, then the polar angle of the placement) plus a translation,
// so triangle orientation survives placement. Points take the translation, vectors (forces,
// impulses, normals) only the rotation: they are different functions so a vector is never
// moved by a translation.
#include "meshes/geometry_parameters.h"
#include "meshes/surface_mesh.h"
#include "meshes/vec3.h"

namespace wear::meshes {

class SampleFrame {
public:
  SampleFrame(const SampleGeometry& sample, const SamplePlacement& placement);

  Vec3 point_to_tester(const Vec3& p) const;  ///< [m] sample frame -> tester frame
  Vec3 point_to_sample(const Vec3& p) const;  ///< [m] tester frame -> sample frame
  Vec3 vector_to_tester(const Vec3& v) const; ///< rotation only
  Vec3 vector_to_sample(const Vec3& v) const; ///< rotation only

  /// The surface moved into the tester frame (new revision, same triangles and labels).
  SurfaceMesh place_in_tester(const SurfaceMesh& m) const;
  /// The surface's vertices moved back into the sample frame (new revision).
  SurfaceMesh place_in_sample(const SurfaceMesh& m) const;

private:
  double thickness_;            ///< [m] bottom face to wear face
  double radius_, face_height_; ///< [m] of the wear-face centre in the tester
  double cos_incline_, sin_incline_, cos_angle_, sin_angle_;
};

} // namespace wear::meshes

// Sample frame <-> tester frame (see sample_frame.h).
//
//   tester = R_z(phi) (R_x(theta) (p - t_s) + r_c e_x) + h e_z
// with theta the incline (positive raises the trailing +y edge, so the leading edge is
// lower), phi the polar angle of the placement, t_s = thickness e_z (the wear-face centre in
// the sample frame), r_c the placement radius and h the wear-face height. Vectors take R_z R_x
// alone. The arithmetic of the point maps is written out component by component in a fixed
// order: the DEM's wall positions are built from it, and any change of rounding would change
// every trajectory.
#include "meshes/sample_frame.h"

#include "meshes/constants.h"

#include <cmath>

namespace wear::meshes {

namespace {

// A copy of the surface with every vertex mapped, as a new revision of the same triangles.
template <typename Map>
SurfaceMesh with_vertices_mapped(const SurfaceMesh& m, Map map) {
  SurfaceMesh out = m;
  for (auto& v : out.vertices)
    v = map(v);
  out.bump_revision();
  return out;
}
} // namespace

SampleFrame::SampleFrame(const SampleGeometry& sample, const SamplePlacement& placement)
    : thickness_(sample.thickness), radius_(placement.radius),
      face_height_(placement.wear_face_height) {
  const double th = placement.incline_deg * pi / 180, phi = placement.angle_deg * pi / 180;
  cos_incline_ = std::cos(th);
  sin_incline_ = std::sin(th);
  cos_angle_ = std::cos(phi);
  sin_angle_ = std::sin(phi);
}

Vec3 SampleFrame::point_to_tester(const Vec3& p) const {
  const Vec3 q{p.x, p.y, p.z - thickness_};
  const Vec3 r{q.x, q.y * cos_incline_ - q.z * sin_incline_,
               q.y * sin_incline_ + q.z * cos_incline_};
  const double rad = radius_ + r.x;
  return {rad * cos_angle_ - r.y * sin_angle_, rad * sin_angle_ + r.y * cos_angle_,
          face_height_ + r.z};
}

Vec3 SampleFrame::point_to_sample(const Vec3& p) const {
  const double rad = p.x * cos_angle_ + p.y * sin_angle_;
  const Vec3 r{rad - radius_, -p.x * sin_angle_ + p.y * cos_angle_, p.z - face_height_};
  return {r.x, r.y * cos_incline_ + r.z * sin_incline_,
          -r.y * sin_incline_ + r.z * cos_incline_ + thickness_};
}

Vec3 SampleFrame::vector_to_tester(const Vec3& v) const {
  const Vec3 r{v.x, v.y * cos_incline_ - v.z * sin_incline_,
               v.y * sin_incline_ + v.z * cos_incline_};
  return {r.x * cos_angle_ - r.y * sin_angle_, r.x * sin_angle_ + r.y * cos_angle_, r.z};
}

Vec3 SampleFrame::vector_to_sample(const Vec3& v) const {
  const Vec3 r{v.x * cos_angle_ + v.y * sin_angle_, -v.x * sin_angle_ + v.y * cos_angle_, v.z};
  return {r.x, r.y * cos_incline_ + r.z * sin_incline_, -r.y * sin_incline_ + r.z * cos_incline_};
}

SurfaceMesh SampleFrame::place_in_tester(const SurfaceMesh& m) const {
  return with_vertices_mapped(m, [this](const Vec3& v) { return point_to_tester(v); });
}

SurfaceMesh SampleFrame::place_in_sample(const SurfaceMesh& m) const {
  return with_vertices_mapped(m, [this](const Vec3& v) { return point_to_sample(v); });
}

} // namespace wear::meshes

// Coarse-grained wall loads (Weinhart et al. 2012, "From discrete particles to continuum
// fields near a boundary"; MercuryDPM's MercuryCG): the traction of point loads as a smooth
// field of stated width, integrated over each face of a triangulation.
//
// A source is an impulse I acting at a point p with a moment M about the origin (for a face
// of the DEM's wall pass: the face's impulse, its normal-load centroid and the moment of its
// contacts, so M - p x I is the couple of the contacts' spread over the face). Its traction
// is t(x) = phi(|x - p|) (I / S + mu x (x - c)), with
//   phi(r) = exp(-r^2 / (2 w^2)) for r < 3w, else 0        (Gaussian cut at 3w)
//   S = sum_g phi_g,  phi_g = A_g phi(|x_g - p|)             (kernel mass over the faces)
//   c = sum_g phi_g x_g / S                                  (kernel centroid)
//   J = sum_g phi_g (|x_g - c|^2 1 - (x_g - c)(x_g - c)^T)   (its inertia tensor about c)
//   mu = J^-1 (M - c x I),
// integrated over face g by the centroid rule: F_g = phi_g (I / S + mu x (x_g - c)). Then
// sum_g F_g = I exactly (sum_g phi_g (x_g - c) = 0) and sum_g x_g x F_g = c x I + J mu = M:
// force and moment of every source, hence of the whole window about any point, to round-off.
// The correction is the traction of a small rigid rotation about c; it is zero for a
// symmetric kernel on a plane and a source without couple, and supplies what truncation,
// curvature and the contacts' couple take away (of the order of w / L of the load).
//
// Choices (docs/theory.md):
// - Distance Euclidean, not along the surface: w is a particle radius (1 to 4 mm), the
//   convex elements are half-ellipsoids of a few cm, and the chord differs from the arc by
//   r^3 / (24 R^2), under 1 % of r inside 3w; a geodesic search would be costly and itself
//   mesh-dependent.
// - Faces of every label whose normal lies within 120 degrees of the source face's: the load
//   crosses the concave foot of an element and the convex rim of the base (about 90 degrees)
//   rather than being cut off there, but never reaches the far side of a thin part.
// - A face with a centroid inside 3w of p takes phi_g (centroid rule, error O(h^2 / w^2)); the
//   source's own face always takes part. A source whose faces give no invertible J (w far
//   below the face size) stays whole on its own face.
// - Scalars (the wear-law volume) are spread with the normalised kernel only, over the faces
//   of the source's label: each label's total stays exact and no face gets a negative share;
//   the centroid of a source near a label edge moves inwards by up to 0.8 w.
// Serial and in a fixed order: the same input gives the same bits.
#include "meshes/coarse_graining.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wear::meshes {

namespace {
/// Faces whose normals differ by more than 120 degrees from the source face's take no load.
constexpr double min_normal_cosine = -0.5;
/// Cut-off of the kernel in widths.
constexpr double cut_off = 3;
/// At most this many grid cells per axis: a tiny width on a large mesh keeps a bounded grid.
constexpr double max_cells_per_axis = 256;

/// Symmetric 3x3 matrix, row-major.
struct Sym3 {
  double a[3][3] = {};
};

/// J^-1 r for a symmetric positive J; false when J is singular to round-off (its
/// determinant below 1e-10 of that of a sphere of the same trace).
bool solve(const Sym3& J, const Vec3& r, Vec3& x) {
  const auto& a = J.a;
  const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
  const double trace = a[0][0] + a[1][1] + a[2][2];
  if (!(trace > 0) || !(det > 1e-10 * std::pow(trace / 3, 3)))
    return false;
  const double c11 = a[0][0] * a[2][2] - a[0][2] * a[2][0];
  const double c12 = a[0][1] * a[2][0] - a[0][0] * a[2][1];
  const double c22 = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  // The inverse is the adjugate (symmetric here) over the determinant.
  x = Vec3{c00 * r.x + c01 * r.y + c02 * r.z, c01 * r.x + c11 * r.y + c12 * r.z,
           c02 * r.x + c12 * r.y + c22 * r.z} /
      det;
  return true;
}
} // namespace

CoarseGraining::CoarseGraining(const SurfaceMesh& mesh, double width, const std::string& what)
    : width_(width), revision_(mesh.revision()), centroid_(face_centroids(mesh)),
      normal_(face_normals(mesh)), area_(face_areas(mesh)), label_(mesh.face_labels) {
  if (!(width > 0) || !std::isfinite(width))
    throw std::invalid_argument(what +
                                ": the coarse-graining width must be positive and finite "
                                "(it is " +
                                std::to_string(width) + " m)");
  if (centroid_.empty())
    return;
  Vec3 lo = centroid_[0], hi = centroid_[0];
  for (const auto& x : centroid_)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], x[k]);
      hi[k] = std::max(hi[k], x[k]);
    }
  const Vec3 extent = hi - lo;
  cell_ = std::max({cut_off * width, extent.x / max_cells_per_axis, extent.y / max_cells_per_axis,
                    extent.z / max_cells_per_axis});
  origin_ = lo;
  for (int k = 0; k < 3; ++k)
    n_[k] = 1 + int(extent[k] / cell_);
  const auto cell_of = [this](const Vec3& x) {
    int c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = std::clamp(int((x[k] - origin_[k]) / cell_), 0, n_[k] - 1);
    return std::size_t(c[0]) + std::size_t(n_[0]) * (std::size_t(c[1]) + std::size_t(n_[1]) * c[2]);
  };
  offset_.assign(std::size_t(n_[0]) * n_[1] * n_[2] + 1, 0);
  for (const auto& x : centroid_)
    ++offset_[cell_of(x) + 1];
  for (std::size_t c = 1; c < offset_.size(); ++c)
    offset_[c] += offset_[c - 1];
  faces_.resize(centroid_.size());
  std::vector<std::uint32_t> fill(offset_.begin(), offset_.end() - 1);
  for (std::size_t g = 0; g < centroid_.size(); ++g)
    faces_[fill[cell_of(centroid_[g])]++] = std::uint32_t(g);
}

SurfaceMesh CoarseGraining::tag() const {
  SurfaceMesh m;
  m.set_revision(revision_);
  return m;
}

void CoarseGraining::neighbours(std::size_t source, const Vec3& p, bool same_label,
                                std::vector<std::uint32_t>& faces,
                                std::vector<double>& weight) const {
  faces.clear();
  weight.clear();
  const double r_cut2 = cut_off * cut_off * width_ * width_;
  const double inv_2w2 = 1 / (2 * width_ * width_);
  int lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    const double u = (p[k] - origin_[k]) / cell_;
    lo[k] = std::clamp(int(std::floor(u - cut_off * width_ / cell_)), 0, n_[k] - 1);
    hi[k] = std::clamp(int(std::floor(u + cut_off * width_ / cell_)), 0, n_[k] - 1);
  }
  const Vec3& n_source = normal_[source];
  bool has_source = false;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::size_t c =
            std::size_t(i) + std::size_t(n_[0]) * (std::size_t(j) + std::size_t(n_[1]) * k);
        for (auto q = offset_[c]; q < offset_[c + 1]; ++q) {
          const std::uint32_t g = faces_[q];
          const double r2 = norm2(centroid_[g] - p);
          if (r2 >= r_cut2 || dot(normal_[g], n_source) < min_normal_cosine ||
              (same_label && label_[g] != label_[source]))
            continue;
          faces.push_back(g);
          weight.push_back(area_[g] * std::exp(-r2 * inv_2w2));
          has_source = has_source || g == source;
        }
      }
  if (!has_source) {
    faces.push_back(std::uint32_t(source));
    weight.push_back(area_[source] * std::exp(-norm2(centroid_[source] - p) * inv_2w2));
  }
}

FaceField<Vec3> CoarseGraining::spread_force(const FaceSources& s, const std::string& name,
                                             const std::string& unit) const {
  const std::size_t nf = n_faces();
  if (s.impulse.size() != nf || s.point.size() != nf || s.moment.size() != nf)
    throw std::invalid_argument("coarse-graining '" + name +
                                "': the sources are not one per face (" + std::to_string(nf) +
                                " faces)");
  FaceField<Vec3> out(name, unit, Extensivity::extensive, tag());
  out.values().assign(nf, Vec3{});
  std::vector<std::uint32_t> faces;
  std::vector<double> weight;
  for (std::size_t f = 0; f < nf; ++f) {
    const Vec3& I = s.impulse[f];
    if (I == Vec3{})
      continue;
    const Vec3& p = s.point[f];
    neighbours(f, p, false, faces, weight);
    double S = 0;
    Vec3 m{};
    for (std::size_t k = 0; k < faces.size(); ++k) {
      S += weight[k];
      m += (centroid_[faces[k]] - p) * weight[k];
    }
    if (!(S > 0)) {
      out[f] += I;
      continue;
    }
    const Vec3 c = p + m / S;
    Sym3 J;
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const Vec3 d = centroid_[faces[k]] - c;
      const double d2 = norm2(d);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          J.a[a][b] += weight[k] * ((a == b ? d2 : 0) - d[a] * d[b]);
    }
    // The moment about c that the spread must carry: the source's own (M - p x I) and that
    // of I moved from p to c.
    const Vec3 moment_c = (s.moment[f] - cross(p, I)) - cross(c - p, I);
    Vec3 mu;
    if (!solve(J, moment_c, mu)) {
      out[f] += I;
      continue;
    }
    for (std::size_t k = 0; k < faces.size(); ++k)
      out[faces[k]] += (I / S + cross(mu, centroid_[faces[k]] - c)) * weight[k];
  }
  return out;
}

FaceField<double> CoarseGraining::spread_scalar(const FaceField<double>& value,
                                                const std::vector<Vec3>& point) const {
  const std::size_t nf = n_faces();
  if (value.size() != nf || point.size() != nf)
    throw std::invalid_argument("coarse-graining '" + value.name() +
                                "': the values or points are not one per face (" +
                                std::to_string(nf) + " faces)");
  if (value.revision() != revision_)
    throw std::invalid_argument("coarse-graining '" + value.name() +
                                "': the field is on mesh "
                                "revision " +
                                std::to_string(value.revision()) + ", the kernel on revision " +
                                std::to_string(revision_));
  FaceField<double> out = value;
  std::fill(out.values().begin(), out.values().end(), 0.0);
  std::vector<std::uint32_t> faces;
  std::vector<double> weight;
  for (std::size_t f = 0; f < nf; ++f) {
    if (value[f] == 0)
      continue;
    neighbours(f, point[f], true, faces, weight);
    double S = 0;
    for (double w : weight)
      S += w;
    if (!(S > 0)) {
      out[f] += value[f];
      continue;
    }
    for (std::size_t k = 0; k < faces.size(); ++k)
      out[faces[k]] += value[f] * (weight[k] / S);
  }
  return out;
}

} // namespace wear::meshes

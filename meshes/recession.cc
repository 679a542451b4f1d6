// Recession of a worn surface (docs/theory.md sections 5 and 6.3), for both deformation schemes.
//
// Area-weighted node recession: D_v = sum_{f in W(v)} V_f / sum_{f in W(v)} A_f along
// n_v = normalized(sum_{f in W(v)} A_f n_f), W(v) the wearing faces around v; x_v -= D_v n_v.
// Only wearing faces enter both sums, so a node where the wear face meets a side moves with
// the wear face (straight down on a flat plate) and a uniformly loaded flat plate recedes
// uniformly. The reference scheme applies it as it is.
// Volume-exact recession (staged scheme): the nodes shared with the unworn surface are kept on
// it (sliding constraints), and the field is scaled by s, found by secant steps on
// g(s) = volume loss(s) - sum V_f, smooth and monotone for small recessions: the averaging
// smooths the depth field and does not conserve volume where wear is concentrated. The
// volume-restoring offset after a remesh is the same recession of a uniform depth, scaled to
// the volume the chords cut off.
//
// Spreading (where a recession would fold): explicit conservative diffusion of the depth
// d_f = V_f / A_f over the region R (wearing faces within k vertex rings of the folding faces):
// per step, across every edge (f, g) inside R, volume q = w (d_f - d_g) min(A_f, A_g) with
// w = 1/4 goes from f to g. A face gives at most 3 w V_f < V_f per step, so volumes stay
// non-negative, and every transfer is antisymmetric, so the total is kept. The assumption is
// physical as well as numerical: a tip thinner than the wear of one step is not cut into a
// sliver, its neighbourhood recedes with it.
#include "meshes/recession.h"

#include "meshes/sliding_constraint.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wear::meshes {

namespace {
// Sums over the wearing faces around each vertex: removed volume, area and unnormalized
// normal (area-weighted).
struct WearingSums {
  std::vector<double> volume, area; ///< [m^3], [m^2]
  std::vector<Vec3> normal;         ///< [m^2]
};

WearingSums wearing_sums(const SurfaceMesh& m, const std::vector<double>& removed_volume) {
  const std::size_t nv = m.n_vertices();
  const auto area = face_areas(m);
  WearingSums s{std::vector<double>(nv, 0), std::vector<double>(nv, 0), std::vector<Vec3>(nv)};
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    if (!m.face_wears(f))
      continue;
    const Vec3 n = face_normal_unnormalized(m, f);
    for (const auto v : m.triangles[f]) {
      s.volume[v] += removed_volume[f];
      s.area[v] += area[f];
      s.normal[v] += n;
    }
  }
  return s;
}

// The area-weighted recession with the vertices the wear face shares with the unworn
// surface kept on it: they slide down a flat side instead of leaving its plane.
std::vector<Vec3> sliding_recession(const SurfaceMesh& surface,
                                    const std::vector<double>& removed_volume) {
  std::vector<Vec3> unit = area_weighted_recession(surface, removed_volume);
  const auto constraint = sliding_constraints(surface);
  for (std::size_t v = 0; v < unit.size(); ++v)
    unit[v] = constraint[v].apply(unit[v]);
  return unit;
}

// `unit` scaled so that the enclosed volume drops by r.removed_volume (set by the caller).
void scale_recession(const SurfaceMesh& surface, const std::vector<Vec3>& unit, Recession& r,
                     double first_guess) {
  r.scale = scale_to_volume_loss(surface, unit, r.removed_volume, &r.swept_volume, first_guess);
  for (std::size_t v = 0; v < surface.n_vertices(); ++v)
    r.displacement[v] = unit[v] * r.scale;
}
} // namespace

// The scale s of the displacement field `unit` at which the enclosed volume drops by
// `target` (negative: grows), by secant steps from s = first_guess and s = 0.
double scale_to_volume_loss(const SurfaceMesh& surface, const std::vector<Vec3>& unit,
                            double target, double* achieved, double first_guess) {
  const std::size_t nv = surface.n_vertices();
  const double v0 = enclosed_volume(surface);
  SurfaceMesh moved = surface;
  const auto loss = [&](double s) {
    for (std::size_t v = 0; v < nv; ++v)
      moved.vertices[v] = surface.vertices[v] + unit[v] * s;
    return v0 - enclosed_volume(moved);
  };
  if (first_guess == 0) {
    // Linearised first step: d(loss)/ds at s = 0 is the area swept per unit offset.
    const double eps = 1e-9 * std::cbrt(std::abs(v0));
    first_guess = target * eps / loss(eps);
  }
  double s0 = 0, g0 = -target, s1 = first_guess, g1 = loss(s1) - target;
  // The enclosed volume is a sum over all faces: its round-off, not the target, limits the
  // attainable accuracy; stop there rather than divide by a vanishing secant.
  const double tolerance = std::max(1e-12 * std::abs(target), 1e-14 * std::abs(v0));
  for (int k = 0; k < 20 && std::abs(g1) > tolerance && g1 != g0; ++k) {
    const double s2 = s1 - g1 * (s1 - s0) / (g1 - g0);
    s0 = s1;
    g0 = g1;
    s1 = s2;
    g1 = loss(s1) - target;
  }
  *achieved = g1 + target;
  return s1;
}

std::vector<double> area_weighted_depth(const SurfaceMesh& m,
                                        const std::vector<double>& removed_volume) {
  const WearingSums s = wearing_sums(m, removed_volume);
  std::vector<double> depth(m.n_vertices(), 0);
  for (std::size_t v = 0; v < depth.size(); ++v)
    if (s.area[v] > 0)
      depth[v] = s.volume[v] / s.area[v];
  return depth;
}

std::vector<Vec3> area_weighted_recession(const SurfaceMesh& m,
                                          const std::vector<double>& removed_volume) {
  const WearingSums s = wearing_sums(m, removed_volume);
  std::vector<Vec3> out(m.n_vertices());
  for (std::size_t v = 0; v < out.size(); ++v)
    if (s.area[v] > 0 && norm(s.normal[v]) > 0)
      out[v] = normalized(s.normal[v]) * (-s.volume[v] / s.area[v]);
  return out;
}

Recession volume_exact_recession(const SurfaceMesh& surface,
                                 const std::vector<double>& removed_volume) {
  const std::size_t nf = surface.n_faces(), nv = surface.n_vertices();
  if (removed_volume.size() != nf)
    throw std::invalid_argument("recession: " + std::to_string(removed_volume.size()) +
                                " face volumes for a surface of " + std::to_string(nf) + " faces");
  Recession r;
  for (std::size_t f = 0; f < nf; ++f) {
    if (!(removed_volume[f] >= 0) || !std::isfinite(removed_volume[f]))
      throw std::invalid_argument("recession: removed volume of face " + std::to_string(f) +
                                  " is negative or not finite");
    if (surface.face_wears(f))
      r.removed_volume += removed_volume[f];
  }
  const std::vector<Vec3> unit = sliding_recession(surface, removed_volume);
  r.displacement.assign(nv, {});
  if (r.removed_volume == 0)
    return r;
  scale_recession(surface, unit, r, 1);
  return r;
}

Recession volume_restoring_offset(const SurfaceMesh& surface, double target_volume,
                                  const std::vector<char>* held_faces) {
  // Unit inward offset of the wear face: the recession of a depth of 1 m everywhere, 0 on
  // held faces (their vertices shared with free faces take the area-weighted mean: a taper).
  std::vector<double> unit_depth = face_areas(surface);
  if (held_faces) {
    if (held_faces->size() != surface.n_faces())
      throw std::invalid_argument("volume-restoring offset: mask of the wrong size");
    for (std::size_t f = 0; f < unit_depth.size(); ++f)
      if ((*held_faces)[f])
        unit_depth[f] = 0;
  }
  const std::vector<Vec3> unit = sliding_recession(surface, unit_depth);
  Recession r;
  r.removed_volume = enclosed_volume(surface) - target_volume;
  r.displacement.assign(surface.n_vertices(), {});
  if (r.removed_volume == 0 ||
      std::none_of(unit.begin(), unit.end(), [](const Vec3& u) { return norm(u) > 0; }))
    return r; // nothing to give back, or nothing free to move
  scale_recession(surface, unit, r, 0);
  return r;
}

std::vector<char> faces_within_rings(const SurfaceMesh& m, const std::vector<std::uint32_t>& seeds,
                                     int rings) {
  const std::size_t nf = m.n_faces();
  const auto vf = vertex_faces(m);
  std::vector<char> in_region(nf, 0);
  std::vector<std::uint32_t> front;
  for (const auto f : seeds)
    if (f < nf && !in_region[f]) {
      in_region[f] = 1;
      front.push_back(f);
    }
  for (int k = 0; k < rings; ++k) {
    std::vector<std::uint32_t> next;
    for (const auto f : front)
      for (const auto v : m.triangles[f])
        for (auto i = vf.offsets[v]; i < vf.offsets[v + 1]; ++i) {
          const auto g = vf.faces[i];
          if (!in_region[g]) {
            in_region[g] = 1;
            next.push_back(g);
          }
        }
    front.swap(next);
  }
  return in_region;
}

int hold_still_around_folds(
    const SurfaceMesh& m, const std::function<SurfaceQuality(const std::vector<char>&)>& attempt) {
  std::vector<char> held(m.n_faces(), 0);
  for (int rings = 0;;) {
    const SurfaceQuality q = attempt(held);
    if (q.valid())
      return rings;
    if (rings == 8)
      return -1;
    rings = rings == 0 ? 1 : 2 * rings;
    const auto around = faces_within_rings(m, q.bad_faces, rings);
    for (std::size_t f = 0; f < held.size(); ++f)
      held[f] |= around[f];
  }
}

double spread_removed_volume(const SurfaceMesh& m, std::vector<double>& removed_volume,
                             const std::vector<std::uint32_t>& seeds, int rings) {
  const std::size_t nf = m.n_faces();
  std::vector<char> in_region = faces_within_rings(m, seeds, rings);
  for (std::size_t f = 0; f < nf; ++f)
    if (!m.face_wears(f))
      in_region[f] = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& [edge, faces] : edge_faces(m))
    if (faces.size() == 2 && in_region[faces[0]] && in_region[faces[1]])
      pairs.emplace_back(faces[0], faces[1]);
  const auto area = face_areas(m);
  const std::vector<double> before = removed_volume;
  std::vector<double> change(nf, 0);
  constexpr double w = 0.25;
  for (int step = 0; step < rings * rings; ++step) {
    for (const auto& [f, g] : pairs) {
      const double q = w * (removed_volume[f] / area[f] - removed_volume[g] / area[g]) *
                       std::min(area[f], area[g]);
      change[f] -= q;
      change[g] += q;
    }
    for (const auto& [f, g] : pairs)
      for (const auto h : {f, g})
        if (change[h] != 0) {
          removed_volume[h] = std::max(0.0, removed_volume[h] + change[h]);
          change[h] = 0;
        }
  }
  double moved = 0;
  for (std::size_t f = 0; f < nf; ++f)
    moved += std::abs(removed_volume[f] - before[f]);
  return 0.5 * moved;
}

} // namespace wear::meshes

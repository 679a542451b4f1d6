// The wear increment of a stage (wear_increment.h): amplification, the stress-informed
// factor, the vertex depth check and adaptive amplification.
//
// The depth is linear in the amplification, so the stage that brings the deepest vertex to
// the cap is the declared one scaled by cap / fraction; the factor is taken just below it so
// rounding in the recomputed check cannot exceed the cap.
#include "coupling/loop/wear_increment.h"

#include "coupling/output/text_format.h"
#include "meshes/recession.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wear::coupling {

double stress_factor(const StressInformedWear& law, double von_mises) {
  if (!law.enabled)
    return 1;
  return 1 +
         law.sensitivity * std::pow(std::max(0.0, von_mises) / law.reference_stress, law.exponent);
}

DepthCheck vertex_depths(const meshes::SurfaceMesh& m, const std::vector<double>& removed) {
  const std::vector<double> depth = meshes::area_weighted_depth(m, removed);
  const std::size_t nv = m.n_vertices();
  std::vector<double> edge(nv, 0);
  std::vector<int> label(nv, 0);
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    if (!m.face_wears(f))
      continue;
    const auto& t = m.triangles[f];
    for (int k = 0; k < 3; ++k) {
      label[t[k]] = m.face_labels[f];
      const double e = meshes::norm(m.vertices[t[k]] - m.vertices[t[(k + 1) % 3]]);
      edge[t[k]] = std::max(edge[t[k]], e);
      edge[t[(k + 1) % 3]] = std::max(edge[t[(k + 1) % 3]], e);
    }
  }
  DepthCheck c;
  for (std::size_t v = 0; v < nv; ++v) {
    if (edge[v] <= 0) // no wear face at v
      continue;
    c.max_depth = std::max(c.max_depth, depth[v]);
    if (depth[v] / edge[v] > c.max_fraction) {
      c.max_fraction = depth[v] / edge[v];
      c.vertex = long(v);
      c.depth_there = depth[v];
      c.label = label[v];
    }
  }
  return c;
}

WearIncrement wear_increment(const meshes::SurfaceMesh& surface,
                             const meshes::FaceField<double>& wear_volume,
                             const meshes::FaceField<double>& previous_stress,
                             const CouplingParameters& p, bool adaptive) {
  wear_volume.check_matches(surface);
  previous_stress.check_matches(surface);
  const auto area = meshes::face_areas(surface);
  WearIncrement w;
  w.amplification = w.declared_amplification = p.amplification;
  w.removed =
      meshes::FaceField<double>("removed volume", "m^3", meshes::Extensivity::extensive, surface);
  double factor_area = 0, wear_area = 0;
  for (std::size_t f = 0; f < surface.n_faces(); ++f) {
    if (!surface.face_wears(f))
      continue;
    const double s = stress_factor(p.stress_informed, previous_stress[f]);
    w.removed[f] = w.amplification * s * wear_volume[f];
    w.dem_wear_volume += wear_volume[f];
    factor_area += s * area[f];
    wear_area += area[f];
  }
  w.mean_stress_factor = wear_area > 0 ? factor_area / wear_area : 1;
  w.depth = vertex_depths(surface, w.removed.values());
  const double cap = p.max_depth_fraction;
  if (adaptive && p.adaptive_amplification && w.depth.max_fraction > cap &&
      w.amplification * cap / w.depth.max_fraction >= p.min_amplification) {
    const double scale = cap / w.depth.max_fraction * (1 - 1e-9);
    w.lowered = true;
    w.declared_depth = w.depth;
    w.amplification *= scale;
    for (auto& v : w.removed.values())
      v *= scale;
    w.depth = vertex_depths(surface, w.removed.values());
  }
  return w;
}

void check_depth_cap(const WearIncrement& w, const CouplingParameters& p, int stage) {
  const double cap = p.max_depth_fraction;
  const DepthCheck& d = w.depth;
  if (d.max_fraction <= cap)
    return;
  throw std::runtime_error(
      "stage " + std::to_string(stage) + " would recede the surface by " +
      format("%.4g", 1e3 * d.depth_there) + " mm at vertex " + std::to_string(d.vertex) + " (" +
      meshes::label::name(d.label) + "), " + format("%.3g", d.max_fraction) +
      " of its longest edge; Coupling/Maximum depth fraction allows " + format("%.3g", cap) +
      ". Lower Coupling/Amplification (now " + format("%g", w.amplification) +
      ") or Coupling/Revolutions per stage, raise Coupling/Maximum depth fraction (up to "
      "10: the wear stage then splits itself where the surface would fold), or set "
      "Coupling/Adaptive amplification (a stage would need " +
      format("%.3g", w.amplification * cap / d.max_fraction) +
      "; Coupling/Minimum amplification is " + format("%g", p.min_amplification) +
      "); a finer mesh raises the fraction");
}

} // namespace wear::coupling

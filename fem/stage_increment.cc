// One increment of a wear stage on the sample's surface.
//
// Share: the increment takes part_f = remaining_f / n_left of every face's remaining wear.
// Relaxation first: the worn region tangentially (tangential_relaxation, weight relax / 2: the
// triangles of a receding tip would otherwise be squeezed into slivers), the unworn surface
// within its flat sides and the crease where the wear face meets a side (unworn_relaxation,
// crease_relaxation, weight relax / 2 each). Cutting spikes (normal part of the offset at a
// crease folded nearly flat) is kept only while the relaxation's own volume loss L stays
// within a quarter of sum(part); otherwise the relaxation is tangential only.
// Recession of the relaxed surface by part_f (1 - L / sum(part)) (meshes::volume_exact_recession),
// so the enclosed volume drops by exactly sum(part) over relaxation and recession together;
// L >= sum(part) leaves nothing to scale, and the relaxation is halved instead.
// Verdict on the moved surface, in this order: a recession short of its volume (one vertex
// carried far past its neighbours: the swept volume stops growing with the offset) is taken
// in smaller steps; a valid surface that takes a worn vertex more than halfway through the
// worn-through layer (it would pass the bottom on the next step) too; an invalid one
// (degenerate, inverted, self-intersecting or folded face) relaxes less when the relaxed
// surface alone is invalid, else spreads the wear around the fold once the increment has
// been halved often enough, else is halved; at the last halving the stage gives up.
#include "fem/stage_increment.h"

#include "fem/mesh_motion.h"
#include "meshes/sliding_constraint.h"

#include <cmath>
#include <limits>

namespace wear::fem {

namespace {
// The lowest vertex of the wear face, whose faces are the first to wear through.
meshes::Vec3 lowest_wearing_vertex(const meshes::SurfaceMesh& s) {
  meshes::Vec3 at{0, 0, std::numeric_limits<double>::infinity()};
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_wears(f))
      for (const auto v : s.triangles[f])
        if (s.vertices[v].z < at.z)
          at = s.vertices[v];
  return at;
}

// The increment's share of the remaining wear, its sum and the vertices it moves.
StageIncrement increment_share(const meshes::SurfaceMesh& s, const std::vector<double>& remaining,
                               int n_left) {
  StageIncrement inc;
  inc.part = remaining;
  for (auto& v : inc.part)
    v /= n_left;
  inc.worn_vertex.assign(s.n_vertices(), 0);
  for (std::size_t f = 0; f < inc.part.size(); ++f)
    if (inc.part[f] > 0) {
      inc.part_sum += inc.part[f];
      for (const auto v : s.triangles[f])
        inc.worn_vertex[v] = 1;
    }
  return inc;
}

// An increment that takes a worn vertex down, more than halfway through the worn-through
// layer above the bottom (`floor_z` its top), would carry on past the bottom on the next.
bool overshoots_floor(const meshes::SurfaceMesh& s, const StageIncrement& inc, double floor_z,
                      double worn_through_thickness) {
  bool overshoots = false;
  for (std::size_t v = 0; v < s.n_vertices() && !overshoots; ++v)
    overshoots = inc.worn_vertex[v] && inc.moved.vertices[v].z < s.vertices[v].z &&
                 inc.moved.vertices[v].z < floor_z - 0.5 * worn_through_thickness;
  return overshoots;
}
} // namespace

double bottom_height(const meshes::SurfaceMesh& s) {
  double z = -std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_labels[f] == meshes::label::bottom)
      for (const auto v : s.triangles[f])
        z = std::max(z, s.vertices[v].z);
  return z;
}

void set_aside_worn_through(const meshes::SurfaceMesh& s, double floor_z,
                            std::vector<double>& remaining, WearStageReport& r) {
  r.n_worn_through = 0;
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_wears(f))
      for (const auto v : s.triangles[f])
        if (s.vertices[v].z < floor_z) {
          r.worn_through_volume += remaining[f];
          remaining[f] = 0;
          ++r.n_worn_through;
          break;
        }
}

StageIncrement relaxed_increment(const meshes::SurfaceMesh& s, const std::vector<double>& remaining,
                                 int n_left, double relax) {
  StageIncrement inc = increment_share(s, remaining, n_left);
  const auto constraint = meshes::sliding_constraints(s);
  const auto unworn = unworn_relaxation(s, 0.5, &constraint);
  const auto crease = crease_relaxation(s, 0.5, &constraint);
  // Cutting spikes must stay a small part of the increment (its volume is given back in
  // the recession only up to the increment's own volume); otherwise relax tangentially only.
  for (const double spike_cos : {-0.9, -2.0}) {
    inc.displacement = tangential_relaxation(s, inc.worn_vertex, 0.5 * relax, spike_cos);
    for (std::size_t v = 0; v < inc.displacement.size(); ++v)
      inc.displacement[v] += (unworn[v] + crease[v]) * relax;
    inc.relaxed = s;
    for (std::size_t v = 0; v < inc.relaxed.n_vertices(); ++v)
      inc.relaxed.vertices[v] += inc.displacement[v];
    inc.relaxation_loss = meshes::enclosed_volume(s) - meshes::enclosed_volume(inc.relaxed);
    if (std::abs(inc.relaxation_loss) <= 0.25 * inc.part_sum)
      break;
  }
  return inc;
}

bool relaxation_removes_increment(const StageIncrement& inc, double relax) {
  return inc.part_sum > 0 && inc.relaxation_loss >= inc.part_sum && relax > 0;
}

void recede(StageIncrement& inc) {
  std::vector<double> left = inc.part;
  if (inc.part_sum > 0)
    for (auto& v : left)
      v *= 1 - inc.relaxation_loss / inc.part_sum; // > 0: relaxation_removes_increment is false
  inc.recession = meshes::volume_exact_recession(inc.relaxed, left);
  inc.moved = inc.relaxed;
  for (std::size_t v = 0; v < inc.moved.n_vertices(); ++v) {
    inc.moved.vertices[v] += inc.recession.displacement[v];
    inc.displacement[v] += inc.recession.displacement[v];
  }
}

Verdict judge_increment(const meshes::SurfaceMesh& s, const StageIncrement& inc, double floor_z,
                        const StageSplit& split, const WornSampleParameters& p) {
  Verdict verdict;
  // The secant scaling can end short of the asked volume on a surface that looks valid:
  // such an increment is taken in smaller steps, never handed on short.
  if (inc.recession.missed_target()) {
    verdict.step = split.halvings < p.max_halvings ? NextStep::halve : NextStep::missed_volume;
    return verdict;
  }
  const auto normals = meshes::face_normals(s);
  verdict.quality = meshes::surface_quality(inc.moved, &normals);
  if (verdict.quality.valid())
    verdict.step = overshoots_floor(s, inc, floor_z, p.worn_through_thickness) &&
                           split.halvings < p.max_halvings
                       ? NextStep::halve
                       : NextStep::take;
  else if (split.relax > 0 && !meshes::surface_quality(inc.relaxed, &normals).valid())
    verdict.step = NextStep::relax_less; // no smaller step helps a relaxation that folds
  else if (split.halvings >= p.halvings_before_spreading && split.spreadings < p.max_spreadings)
    verdict.step = NextStep::spread;
  else if (split.halvings == p.max_halvings)
    verdict.step = NextStep::folds;
  else
    verdict.step = NextStep::halve_after_fold;
  return verdict;
}

std::string missed_volume_message(const meshes::Recession& rec, int halvings, int n_taken) {
  return "wear stage: the recession removes " + std::to_string(rec.swept_volume * 1e9) +
         " mm^3 where " + std::to_string(rec.removed_volume * 1e9) +
         " mm^3 is asked, even in increments of 1/" + std::to_string(1 << halvings) +
         " of the stage (" + std::to_string(n_taken) +
         " taken before); reduce the wear per stage (Coupling/Amplification or "
         "Coupling/Maximum depth fraction)";
}

std::string fold_message(const meshes::SurfaceMesh& s, const meshes::SurfaceQuality& quality,
                         int halvings, int n_taken, const std::string& dump) {
  const std::string where =
      quality.first_bad_face < 0
          ? std::string("")
          : " at face " + std::to_string(quality.first_bad_face) + " (label " +
                meshes::label::name(s.face_labels[std::size_t(quality.first_bad_face)]) + ")";
  // Tell apart a step that folds from a surface that already does (then no step helps).
  const bool folded_before = !meshes::surface_quality(s).valid();
  // How thin the sample has worn (sample frame: the clamped bottom is the lowest face).
  const meshes::Vec3 at = lowest_wearing_vertex(s);
  const double bottom_z = bottom_height(s);
  const std::string thickness =
      std::isfinite(at.z) && std::isfinite(bottom_z)
          ? "; the wear face is " + std::to_string((at.z - bottom_z) * 1e3) +
                " mm above the clamped bottom at its lowest, at (" + std::to_string(at.x * 1e3) +
                ", " + std::to_string(at.y * 1e3) + ") mm"
          : std::string();
  return "wear stage: the worn surface folds" + where + " even in increments of 1/" +
         std::to_string(1 << halvings) + " of the stage (" + std::to_string(n_taken) +
         " taken before)" +
         (folded_before ? " (the surface before this increment already folds)" : "") + thickness +
         "; reduce the wear per stage (surface before and after the increment, bad faces "
         "marked: " +
         dump + ")";
}

} // namespace wear::fem

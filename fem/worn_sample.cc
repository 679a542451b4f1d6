// One wear stage on the sample's volume mesh.
//
// The stage is taken in increments, each on the surface the previous one produced
// (fem/stage_increment.cc: the increment's share of the remaining wear, the relaxation of the
// surface, the volume-exact recession meshes::volume_exact_recession, and the verdict on the
// moved surface). An increment whose surface would hold a degenerate, inverted (normal turned
// by more than 90 deg) or self-intersecting face is split in two and tried again, because an
// offset along vertex normals folds where the depth exceeds the local radius of curvature, and
// smaller steps on the updated surface follow the receding front instead. If the relaxation
// alone already folds the surface (large umbrella offsets beside the small triangles of a
// graded remesh), no smaller step helps: it is halved for the rest of the stage, and turned
// off after six halvings. Where even small steps fold (a tip sharpened by wear on one flank:
// the fronts of its two flanks meet), the remaining wear is spread over the fold's
// neighbourhood (meshes::spread_removed_volume, total kept), so the tip recedes as a whole
// instead of being cut into a sliver. The interior follows (move_mesh); if a cell inverts or
// the smallest scaled Jacobian drops below the threshold, the moved surface is remeshed
// (remesh_sample) and the enclosed volume the new chords cut off is given back by a uniform
// normal offset of the wear face (meshes::volume_restoring_offset), so volume is conserved
// across remeshing to round-off of the secant (the wear record is the volume, not the chord
// geometry); where that offset would fold the surface, it is held still within 1, 2, 4, 8
// rings of the fold, and given up if it still folds; what it does not give back (given up, or
// a valid offset short of the target) is reported as volume not restored.
// Accumulated fields follow the faces while the topology is kept and are transferred
// (FaceTransfer: extensive per label, exactly; intensive by area) across a remesh. A wearing
// face with a vertex within `worn_through_thickness` of the clamped bottom is worn through:
// the model has no material left there (a hole would change the topology), so the wear asked
// of it is recorded as worn-through volume instead of removed, and the stage ends with volume
// change = asked - worn through. Increments that would take a vertex more than halfway through
// that layer are split like folding ones, and so are increments whose recession cannot reach
// the asked volume; at the last split that stops the stage with a message instead of handing
// on a surface short of the wear. The implicit path (meshes::implicit_recession) takes what
// it is given in one recession, or with a step depth in as many as keep the deepest face
// within it, each an equal share of what is left, the rest following each new surface by
// FaceTransfer; the volume mesh is remeshed once, from the last surface.
#include "fem/worn_sample.h"

#include "fem/sample_triangulation.h"
#include "fem/stage_increment.h"
#include "meshes/atomic_file.h"
#include "meshes/face_transfer.h"
#include "meshes/mesh_quality.h"
#include "meshes/recession.h"
#include "meshes/vtu_writer.h"

#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace wear::fem {

namespace {

/// The two accumulated fields of a sample on `surface`, zero: the volume each face has lost
/// (extensive) and the depth it has receded (intensive).
meshes::FaceField<double> removed_volume_field(const meshes::SurfaceMesh& surface) {
  return {"removed volume", "m^3", meshes::Extensivity::extensive, surface};
}
meshes::FaceField<double> wear_depth_field(const meshes::SurfaceMesh& surface) {
  return {"wear depth", "m", meshes::Extensivity::intensive, surface};
}
// The stage's removed volume on the wear face only (sides and bottom do not recede); its sum
// goes to r.removed_volume.
meshes::FaceField<double> wear_face_share(const meshes::FaceField<double>& removed,
                                          const meshes::SurfaceMesh& surface, WearStageReport& r) {
  removed.check_matches(surface);
  if (!removed.extensive())
    throw std::invalid_argument("wear stage: the field '" + removed.name() +
                                "' is intensive; removed volume per face [m^3] is expected");
  meshes::FaceField<double> remaining = removed;
  for (std::size_t f = 0; f < remaining.size(); ++f) {
    if (!surface.face_wears(f))
      remaining[f] = 0;
    r.removed_volume += remaining[f];
  }
  return remaining;
}

// Halves the relaxation for the rest of the stage, and turns it off after six halvings (so it
// is when its own volume loss would be the whole increment, leaving the recession nothing).
void relax_less(StageSplit& split, WearStageReport& r) {
  split.relax = split.relax > 1.0 / 32 ? 0.5 * split.relax : 0.0;
  ++r.n_relaxation_halvings;
}

// Adds one remesh of the stage to its report.
void record_remesh(const RemeshReport& remesh, WearStageReport& r) {
  r.last_remesh = remesh;
  if (remesh.attempt == 1)
    ++r.n_first_attempt_remeshes;
  if (!remesh.failed_attempts.empty())
    r.remesh_refusals.push_back(remesh.failed_attempts);
  if (remesh.restore_held_rings > 0)
    ++r.n_held_restorations;
  r.volume_not_restored += remesh.volume_not_restored;
  ++r.n_remeshes;
  r.remesh_seconds += remesh.seconds;
}

// A remeshed sample as read back: its triangulation and the map of its boundary surface.
struct Remeshed {
  std::unique_ptr<dealii::Triangulation<3>> tria;
  std::unique_ptr<BoundaryFaceMap> map;
};

// Remeshes `worn` into `path` and reads it back. The surface is taken from the triangulation
// as read (the .msh text need not round-trip gmsh's doubles bit for bit).
Remeshed remesh_and_read(const meshes::SurfaceMesh& worn, const RemeshParameters& p,
                         const std::string& path, RemeshReport& report, SurfaceKind kind) {
  remesh_sample(worn, p, path, &report, kind);
  Remeshed out;
  out.tria = std::make_unique<dealii::Triangulation<3>>();
  read_sample_mesh(path, *out.tria);
  auto fresh = extract_boundary_surface(*out.tria, worn.roles);
  for (std::size_t f = 0; f < fresh.n_faces(); ++f)
    if (fresh.face_labels[f] == 0)
      throw std::runtime_error("remeshing: '" + path + "' holds a boundary face without a label");
  fresh.set_revision(worn.revision() + 1);
  out.map = std::make_unique<BoundaryFaceMap>(*out.tria, fresh);
  return out;
}

// The offset of the remeshed surface `fresh` that gives back the volume the chords cut off,
// up to the enclosed volume `target` [m^3]. Beside a low, nearly folded remnant of a worn
// element the offset itself can fold the surface (50x wear-out, stage 15: cos -0.952 across a
// C12-base edge after an offset of a few um); then it is held still within 1, 2, 4, 8 rings of
// the fold, and the rest of the wear face takes its share. What it does not give back is
// reported in report.volume_not_restored, the rings in report.restore_held_rings.
std::vector<meshes::Vec3> fold_free_restoring_offset(const meshes::SurfaceMesh& fresh,
                                                     double target, RemeshReport& report) {
  const auto normals = meshes::face_normals(fresh);
  std::vector<meshes::Vec3> taken;
  const int rings = meshes::hold_still_around_folds(fresh, [&](const std::vector<char>& held) {
    const bool any_held = std::find(held.begin(), held.end(), 1) != held.end();
    const auto restoring =
        meshes::volume_restoring_offset(fresh, target, any_held ? &held : nullptr);
    meshes::SurfaceMesh candidate = fresh;
    for (std::size_t v = 0; v < candidate.n_vertices(); ++v)
      candidate.vertices[v] += restoring.displacement[v];
    auto q = meshes::surface_quality(candidate, &normals);
    if (q.valid()) {
      // The secant scaling can end short of the target (an offset that stops sweeping volume,
      // or free faces too few to hold it): the valid offset is kept, and what it does not
      // give back is reported, never counted as restored.
      if (restoring.missed_target())
        report.volume_not_restored = restoring.removed_volume - restoring.swept_volume;
      taken = restoring.displacement;
    }
    return q;
  });
  if (rings < 0) {
    // Every restoring offset folded: hand on the remeshed surface (valid: remesh_sample
    // refuses folds) with the chord volume not given back.
    report.restore_held_rings = 8;
    report.volume_not_restored = meshes::enclosed_volume(fresh) - target;
    return std::vector<meshes::Vec3>(fresh.n_vertices());
  }
  if (rings > 0)
    report.restore_held_rings = rings;
  return taken;
}
} // namespace

WornSample::WornSample(const std::string& msh_path, const meshes::LabelRoles& roles,
                       const WornSampleParameters& p)
    : p_(p) {
  tria_ = std::make_unique<dealii::Triangulation<3>>();
  read_sample_mesh(msh_path, *tria_);
  set_surface(extract_boundary_surface(*tria_, roles));
}

WornSample::WornSample(const std::string& msh_path, const meshes::SurfaceMesh& surface,
                       const WornSampleParameters& p)
    : p_(p) {
  tria_ = std::make_unique<dealii::Triangulation<3>>();
  read_sample_mesh(msh_path, *tria_);
  set_surface(surface);
}

WornSample::WornSample(const WornSampleState& st, const WornSampleParameters& p) : p_(p) {
  if (st.vertices.empty() && st.tetrahedra.empty() && st.boundary_ids.empty()) {
    mesh_kept_surface(st);
    return;
  }
  const std::size_t nv = st.vertices.size() / 3, nc = st.tetrahedra.size() / 4;
  if (st.vertices.size() != 3 * nv || st.tetrahedra.size() != 4 * nc || nc == 0 ||
      st.boundary_faces.size() != 3 * st.boundary_ids.size())
    throw std::runtime_error("worn sample state: mesh arrays of inconsistent sizes");
  std::vector<dealii::Point<3>> points(nv);
  for (std::size_t v = 0; v < nv; ++v)
    points[v] =
        dealii::Point<3>(st.vertices[3 * v], st.vertices[3 * v + 1], st.vertices[3 * v + 2]);
  std::vector<dealii::CellData<3>> cells(nc, dealii::CellData<3>(4));
  for (std::size_t c = 0; c < nc; ++c)
    for (unsigned int k = 0; k < 4; ++k) {
      const auto v = st.tetrahedra[4 * c + k];
      if (v < 0 || std::size_t(v) >= nv)
        throw std::runtime_error("worn sample state: tetrahedron " + std::to_string(c) +
                                 " refers to a missing vertex");
      cells[c].vertices[k] = unsigned(v);
    }
  tria_ = std::make_unique<dealii::Triangulation<3>>();
  tria_->create_triangulation(points, cells, dealii::SubCellData());
  using Key = std::array<std::int64_t, 3>;
  std::map<Key, int> id_of;
  for (std::size_t f = 0; f < st.boundary_ids.size(); ++f) {
    Key k{st.boundary_faces[3 * f], st.boundary_faces[3 * f + 1], st.boundary_faces[3 * f + 2]};
    std::sort(k.begin(), k.end());
    id_of[k] = st.boundary_ids[f];
  }
  for (const auto& cell : tria_->active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary()) {
        Key k{cell->face(f)->vertex_index(0), cell->face(f)->vertex_index(1),
              cell->face(f)->vertex_index(2)};
        std::sort(k.begin(), k.end());
        const auto it = id_of.find(k);
        if (it == id_of.end())
          throw std::runtime_error("worn sample state: a boundary face has no label");
        cell->face(f)->set_boundary_id(dealii::types::boundary_id(it->second));
      }
  set_surface(st.surface);
  if (st.removed_volume.size() != removed_.size() || st.wear_depth.size() != depth_.size())
    throw std::runtime_error("worn sample state: face fields do not match the surface");
  removed_.values() = st.removed_volume;
  depth_.values() = st.wear_depth;
  n_remeshes_ = st.n_remeshes;
}

void WornSample::mesh_kept_surface(const WornSampleState& st) {
  // The kept surface is gmsh's own from the last remesh (or the generated sample's): its
  // triangles are kept and only the volume is meshed (the attempt order of an isotropic
  // surface, with no sharp edges to add); another attempt remeshes it and the fields follow
  // by the conservative face transfer, the volume restored as after every remesh.
  if (st.removed_volume.size() != st.surface.n_faces() ||
      st.wear_depth.size() != st.surface.n_faces())
    throw std::runtime_error("worn sample state: face fields do not match the surface");
  removed_ = removed_volume_field(st.surface);
  depth_ = wear_depth_field(st.surface);
  removed_.values() = st.removed_volume;
  depth_.values() = st.wear_depth;
  // The kept surface was meshed once as it is: its triangles are kept again.
  remesh_from(st.surface, SurfaceKind::isotropic);
  n_remeshes_ = st.n_remeshes;
}

WornSampleState triangulation_state(const dealii::Triangulation<3>& tria,
                                    const meshes::SurfaceMesh& surface) {
  WornSampleState st;
  for (const auto& v : tria.get_vertices())
    for (int d = 0; d < 3; ++d)
      st.vertices.push_back(v[d]);
  for (const auto& cell : tria.active_cell_iterators()) {
    for (unsigned int k = 0; k < 4; ++k)
      st.tetrahedra.push_back(cell->vertex_index(k));
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary()) {
        for (unsigned int k = 0; k < 3; ++k)
          st.boundary_faces.push_back(cell->face(f)->vertex_index(k));
        st.boundary_ids.push_back(int(cell->face(f)->boundary_id()));
      }
  }
  st.surface = surface;
  st.removed_volume.assign(st.surface.n_faces(), 0);
  st.wear_depth.assign(st.surface.n_faces(), 0);
  return st;
}

WornSampleState WornSample::state() const {
  WornSampleState st = triangulation_state(*tria_, surface());
  st.removed_volume = removed_.values();
  st.wear_depth = depth_.values();
  st.n_remeshes = n_remeshes_;
  return st;
}

void WornSample::set_surface(const meshes::SurfaceMesh& surface) {
  bool clamped = false;
  for (std::size_t f = 0; f < surface.n_faces() && !clamped; ++f)
    clamped = surface.face_role(f) == meshes::FaceRole::clamped;
  if (!clamped)
    throw std::runtime_error("the sample's surface has no clamped face (a label with the role "
                             "clamped: the sample's bottom, a part's Clamped surfaces); the FEM "
                             "would have nothing to hold it");
  map_ = std::make_unique<BoundaryFaceMap>(*tria_, surface);
  removed_ = removed_volume_field(surface);
  depth_ = wear_depth_field(surface);
}

WearStageReport WornSample::apply_wear(const meshes::FaceField<double>& removed) {
  WearStageReport r;
  meshes::FaceField<double> remaining = wear_face_share(removed, surface(), r);
  const double volume_before = mesh_volume(*tria_);
  StageSplit split;
  if (p_.evolution == SurfaceEvolution::implicit) {
    take_implicit(remaining, r);
    split.n_left = 0;
  }
  while (split.n_left > 0) {
    const meshes::SurfaceMesh& s = surface();
    const double floor_z = bottom_height(s) + p_.worn_through_thickness;
    set_aside_worn_through(s, floor_z, remaining.values(), r);
    StageIncrement inc = relaxed_increment(s, remaining.values(), split.n_left, split.relax);
    if (relaxation_removes_increment(inc, split.relax)) {
      relax_less(split, r);
      continue;
    }
    recede(inc);
    const Verdict verdict = judge_increment(s, inc, floor_z, split, p_);
    const bool gives_up =
        verdict.step == NextStep::folds || verdict.step == NextStep::missed_volume;
    if (gives_up && p_.evolution == SurfaceEvolution::explicit_then_implicit &&
        try_implicit(remaining, r))
      break;
    if (verdict.step != NextStep::take) {
      retry_increment(verdict, inc, split, remaining.values(), r);
      continue;
    }
    split.spreadings = 0;
    --split.n_left;
    if (take_increment(inc, remaining, r))
      break;
  }
  r.volume_change = volume_before - mesh_volume(*tria_);
  r.quality = volume_quality(*tria_);
  return r;
}

void WornSample::retry_increment(const Verdict& verdict, const StageIncrement& inc,
                                 StageSplit& split, std::vector<double>& remaining,
                                 WearStageReport& r) const {
  switch (verdict.step) {
  case NextStep::relax_less:
    relax_less(split, r);
    break;
  case NextStep::halve_after_fold:
    split.spreadings = 0; // spread again at the smaller increment
    [[fallthrough]];
  case NextStep::halve:
    split.n_left *= 2;
    ++split.halvings;
    break;
  case NextStep::spread:
    r.spread_volume += meshes::spread_removed_volume(
        surface(), remaining, verdict.quality.bad_faces, 2 << split.spreadings);
    ++split.spreadings;
    ++r.n_spreadings;
    break;
  case NextStep::missed_volume:
    throw std::runtime_error(missed_volume_message(inc.recession, split.halvings, r.increments));
  case NextStep::folds:
    throw std::runtime_error(
        fold_message(surface(), verdict.quality, split.halvings, r.increments,
                     write_failed_increment(surface(), inc.moved, verdict.quality.bad_faces)));
  case NextStep::take:
    break;
  }
}

bool WornSample::take_increment(const StageIncrement& inc, meshes::FaceField<double>& remaining,
                                WearStageReport& r) {
  MotionReport motion;
  auto moved = move_mesh(*tria_, *map_, inc.displacement, &motion);
  r.motion_seconds += motion.seconds;
  const bool remeshes = motion.quality.n_inverted > 0 ||
                        motion.quality.min_scaled_jacobian < p_.remesh_min_scaled_jacobian;
  if (!remeshes) {
    accumulate(inc.part, remaining.values(), surface());
    ++r.increments;
    map_->follow(*tria_, std::move(moved));
    removed_.follow(surface());
    depth_.follow(surface());
    remaining.follow(surface());
    return false;
  }
  // The moved triangulation is discarded: only its surface (valid, checked) is used. Its
  // accumulated wear is taken back if every attempt to remesh it fails (the remesher throws
  // before the sample changes), so that the implicit step can take the whole of what was
  // left before this increment, from the surface before it.
  const FieldSnapshot before = snapshot(remaining);
  accumulate(inc.part, remaining.values(), surface());
  remaining.follow(moved);
  try {
    record_remesh(remesh_from(moved), r);
  } catch (const std::exception& e) {
    if (p_.evolution != SurfaceEvolution::explicit_then_implicit)
      throw;
    r.explicit_remesh_failures.push_back(e.what());
    restore(before, remaining);
    try {
      take_implicit(remaining, r);
    } catch (const std::exception& implicit) {
      throw std::runtime_error("the moved surface could not be remeshed (" + std::string(e.what()) +
                               "), nor could the implicit recession take the rest of the stage (" +
                               implicit.what() + ")");
    }
    return true;
  }
  ++r.increments;
  remaining = meshes::FaceTransfer(moved, surface()).apply(remaining);
  return false;
}

bool WornSample::try_implicit(meshes::FaceField<double>& remaining, WearStageReport& r) {
  const FieldSnapshot before = snapshot(remaining);
  const WearStageReport report_before = r;
  try {
    take_implicit(remaining, r);
    return true;
  } catch (const std::exception& e) {
    // The sample is as it was (the remesher throws before it changes); the fields and the
    // report are put back, and the explicit path goes on.
    restore(before, remaining);
    r = report_before;
    r.implicit_failures.push_back(e.what());
    return false;
  }
}

void WornSample::accumulate(const std::vector<double>& part, std::vector<double>& remaining,
                            const meshes::SurfaceMesh& on) {
  const auto area = meshes::face_areas(on);
  for (std::size_t f = 0; f < part.size(); ++f) {
    const double v = part[f]; // part may be remaining itself
    removed_[f] += v;
    depth_[f] += v / area[f];
    remaining[f] -= v;
  }
}

int WornSample::implicit_steps(const meshes::SurfaceMesh& worn,
                               const std::vector<double>& remaining) const {
  if (p_.implicit_step_depth <= 0)
    return 1;
  const auto area = meshes::face_areas(worn);
  double deepest = 0;
  for (std::size_t f = 0; f < remaining.size(); ++f)
    deepest = std::max(deepest, remaining[f] / area[f]);
  // A face asked for a whole number of step depths takes that many steps, not one more for
  // the round-off of its volume over its area.
  const double n = std::ceil(deepest / p_.implicit_step_depth * (1 - 1e-9));
  return int(std::clamp(n, 1.0, double(max_implicit_steps)));
}

void WornSample::take_implicit(meshes::FaceField<double>& remaining, WearStageReport& r) {
  meshes::SurfaceMesh worn = surface();
  const int n_steps = implicit_steps(worn, remaining.values());
  for (int left = n_steps; left > 0; --left) {
    // Each step takes an equal share of what is left, so the last takes the rest.
    std::vector<double> part = remaining.values();
    for (double& v : part) // the carried rest may hold round-off below zero
      v = std::max(v, 0.0) / left;
    const auto receded = meshes::implicit_recession(worn, part, p_.implicit);
    accumulate(part, remaining.values(), worn);
    ++r.increments;
    ++r.n_implicit;
    r.implicit_seconds += receded.seconds;
    r.implicit_grid_loss += receded.grid_loss;
    r.n_fragments += receded.n_fragments;
    r.fragment_volume += receded.fragment_volume;
    r.n_teeth_joined += receded.n_teeth_joined;
    r.n_folds_mended += receded.n_folds_mended;
    r.n_folds_left += receded.n_folds_left;
    r.n_held_restorations += receded.restore_held_rings > 0;
    r.volume_not_restored += receded.volume_not_restored;
    r.worn_through_area += receded.worn_through_area;
    r.vanished_labels.insert(r.vanished_labels.end(), receded.vanished_labels.begin(),
                             receded.vanished_labels.end());
    const meshes::FaceTransfer transfer(worn, receded.surface);
    carry_fields(worn, transfer);
    remaining.follow(worn);
    remaining = transfer.apply(remaining);
    worn = receded.surface;
  }
  record_remesh(remesh_from(worn, SurfaceKind::isotropic), r);
}

std::string WornSample::write_failed_increment(const meshes::SurfaceMesh& before,
                                               const meshes::SurfaceMesh& after,
                                               const std::vector<std::uint32_t>& bad_faces) const {
  meshes::ensure_directory(p_.mesh_directory);
  meshes::FaceField<double> bad("bad face", "-", meshes::Extensivity::intensive, before);
  for (const auto f : bad_faces)
    bad[f] = 1;
  const std::string stem = p_.mesh_directory + "/wear-failed-r" + std::to_string(before.revision());
  meshes::write_vtu(before, stem + "-before.vtu", {&bad});
  bad.follow(after);
  meshes::write_vtu(after, stem + "-after.vtu", {&bad});
  return stem + "-{before,after}.vtu";
}

RemeshReport WornSample::remesh() {
  return remesh_from(surface());
}

RemeshReport WornSample::remesh_from(const meshes::SurfaceMesh& worn, SurfaceKind kind) {
  meshes::ensure_directory(p_.mesh_directory);
  const std::string path =
      p_.mesh_directory + "/sample-r" + std::to_string(worn.revision() + 1) + ".msh";
  RemeshReport report;
  Remeshed fresh = remesh_and_read(worn, p_.remesh, path, report, kind);
  const auto offset =
      fold_free_restoring_offset(fresh.map->surface(), meshes::enclosed_volume(worn), report);
  MotionReport motion;
  auto restored = move_mesh(*fresh.tria, *fresh.map, offset, &motion);
  fresh.map->follow(*fresh.tria, std::move(restored));
  carry_fields(worn, fresh.map->surface());
  tria_ = std::move(fresh.tria);
  map_ = std::move(fresh.map);
  ++n_remeshes_;
  report.volume_restored = mesh_volume(*tria_);
  report.seconds += motion.seconds;
  return report;
}

void WornSample::carry_fields(const meshes::SurfaceMesh& worn, const meshes::SurfaceMesh& fresh) {
  carry_fields(worn, meshes::FaceTransfer(worn, fresh));
}

void WornSample::carry_fields(const meshes::SurfaceMesh& worn,
                              const meshes::FaceTransfer& to_fresh) {
  meshes::FaceField<double> removed = removed_, depth = depth_;
  removed.follow(worn);
  depth.follow(worn);
  removed_ = to_fresh.apply(removed);
  depth_ = to_fresh.apply(depth);
}

} // namespace wear::fem

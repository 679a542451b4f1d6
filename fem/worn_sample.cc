// One wear stage on the sample's volume mesh.
//
// Per increment: the worn region is first relaxed tangentially (tangential_relaxation: the
// triangles of a receding tip would otherwise be squeezed into slivers), and so is the unworn
// surface within its flat sides (unworn_relaxation: the side strip under the receding edge of
// the wear face would fold), then the recession of the
// removed volume (compute_recession, volume-exact) is tried on the surface first; if the moved
// surface would hold a degenerate, inverted (normal turned by more than 90 deg) or
// self-intersecting face, the stage is split in two and tried again, because an offset along vertex
// normals folds where the depth exceeds the local radius of curvature, and smaller steps on the
// updated surface follow the receding front instead. If the relaxation alone already folds the
// surface (large umbrella offsets beside the small triangles of a graded remesh), no smaller step
// helps: it is halved for the rest of the stage, and turned off after six halvings (so it is
// when its own volume loss would be the whole increment, leaving the recession nothing). Where even
// small steps fold (a tip sharpened by wear on one flank: the fronts of its two flanks meet), the
// remaining wear is spread over the fold's neighbourhood (meshes::spread_removed_volume, total
// kept), so the tip recedes as a whole instead of being cut into a sliver. The interior follows
// (move_mesh); if a cell inverts or the smallest scaled Jacobian drops below the threshold, the
// moved surface is remeshed (remesh_sample) and the enclosed volume the new chords cut off is given
// back by a uniform normal offset of the wear face, so volume is conserved across remeshing to
// round-off of the secant (the wear record is the volume, not the chord geometry); where that
// offset would fold the surface, it is held still within 1, 2, 4, 8 rings of the fold, and
// given up if it still folds; what it does not give back (given up, or a valid offset short
// of the target) is reported as volume not restored.
// Accumulated fields follow the faces while the topology is kept and are transferred (FaceTransfer:
// extensive per label, exactly; intensive by area) across a remesh. A wearing face with a vertex
// within `worn_through_thickness` of the clamped bottom is worn through: the model has no material
// left there (a hole would change the topology), so the wear asked of it is recorded as
// worn-through volume instead of removed, and the stage ends with volume change = asked - worn
// through. Increments that would take a vertex more than halfway through that layer are split like
// folding ones, and so are increments whose recession cannot reach the asked volume (one vertex
// carried far past its neighbours: the swept volume stops growing with the offset); at the last
// split that stops the stage with a message instead of handing on a surface short of the wear.
#include "fem/worn_sample.h"

#include "fem/sample_triangulation.h"
#include "meshes/atomic_file.h"
#include "meshes/face_transfer.h"
#include "meshes/mesh_quality.h"
#include "meshes/recession.h"
#include "meshes/sliding_constraint.h"
#include "meshes/vtu_writer.h"

#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace wear::fem {

namespace {
// Height of the clamped bottom in the sample frame (its highest vertex; the bottom is flat),
// or -infinity for a surface without one.
double bottom_height(const meshes::SurfaceMesh& s) {
  double z = -std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_labels[f] == meshes::label::bottom)
      for (const auto v : s.triangles[f])
        z = std::max(z, s.vertices[v].z);
  return z;
}

// The lowest vertex of the wear face, whose faces are the first to wear through.
meshes::Vec3 lowest_wearing_vertex(const meshes::SurfaceMesh& s) {
  meshes::Vec3 at{0, 0, std::numeric_limits<double>::infinity()};
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (meshes::label::wears(s.face_labels[f]))
      for (const auto v : s.triangles[f])
        if (s.vertices[v].z < at.z)
          at = s.vertices[v];
  return at;
}
} // namespace

WornSample::WornSample(const std::string& msh_path, const WornSampleParameters& p) : p_(p) {
  tria_ = std::make_unique<dealii::Triangulation<3>>();
  read_sample_mesh(msh_path, *tria_);
  set_surface(extract_boundary_surface(*tria_));
}

WornSample::WornSample(const std::string& msh_path, const meshes::SurfaceMesh& surface,
                       const WornSampleParameters& p)
    : p_(p) {
  tria_ = std::make_unique<dealii::Triangulation<3>>();
  read_sample_mesh(msh_path, *tria_);
  set_surface(surface);
}

WornSample::WornSample(const WornSampleState& st, const WornSampleParameters& p) : p_(p) {
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
  map_ = std::make_unique<BoundaryFaceMap>(*tria_, st.surface);
  removed_ = meshes::FaceField<double>("removed volume", "m^3", meshes::Extensivity::extensive,
                                       st.surface);
  depth_ = meshes::FaceField<double>("wear depth", "m", meshes::Extensivity::intensive, st.surface);
  if (st.removed_volume.size() != removed_.size() || st.wear_depth.size() != depth_.size())
    throw std::runtime_error("worn sample state: face fields do not match the surface");
  removed_.values() = st.removed_volume;
  depth_.values() = st.wear_depth;
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
  map_ = std::make_unique<BoundaryFaceMap>(*tria_, surface);
  removed_ =
      meshes::FaceField<double>("removed volume", "m^3", meshes::Extensivity::extensive, surface);
  depth_ = meshes::FaceField<double>("wear depth", "m", meshes::Extensivity::intensive, surface);
}

WearStageReport WornSample::apply_wear(const meshes::FaceField<double>& removed) {
  removed.check_matches(surface());
  if (!removed.extensive())
    throw std::invalid_argument("wear stage: the field '" + removed.name() +
                                "' is intensive; removed volume per face [m^3] is expected");
  WearStageReport r;
  const double volume_before = mesh_volume(*tria_);
  meshes::FaceField<double> remaining = removed;
  for (std::size_t f = 0; f < remaining.size(); ++f) {
    if (!meshes::label::wears(surface().face_labels[f]))
      remaining[f] = 0; // sides and bottom do not recede
    r.removed_volume += remaining[f];
  }
  int n_left = 1, halvings = 0, spreadings = 0;
  // Fraction of the relaxations applied. The umbrella offsets of a graded mesh (a remesh
  // refines where the surface curves) can be large next to small triangles, and moving every
  // vertex at once can turn one of them over whatever the increment; then the relaxation, not
  // the recession, folds the surface, and it is halved for the rest of the stage.
  double relax = 1;
  const auto relax_less = [&] {
    relax = relax > 1.0 / 32 ? 0.5 * relax : 0.0;
    ++r.n_relaxation_halvings;
  };
  while (n_left > 0) {
    const auto& s = surface();
    // Faces worn down to the clamped bottom have no material left: what is asked of them is
    // recorded, and the recession below acts on the rest of the wear face only.
    const double floor_z = bottom_height(s) + p_.worn_through_thickness;
    r.n_worn_through = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f)
      if (meshes::label::wears(s.face_labels[f]))
        for (const auto v : s.triangles[f])
          if (s.vertices[v].z < floor_z) {
            r.worn_through_volume += remaining[f];
            remaining[f] = 0;
            ++r.n_worn_through;
            break;
          }
    std::vector<double> part = remaining.values();
    for (auto& v : part)
      v /= n_left;
    // Relax the worn region tangentially, then recede the relaxed surface by what remains
    // of the increment's volume, so the enclosed volume still drops by exactly sum(part).
    std::vector<char> worn_vertex(s.n_vertices(), 0);
    double part_sum = 0;
    for (std::size_t f = 0; f < part.size(); ++f)
      if (part[f] > 0) {
        part_sum += part[f];
        for (const auto v : s.triangles[f])
          worn_vertex[v] = 1;
      }
    const auto constraint = meshes::sliding_constraints(s);
    const auto unworn = unworn_relaxation(s, 0.5, &constraint);
    const auto crease = crease_relaxation(s, 0.5, &constraint);
    std::vector<meshes::Vec3> displacement;
    meshes::SurfaceMesh candidate;
    double relaxation_loss = 0;
    // Cutting spikes must stay a small part of the increment (its volume is given back in
    // the recession only up to the increment's own volume); otherwise relax tangentially only.
    for (const double spike_cos : {-0.9, -2.0}) {
      displacement = tangential_relaxation(s, worn_vertex, 0.5 * relax, spike_cos);
      for (std::size_t v = 0; v < displacement.size(); ++v)
        displacement[v] += (unworn[v] + crease[v]) * relax;
      candidate = s;
      for (std::size_t v = 0; v < candidate.n_vertices(); ++v)
        candidate.vertices[v] += displacement[v];
      relaxation_loss = meshes::enclosed_volume(s) - meshes::enclosed_volume(candidate);
      if (std::abs(relaxation_loss) <= 0.25 * part_sum)
        break;
    }
    // A relaxation that alone removes the whole increment would leave the recession nothing
    // to scale (and the increment would remove more than asked): relax less.
    if (part_sum > 0 && relaxation_loss >= part_sum && relax > 0) {
      relax_less();
      continue;
    }
    std::vector<double> recede = part;
    if (part_sum > 0)
      for (auto& v : recede)
        v *= 1 - relaxation_loss / part_sum; // > 0: checked above (relax = 0 loses nothing)
    const meshes::SurfaceMesh relaxed = candidate;
    const auto rec = compute_recession(candidate, recede);
    for (std::size_t v = 0; v < candidate.n_vertices(); ++v) {
      candidate.vertices[v] += rec.displacement[v];
      displacement[v] += rec.displacement[v];
    }
    // One increment that would carry a vertex far past its neighbours can leave no offset at
    // which the enclosed volume drops by the asked amount (the swept volume stops growing
    // with the offset); the secant scaling then ends short of it, on a surface that looks
    // valid. Such an increment is taken in smaller steps, never handed on short.
    if (rec.missed_target()) {
      if (halvings < p_.max_halvings) {
        n_left *= 2;
        ++halvings;
        continue;
      }
      throw std::runtime_error(
          "wear stage: the recession removes " + std::to_string(rec.swept_volume * 1e9) +
          " mm^3 where " + std::to_string(rec.removed_volume * 1e9) +
          " mm^3 is asked, even in increments of 1/" + std::to_string(1 << halvings) +
          " of the stage (" + std::to_string(r.increments) +
          " taken before); reduce the wear per stage (Coupling/Amplification or "
          "Coupling/Maximum depth fraction)");
    }
    const auto normals = meshes::face_normals(s);
    const auto sq = meshes::surface_quality(candidate, &normals);
    // An increment that takes a vertex more than halfway through the worn-through layer
    // would carry on past the bottom on the next: take it in smaller steps.
    bool overshoots = false;
    for (std::size_t v = 0; v < s.n_vertices() && !overshoots; ++v)
      overshoots = worn_vertex[v] && candidate.vertices[v].z < s.vertices[v].z &&
                   candidate.vertices[v].z < floor_z - 0.5 * p_.worn_through_thickness;
    if (sq.valid() && overshoots && halvings < p_.max_halvings) {
      n_left *= 2;
      ++halvings;
      continue;
    }
    if (!sq.valid() && relax > 0 && !meshes::surface_quality(relaxed, &normals).valid()) {
      relax_less();
      continue;
    }
    if (!sq.valid()) {
      if (halvings >= p_.halvings_before_spreading && spreadings < p_.max_spreadings) {
        r.spread_volume +=
            meshes::spread_removed_volume(s, remaining.values(), sq.bad_faces, 2 << spreadings);
        ++spreadings;
        ++r.n_spreadings;
        continue;
      }
      if (halvings == p_.max_halvings) {
        const std::string where =
            sq.first_bad_face < 0
                ? std::string("")
                : " at face " + std::to_string(sq.first_bad_face) + " (label " +
                      meshes::label::name(s.face_labels[std::size_t(sq.first_bad_face)]) + ")";
        // Tell apart a step that folds from a surface that already does (then no step helps).
        const bool folded_before = !meshes::surface_quality(s).valid();
        const std::string dump = write_failed_increment(s, candidate, sq.bad_faces);
        // How thin the sample has worn (sample frame: the clamped bottom is the lowest face).
        const meshes::Vec3 at = lowest_wearing_vertex(s);
        const double bottom_z = bottom_height(s);
        const std::string thickness =
            std::isfinite(at.z) && std::isfinite(bottom_z)
                ? "; the wear face is " + std::to_string((at.z - bottom_z) * 1e3) +
                      " mm above the clamped bottom at its lowest, at (" +
                      std::to_string(at.x * 1e3) + ", " + std::to_string(at.y * 1e3) + ") mm"
                : std::string();
        throw std::runtime_error(
            "wear stage: the worn surface folds" + where + " even in increments of 1/" +
            std::to_string(1 << halvings) + " of the stage (" + std::to_string(r.increments) +
            " taken before)" +
            (folded_before ? " (the surface before this increment already folds)" : "") +
            thickness +
            "; reduce the wear per stage (surface before and after the increment, bad faces "
            "marked: " +
            dump + ")");
      }
      n_left *= 2;
      ++halvings;
      spreadings = 0; // spread again at the smaller increment
      continue;
    }
    spreadings = 0;
    const auto area = meshes::face_areas(s);
    for (std::size_t f = 0; f < part.size(); ++f) {
      removed_[f] += part[f];
      depth_[f] += part[f] / area[f];
      remaining[f] -= part[f];
    }
    MotionReport motion;
    auto moved = move_mesh(*tria_, *map_, displacement, &motion);
    r.motion_seconds += motion.seconds;
    ++r.increments;
    --n_left;
    if (motion.quality.n_inverted > 0 ||
        motion.quality.min_scaled_jacobian < p_.remesh_min_scaled_jacobian) {
      // The moved triangulation is discarded: only its surface (valid, checked above) is used.
      remaining.follow(moved);
      r.last_remesh = remesh_from(moved);
      if (!r.last_remesh.failed_attempts.empty())
        r.remesh_refusals.push_back(r.last_remesh.failed_attempts);
      if (r.last_remesh.restore_held_rings > 0)
        ++r.n_held_restorations;
      r.volume_not_restored += r.last_remesh.volume_not_restored;
      ++r.n_remeshes;
      r.remesh_seconds += r.last_remesh.seconds;
      remaining = meshes::FaceTransfer(moved, surface()).apply(remaining);
    } else {
      map_->follow(*tria_, std::move(moved));
      removed_.follow(surface());
      depth_.follow(surface());
      remaining.follow(surface());
    }
  }
  r.volume_change = volume_before - mesh_volume(*tria_);
  r.quality = volume_quality(*tria_);
  return r;
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

RemeshReport WornSample::remesh_from(const meshes::SurfaceMesh& worn) {
  meshes::ensure_directory(p_.mesh_directory);
  const std::string path =
      p_.mesh_directory + "/sample-r" + std::to_string(worn.revision() + 1) + ".msh";
  RemeshReport report;
  remesh_sample(worn, p_.remesh, path, &report);
  auto tria = std::make_unique<dealii::Triangulation<3>>();
  read_sample_mesh(path, *tria);
  // The surface is taken from the triangulation as read (the .msh text need not round-trip
  // gmsh's doubles bit for bit).
  auto fresh = extract_boundary_surface(*tria);
  for (std::size_t f = 0; f < fresh.n_faces(); ++f)
    if (fresh.face_labels[f] == 0)
      throw std::runtime_error("remeshing: '" + path + "' holds a boundary face without a label");
  fresh.set_revision(worn.revision() + 1);
  auto map = std::make_unique<BoundaryFaceMap>(*tria, fresh);
  // Give back the volume the chords cut off. Beside a low, nearly folded remnant of a worn
  // element the offset itself can fold the surface (50x wear-out, stage 15: cos -0.952 across a
  // C12-base edge after an offset of a few um); then it is held still around the fold, and the
  // rest of the wear face takes its share.
  const double target = meshes::enclosed_volume(worn);
  const auto normals = meshes::face_normals(fresh);
  std::vector<char> held(fresh.n_faces(), 0);
  std::vector<meshes::Vec3> offset;
  for (int rings = 0;;) {
    const auto restoring = volume_restoring_offset(fresh, target, rings > 0 ? &held : nullptr);
    offset = restoring.displacement;
    meshes::SurfaceMesh candidate = fresh;
    for (std::size_t v = 0; v < candidate.n_vertices(); ++v)
      candidate.vertices[v] += offset[v];
    const auto q = meshes::surface_quality(candidate, &normals);
    if (q.valid()) {
      // The secant scaling can end short of the target (an offset that stops sweeping volume,
      // or free faces too few to hold it): the valid offset is kept, and what it does not
      // give back is reported, never counted as restored.
      if (restoring.missed_target())
        report.volume_not_restored = restoring.removed_volume - restoring.swept_volume;
      break;
    }
    if (rings == 8) {
      // Every restoring offset folded: hand on the remeshed surface (valid: remesh_sample
      // refuses folds) with the chord volume not given back.
      offset.assign(fresh.n_vertices(), {});
      report.volume_not_restored = meshes::enclosed_volume(fresh) - target;
      break;
    }
    rings = rings == 0 ? 1 : 2 * rings;
    const auto around = meshes::faces_within_rings(fresh, q.bad_faces, rings);
    for (std::size_t f = 0; f < held.size(); ++f)
      held[f] |= around[f];
    report.restore_held_rings = rings;
  }
  MotionReport motion;
  auto restored = move_mesh(*tria, *map, offset, &motion);
  map->follow(*tria, std::move(restored));
  // Carry the accumulated fields (they are on `worn`'s faces when it is the current surface
  // or its moved copy).
  meshes::FaceField<double> removed = removed_, depth = depth_;
  removed.follow(worn);
  depth.follow(worn);
  const meshes::FaceTransfer transfer(worn, map->surface());
  removed_ = transfer.apply(removed);
  depth_ = transfer.apply(depth);
  tria_ = std::move(tria);
  map_ = std::move(map);
  ++n_remeshes_;
  report.volume_restored = mesh_volume(*tria_);
  report.seconds += motion.seconds;
  return report;
}

} // namespace wear::fem

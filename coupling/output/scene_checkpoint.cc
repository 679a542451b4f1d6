// A scene run's part of checkpoint.h5 (scene_checkpoint.h). Layout under /scene:
//   progress            time, stage end, records written, particles removed
//   outlet_mass, outlet_counts, n_inlets, inlet_<k>/{pending, inserted, rng}
//   n_flux_planes, flux_plane_<k>/{ids, last, counts}
//   rank_bounds         the slabs' cuts of a run over ranks (empty from one process)
//   n_parts, part_<k>/{sample/..., face_von_mises, stages/..., labels, removed_per_label,
//                      footprint_labels, footprint_edges (its convex elements' outlines),
//                      open_loads/... with attribute duration, attribute sample_frame for the
//                      tester's sample (kept in its own frame), and with Scene/Evaluation
//                      evaluation/{records/..., samples/..., sums (removed, normal_impulse,
//                      wear_volume as n_faces x 3), scalars (windows, contact total, wall
//                      seconds, particle-steps)}, moved_volume (attribute moved) after reference
//                      stages}
//   n_node_moves (with the root's attribute scene_node_moves), node_moves_<k>/{vertices, sums
//   (swept, applied volume, updates), with a
//                      distortion its attributes kind, face, label, time}
#include "coupling/output/scene_checkpoint.h"

#include <stdexcept>

namespace wear::coupling {

namespace {

std::string part_group(std::size_t k) {
  return "/scene/part_" + std::to_string(k);
}

void write_part(Hdf5File& h5, const std::string& g, const PartCheckpoint& p) {
  write_sample_state(h5, g + "/sample", p.sample);
  write_doubles(h5, g + "/face_von_mises", p.face_von_mises);
  write_stage_records(h5, g + "/stages", p.stages);
  h5.write(g + "/labels", p.labels, {p.labels.size()});
  write_doubles(h5, g + "/removed_per_label", p.removed_per_label);
  write_load_arrays(h5, g + "/open_loads", p.open);
  h5.attribute(g + "/open_loads/impulse", "duration", p.open.duration);
  if (p.sample_frame)
    h5.attribute(g, "sample_frame", 1.0);
  if (!p.moved_volume.empty()) {
    write_doubles(h5, g + "/moved_volume", p.moved_volume);
    h5.attribute(g, "moved", 1.0);
  }
  if (!p.footprints.empty()) { // per outline edge its element's label and {x0, y0, x1, y1}
    std::vector<int> labels;
    std::vector<double> edges;
    for (const auto& [label, outline] : p.footprints)
      for (const auto& e : outline) {
        labels.push_back(label);
        edges.insert(edges.end(), e.begin(), e.end());
      }
    h5.write(g + "/footprint_labels", labels, {labels.size()});
    h5.write(g + "/footprint_edges", edges, {labels.size(), 4});
  }
  if (!p.evaluation)
    return;
  h5.attribute(g, "evaluated", 1.0);
  const auto& e = *p.evaluation;
  write_revolution_records(h5, g + "/evaluation/records", e.history);
  write_revolution_samples(h5, g + "/evaluation/samples", e.samples);
  std::vector<double> sums;
  for (std::size_t f = 0; f < e.removed.size(); ++f)
    sums.insert(sums.end(), {e.removed[f], e.normal_impulse[f], e.wear_volume[f]});
  h5.write(g + "/evaluation/sums", sums, {e.removed.size(), 3});
  write_doubles(h5, g + "/evaluation/scalars",
                {double(e.n_windows), e.contact_total, e.wall_seconds, e.particle_steps});
}

dem::SceneEvaluationState read_evaluation(const Hdf5Reader& h5, const std::string& g) {
  dem::SceneEvaluationState e;
  e.history = read_revolution_records(h5, g + "/records");
  e.samples = read_revolution_samples(h5, g + "/samples");
  const auto dims = h5.dims(g + "/sums");
  const auto sums = h5.doubles(g + "/sums");
  if (dims.size() != 2 || dims[1] != 3 || sums.size() != dims[0] * 3)
    throw std::runtime_error("'" + g + "/sums' is not n_faces x 3");
  for (std::size_t f = 0; f < dims[0]; ++f) {
    e.removed.push_back(sums[3 * f]);
    e.normal_impulse.push_back(sums[3 * f + 1]);
    e.wear_volume.push_back(sums[3 * f + 2]);
  }
  const auto x = h5.doubles(g + "/scalars");
  if (x.size() != 4 || !(x[0] >= 0))
    throw std::runtime_error("'" + g + "/scalars' does not hold the open period's progress");
  e.n_windows = int(x[0]), e.contact_total = x[1], e.wall_seconds = x[2], e.particle_steps = x[3];
  return e;
}

void write_node_moves(Hdf5File& h5, const std::string& g, const dem::ReferenceDeformationState& m) {
  write_vec3(h5, g + "/vertices", m.vertices);
  write_doubles(h5, g + "/sums", {m.swept_volume, m.applied_volume, double(m.n_updates)});
  if (!m.distortion)
    return;
  h5.attribute(g + "/sums", "kind", m.distortion->kind);
  h5.attribute(g + "/sums", "face", double(m.distortion->face));
  h5.attribute(g + "/sums", "label", double(m.distortion->label));
  h5.attribute(g + "/sums", "time", m.distortion->time);
}

dem::ReferenceDeformationState read_node_moves(const Hdf5Reader& h5, const std::string& g) {
  dem::ReferenceDeformationState m;
  m.vertices = vec3s(h5.doubles(g + "/vertices"), g + "/vertices");
  const auto x = h5.doubles(g + "/sums");
  if (x.size() != 3 || !(x[2] >= 0))
    throw std::runtime_error("'" + g + "/sums' does not hold the node moves' sums");
  m.swept_volume = x[0], m.applied_volume = x[1], m.n_updates = std::uint64_t(x[2]);
  if (h5.has_attribute(g + "/sums", "kind"))
    m.distortion = dem::Distortion{
        h5.text_attribute(g + "/sums", "kind"), long(h5.attribute(g + "/sums", "face")),
        int(h5.attribute(g + "/sums", "label")), h5.attribute(g + "/sums", "time")};
  return m;
}

PartCheckpoint read_part(const Hdf5Reader& h5, const std::string& g) {
  PartCheckpoint p;
  p.sample = read_sample_state(h5, g + "/sample");
  p.face_von_mises = h5.doubles(g + "/face_von_mises");
  p.stages = read_stage_records(h5, g + "/stages");
  p.labels = h5.ints(g + "/labels");
  p.removed_per_label = h5.doubles(g + "/removed_per_label");
  read_load_arrays(h5, g + "/open_loads", p.open);
  p.open.duration = h5.attribute(g + "/open_loads/impulse", "duration");
  const std::size_t nf = p.sample.surface.n_faces();
  if (p.face_von_mises.size() != nf || p.open.impulse.size() != nf)
    throw std::runtime_error("the stress or loads of '" + g + "' are not on its surface's faces");
  if (p.labels.size() != p.removed_per_label.size())
    throw std::runtime_error("the per-label volumes of '" + g + "' differ in length");
  p.sample_frame = h5.has_attribute(g, "sample_frame");
  if (h5.has_attribute(g, "moved"))
    p.moved_volume = h5.doubles(g + "/moved_volume");
  if (!p.moved_volume.empty() && p.moved_volume.size() != nf)
    throw std::runtime_error("the moved volume of '" + g + "' is not on its surface's faces");
  if (h5.has_object(g + "/footprint_labels")) {
    const auto labels = h5.ints(g + "/footprint_labels");
    const auto edges = h5.doubles(g + "/footprint_edges");
    if (edges.size() != 4 * labels.size())
      throw std::runtime_error("the element footprints of '" + g + "' hold " +
                               std::to_string(edges.size()) + " coordinates for " +
                               std::to_string(labels.size()) + " edges");
    for (std::size_t k = 0; k < labels.size(); ++k)
      p.footprints[labels[k]].push_back(
          {edges[4 * k], edges[4 * k + 1], edges[4 * k + 2], edges[4 * k + 3]});
  }
  if (h5.has_attribute(g, "evaluated"))
    p.evaluation = read_evaluation(h5, g + "/evaluation");
  return p;
}

} // namespace

SceneCheckpoint scene_checkpoint(const dem::SceneRunState& state, double stage_end, int n_records,
                                 int first_table_record) {
  SceneCheckpoint s;
  s.time = state.time;
  s.stage_end = stage_end;
  s.n_records = n_records;
  s.first_table_record = first_table_record;
  s.rank_bounds = state.rank_bounds;
  s.n_removed = state.n_removed;
  s.inlets = state.inlets;
  s.outlet_mass = state.outlet_mass;
  s.outlet_counts = state.outlet_counts;
  s.flux_planes = state.flux_planes;
  s.node_moves = state.node_moves;
  return s;
}

dem::SceneRunState scene_run_state(const SceneCheckpoint& s, const dem::SystemState& system) {
  return {s.time,          true,          system,        s.n_removed, s.inlets, s.outlet_mass,
          s.outlet_counts, s.flux_planes, s.rank_bounds, s.node_moves};
}

void write_scene(Hdf5File& h5, const SceneCheckpoint& s) {
  write_doubles(h5, "/scene/progress",
                {s.time, s.stage_end, double(s.n_records), double(s.n_removed),
                 double(s.first_table_record)});
  write_doubles(h5, "/scene/outlet_mass", s.outlet_mass);
  h5.write("/scene/outlet_counts", wide(s.outlet_counts), {s.outlet_counts.size()});
  write_doubles(h5, "/scene/rank_bounds", s.rank_bounds);
  h5.write("/scene/n_inlets", std::vector<int>{int(s.inlets.size())}, {1});
  for (std::size_t k = 0; k < s.inlets.size(); ++k) {
    const auto& in = s.inlets[k];
    const std::string g = "/scene/inlet_" + std::to_string(k);
    write_doubles(h5, g + "/pending", in.pending);
    write_doubles(h5, g + "/inserted", {in.inserted_mass, double(in.n_inserted)});
    h5.attribute(g, "rng", in.rng);
  }
  h5.write("/scene/n_flux_planes", std::vector<int>{int(s.flux_planes.size())}, {1});
  for (std::size_t k = 0; k < s.flux_planes.size(); ++k) {
    const auto& f = s.flux_planes[k];
    const std::string g = "/scene/flux_plane_" + std::to_string(k);
    h5.write(g + "/ids", f.ids, {f.ids.size()});
    write_vec3(h5, g + "/last", f.last);
    write_doubles(h5, g + "/counts", {f.net_mass, double(f.n_forward), double(f.n_backward)});
  }
  h5.write("/scene/n_parts", std::vector<int>{int(s.parts.size())}, {1});
  h5.attribute("/", "scene_parts", 1.0);
  for (std::size_t k = 0; k < s.parts.size(); ++k)
    write_part(h5, part_group(k), s.parts[k]);
  if (s.node_moves.empty()) // a checkpoint without them reads as before
    return;
  h5.write("/scene/n_node_moves", std::vector<int>{int(s.node_moves.size())}, {1});
  h5.attribute("/", "scene_node_moves", 1.0);
  for (std::size_t k = 0; k < s.node_moves.size(); ++k)
    write_node_moves(h5, "/scene/node_moves_" + std::to_string(k), s.node_moves[k]);
}

SceneCheckpoint read_scene(const Hdf5Reader& h5) {
  SceneCheckpoint s;
  const auto x = h5.doubles("/scene/progress");
  // An older checkpoint holds no first table record: its tables start at record 1.
  if (x.size() != 4 && x.size() != 5)
    throw std::runtime_error("'/scene/progress' does not hold the scene's progress");
  s.time = x[0], s.stage_end = x[1], s.n_records = int(x[2]), s.n_removed = std::uint64_t(x[3]);
  s.first_table_record = x.size() == 5 ? int(x[4]) : 1;
  if (s.first_table_record < 1 || s.first_table_record > s.n_records + 1)
    throw std::runtime_error("'/scene/progress': the tables' first record " +
                             std::to_string(s.first_table_record) + " lies outside records 1 to " +
                             std::to_string(s.n_records + 1));
  s.outlet_mass = h5.doubles("/scene/outlet_mass");
  s.outlet_counts = narrow<std::uint64_t>(h5.int64s("/scene/outlet_counts"));
  if (s.outlet_mass.size() != s.outlet_counts.size())
    throw std::runtime_error("the scene's per-outlet records differ in length");
  const auto n_inlets = h5.ints("/scene/n_inlets");
  for (int k = 0; k < n_inlets.at(0); ++k) {
    const std::string g = "/scene/inlet_" + std::to_string(k);
    dem::InletState in;
    in.pending = h5.doubles(g + "/pending");
    const auto inserted = h5.doubles(g + "/inserted");
    if (inserted.size() != 2)
      throw std::runtime_error("'" + g + "/inserted' does not hold the inserted mass and count");
    in.inserted_mass = inserted[0], in.n_inserted = std::uint64_t(inserted[1]);
    in.rng = h5.text_attribute(g, "rng");
    s.inlets.push_back(in);
  }
  s.rank_bounds = h5.doubles("/scene/rank_bounds");
  const auto n_planes = h5.ints("/scene/n_flux_planes");
  for (int k = 0; k < n_planes.at(0); ++k) {
    const std::string g = "/scene/flux_plane_" + std::to_string(k);
    dem::FluxPlaneState f;
    f.ids = h5.int64s(g + "/ids");
    f.last = vec3s(h5.doubles(g + "/last"), g + "/last");
    const auto c = h5.doubles(g + "/counts");
    if (c.size() != 3 || f.ids.size() != f.last.size())
      throw std::runtime_error("'" + g + "' does not hold a flux plane's state");
    f.net_mass = c[0], f.n_forward = std::uint64_t(c[1]), f.n_backward = std::uint64_t(c[2]);
    s.flux_planes.push_back(f);
  }
  if (!h5.has_attribute("/", "scene_parts"))
    throw std::runtime_error("a scene checkpoint written before scenes had several wearing "
                             "parts; run the case again with --overwrite");
  const auto n_parts = h5.ints("/scene/n_parts");
  for (int k = 0; k < n_parts.at(0); ++k)
    s.parts.push_back(read_part(h5, part_group(std::size_t(k))));
  if (!h5.has_attribute("/", "scene_node_moves"))
    return s;
  const auto n_moves = h5.ints("/scene/n_node_moves");
  for (int k = 0; k < n_moves.at(0); ++k)
    s.node_moves.push_back(read_node_moves(h5, "/scene/node_moves_" + std::to_string(k)));
  return s;
}

} // namespace wear::coupling

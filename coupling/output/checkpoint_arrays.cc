// The arrays of a checkpoint (checkpoint_arrays.h): each value in its binary form, so a read
// gives back the same bits; every read checks the lengths that must agree and throws naming
// the dataset.
#include "coupling/output/checkpoint_arrays.h"

#include <stdexcept>

namespace wear::coupling {

OpenStage open_stage(const dem::WallLoads& loads) {
  OpenStage o;
  o.impulse = loads.impulse.values();
  o.traction_impulse = loads.traction_impulse.values();
  o.normal_impulse = loads.normal_impulse.values();
  o.archard = loads.archard.values();
  o.sliding_work = loads.sliding_work.values();
  o.contact_steps = loads.contact_steps.values();
  o.wear_volume = loads.wear_volume.values();
  o.impact_volume = loads.impact_volume.values();
  o.duration = loads.duration;
  return o;
}

dem::WallLoads loads_of(const OpenStage& o, const meshes::SurfaceMesh& surface) {
  if (o.impulse.size() != surface.n_faces())
    throw std::runtime_error("checkpoint: the open stage's loads are on " +
                             std::to_string(o.impulse.size()) + " faces, the part's surface has " +
                             std::to_string(surface.n_faces()));
  dem::WallLoads l = dem::WallLoads::zero(surface);
  l.impulse.values() = o.impulse;
  l.traction_impulse.values() = o.traction_impulse;
  l.normal_impulse.values() = o.normal_impulse;
  l.archard.values() = o.archard;
  l.sliding_work.values() = o.sliding_work;
  l.contact_steps.values() = o.contact_steps;
  l.wear_volume.values() = o.wear_volume;
  if (!o.impact_volume.empty())
    l.impact_volume.values() = o.impact_volume;
  l.duration = o.duration;
  return l;
}

std::vector<double> flat(const std::vector<meshes::Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const auto& x : v)
    out.push_back(x.x), out.push_back(x.y), out.push_back(x.z);
  return out;
}

std::vector<meshes::Vec3> vec3s(const std::vector<double>& v, const std::string& name) {
  if (v.size() % 3 != 0)
    throw std::runtime_error("'" + name + "' is not n x 3");
  std::vector<meshes::Vec3> out(v.size() / 3);
  for (std::size_t k = 0; k < out.size(); ++k)
    out[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
  return out;
}

void write_vec3(Hdf5File& h5, const std::string& name, const std::vector<meshes::Vec3>& v) {
  h5.write(name, flat(v), {v.size(), 3});
}

void write_doubles(Hdf5File& h5, const std::string& name, const std::vector<double>& v) {
  h5.write(name, v, {v.size()});
}

void write_sample_state(Hdf5File& h5, const std::string& g, const fem::WornSampleState& s) {
  if (!s.tetrahedra.empty()) {
    h5.write(g + "/vertices", s.vertices, {s.vertices.size() / 3, 3});
    h5.write(g + "/tetrahedra", s.tetrahedra, {s.tetrahedra.size() / 4, 4});
    h5.write(g + "/boundary_faces", s.boundary_faces, {s.boundary_faces.size() / 3, 3});
    h5.write(g + "/boundary_ids", s.boundary_ids, {s.boundary_ids.size()});
  }
  const auto& m = s.surface;
  write_vec3(h5, g + "/surface/vertices", m.vertices);
  std::vector<std::int64_t> tri;
  for (const auto& t : m.triangles)
    tri.insert(tri.end(), t.begin(), t.end());
  h5.write(g + "/surface/triangles", tri, {m.n_faces(), 3});
  h5.write(g + "/surface/labels", m.face_labels, {m.n_faces()});
  h5.attribute(g + "/surface", "revision", double(m.revision()));
  std::vector<int> role_labels, roles;
  for (const auto& [label, role] : m.roles.entries()) {
    role_labels.push_back(label);
    roles.push_back(int(role));
  }
  h5.write(g + "/surface/role_labels", role_labels, {role_labels.size()});
  h5.write(g + "/surface/roles", roles, {roles.size()});
  h5.attribute(g + "/surface", "n_roles", double(roles.size()));
  h5.write(g + "/removed_volume", s.removed_volume, {s.removed_volume.size()});
  h5.write(g + "/wear_depth", s.wear_depth, {s.wear_depth.size()});
  h5.attribute(g, "n_remeshes", double(s.n_remeshes));
}

fem::WornSampleState read_sample_state(const Hdf5Reader& h5, const std::string& g) {
  fem::WornSampleState s;
  if (h5.has_object(g + "/tetrahedra")) { // else kept without its volume mesh (WornSampleState)
    s.vertices = h5.doubles(g + "/vertices");
    s.tetrahedra = h5.int64s(g + "/tetrahedra");
    s.boundary_faces = h5.int64s(g + "/boundary_faces");
    s.boundary_ids = h5.ints(g + "/boundary_ids");
  }
  auto& m = s.surface;
  m.vertices = vec3s(h5.doubles(g + "/surface/vertices"), g + "/surface/vertices");
  const auto tri = h5.int64s(g + "/surface/triangles");
  m.triangles.resize(tri.size() / 3);
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      m.triangles[f][k] = std::uint32_t(tri[3 * f + k]);
  m.face_labels = h5.ints(g + "/surface/labels");
  m.set_revision(std::uint64_t(h5.attribute(g + "/surface", "revision")));
  if (!h5.has_attribute(g + "/surface", "n_roles"))
    throw std::runtime_error("checkpoint '" + h5.path() + "': the surface of '" + g +
                             "' carries no face roles (an older engine's checkpoint); run the "
                             "case again with --overwrite");
  const auto role_labels = h5.ints(g + "/surface/role_labels");
  const auto roles = h5.ints(g + "/surface/roles");
  if (role_labels.size() != roles.size())
    throw std::runtime_error("checkpoint '" + h5.path() + "': the face roles of '" + g +
                             "' do not match their labels");
  for (std::size_t k = 0; k < roles.size(); ++k) {
    if (roles[k] < 0 || roles[k] > int(meshes::FaceRole::held))
      throw std::runtime_error("checkpoint '" + h5.path() + "': an unknown face role " +
                               std::to_string(roles[k]) + " in '" + g + "'");
    m.roles.set(role_labels[k], meshes::FaceRole(roles[k]));
  }
  m.validate("checkpoint surface " + g);
  s.removed_volume = h5.doubles(g + "/removed_volume");
  s.wear_depth = h5.doubles(g + "/wear_depth");
  s.n_remeshes = int(h5.attribute(g, "n_remeshes"));
  if (s.removed_volume.size() != m.n_faces() || s.wear_depth.size() != m.n_faces())
    throw std::runtime_error("the fields of '" + g + "' do not match its surface");
  return s;
}

void write_load_arrays(Hdf5File& h5, const std::string& g, const OpenStage& o) {
  write_vec3(h5, g + "/impulse", o.impulse);
  write_vec3(h5, g + "/traction_impulse", o.traction_impulse);
  write_doubles(h5, g + "/normal_impulse", o.normal_impulse);
  write_doubles(h5, g + "/archard", o.archard);
  write_doubles(h5, g + "/sliding_work", o.sliding_work);
  write_doubles(h5, g + "/contact_steps", o.contact_steps);
  write_doubles(h5, g + "/wear_volume", o.wear_volume);
  write_doubles(h5, g + "/impact_volume", o.impact_volume);
}

void read_load_arrays(const Hdf5Reader& h5, const std::string& g, OpenStage& o) {
  o.impulse = vec3s(h5.doubles(g + "/impulse"), g + "/impulse");
  o.traction_impulse = vec3s(h5.doubles(g + "/traction_impulse"), g + "/traction_impulse");
  o.normal_impulse = h5.doubles(g + "/normal_impulse");
  o.archard = h5.doubles(g + "/archard");
  o.sliding_work = h5.doubles(g + "/sliding_work");
  o.contact_steps = h5.doubles(g + "/contact_steps");
  o.wear_volume = h5.doubles(g + "/wear_volume");
  o.impact_volume = h5.has_object(g + "/impact_volume")
                        ? h5.doubles(g + "/impact_volume")
                        : std::vector<double>(o.wear_volume.size(), 0.0);
  const std::size_t nf = o.impulse.size();
  bool same = o.traction_impulse.size() == nf;
  for (const auto* v : {&o.normal_impulse, &o.archard, &o.sliding_work, &o.contact_steps,
                        &o.wear_volume, &o.impact_volume})
    same = same && v->size() == nf;
  if (!same)
    throw std::runtime_error("the loads of '" + g + "' are of different lengths");
}

} // namespace wear::coupling

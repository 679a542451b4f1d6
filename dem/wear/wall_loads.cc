// Per-face window loads of a wearing wall as revision-checked FaceFields (wall_loads.h).
// Every field is extensive: sums over windows and over faces are physical totals, and they
// transfer conservatively between triangulations (meshes::FaceTransfer).
//
// The coarse-grained fields spread each face's window load from its normal-load centroid
// p_f = (integral of x_c F_n dt) / (integral of F_n dt), the point where its contacts
// pressed, with the moment of its contacts (integral of x_c x F dt) about the wall's origin
// (meshes/coarse_graining.cc). p_f and the moment come from the engine's per-contact sums,
// so the coarse-grained traction has the window's force and moment, not those of loads
// moved to face centroids. A face loaded only tangentially (no normal impulse, which a
// contact never gives) would spread from its centroid.
#include "dem/wear/wall_loads.h"

#include "meshes/coarse_graining.h"

#include <stdexcept>

namespace wear::dem {

namespace {
using meshes::Extensivity;
using meshes::FaceField;

// The values of one field of a window, checked against the face count.
template <typename T>
void fill(FaceField<T>& to, const std::vector<T>& values) {
  if (values.size() != to.size())
    throw std::logic_error("wall loads: '" + to.name() + "' has " + std::to_string(values.size()) +
                           " values for " + std::to_string(to.size()) + " faces");
  to.values() = values;
}

template <typename T>
void add(FaceField<T>& to, const FaceField<T>& from) {
  if (to.revision() != from.revision() || to.size() != from.size())
    throw std::logic_error("wall loads: cannot add '" + from.name() + "' of mesh revision " +
                           std::to_string(from.revision()) + " to one of revision " +
                           std::to_string(to.revision()));
  for (std::size_t f = 0; f < to.size(); ++f)
    to[f] += from[f];
}

template <typename T>
FaceField<T> followed(FaceField<T> f, const meshes::SurfaceMesh& mesh) {
  f.follow(mesh);
  return f;
}
} // namespace

WallLoads WallLoads::zero(const meshes::SurfaceMesh& mesh) {
  WallLoads w;
  w.impulse = FaceField<meshes::Vec3>("impulse", "N s", Extensivity::extensive, mesh);
  w.traction_impulse =
      FaceField<meshes::Vec3>("traction impulse", "N s", Extensivity::extensive, mesh);
  w.normal_impulse = FaceField<double>("normal impulse", "N s", Extensivity::extensive, mesh);
  w.archard = FaceField<double>("Archard load-distance", "N m", Extensivity::extensive, mesh);
  w.sliding_work = FaceField<double>("sliding work", "J", Extensivity::extensive, mesh);
  w.contact_steps = FaceField<double>("contact-steps", "1", Extensivity::extensive, mesh);
  w.wear_volume = FaceField<double>("wear-law volume", "m^3", Extensivity::extensive, mesh);
  w.impact_volume =
      FaceField<double>("impact wear-law volume", "m^3", Extensivity::extensive, mesh);
  return w;
}

WallLoads& WallLoads::operator+=(const WallLoads& o) {
  add(impulse, o.impulse);
  add(traction_impulse, o.traction_impulse);
  add(normal_impulse, o.normal_impulse);
  add(archard, o.archard);
  add(sliding_work, o.sliding_work);
  add(contact_steps, o.contact_steps);
  add(wear_volume, o.wear_volume);
  add(impact_volume, o.impact_volume);
  duration += o.duration;
  return *this;
}

WallLoads WallLoads::follow(const meshes::SurfaceMesh& mesh,
                            const std::function<meshes::Vec3(const meshes::Vec3&)>& rotate) const {
  WallLoads w;
  w.impulse = followed(impulse, mesh);
  for (auto& v : w.impulse.values())
    v = rotate(v);
  w.traction_impulse = followed(traction_impulse, mesh);
  for (auto& v : w.traction_impulse.values())
    v = rotate(v);
  w.normal_impulse = followed(normal_impulse, mesh);
  w.archard = followed(archard, mesh);
  w.sliding_work = followed(sliding_work, mesh);
  w.contact_steps = followed(contact_steps, mesh);
  w.wear_volume = followed(wear_volume, mesh);
  w.impact_volume = followed(impact_volume, mesh);
  w.duration = duration;
  return w;
}

LoadSpreading load_spreading(const WallLoadParameters& p, const SizeDistribution& psd) {
  return {p.coarse_graining_width > 0 ? p.coarse_graining_width : psd.mean_diameter() / 2,
          p.coarse_grained_traction, p.coarse_grained_wear};
}

std::vector<double> impact_part(const WearLaw& law, const WearIntegrals& integrals) {
  for (auto& [mechanism, volume] : law.removed_by_mechanism(integrals))
    if (mechanism == "impact")
      return volume;
  return std::vector<double>(integrals.archard.size(), 0.0);
}

WallLoads wall_loads(const WearIntegrals& integrals, const std::vector<double>& wear_volume,
                     const meshes::SurfaceMesh& mesh, double duration,
                     const LoadSpreading& spreading, const std::vector<double>& impact_volume) {
  WallLoads w = WallLoads::zero(mesh);
  fill(w.impulse, integrals.impulse);
  fill(w.normal_impulse, integrals.normal_impulse);
  fill(w.archard, integrals.archard);
  fill(w.sliding_work, integrals.sliding_work);
  fill(w.contact_steps, integrals.contact_steps);
  fill(w.wear_volume, wear_volume);
  if (!impact_volume.empty())
    fill(w.impact_volume, impact_volume);
  w.duration = duration;
  if (!spreading.traction && !spreading.wear) {
    w.traction_impulse.values() = w.impulse.values();
    return w;
  }
  const meshes::CoarseGraining kernel(mesh, spreading.width, "DEM/Coarse-graining width");
  meshes::FaceSources sources{integrals.impulse, meshes::face_centroids(mesh),
                              integrals.impulse_moment};
  for (std::size_t f = 0; f < mesh.n_faces(); ++f)
    if (integrals.normal_impulse[f] > 0)
      sources.point[f] = integrals.normal_moment[f] / integrals.normal_impulse[f];
  if (spreading.traction)
    w.traction_impulse =
        kernel.spread_force(sources, w.traction_impulse.name(), w.traction_impulse.unit());
  else
    w.traction_impulse.values() = w.impulse.values();
  if (spreading.wear) {
    w.wear_volume = kernel.spread_scalar(w.wear_volume, sources.point);
    w.impact_volume = kernel.spread_scalar(w.impact_volume, sources.point);
  }
  return w;
}

} // namespace wear::dem

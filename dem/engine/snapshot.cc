// Particle snapshot: VTK vertex cells, one per particle, with point data; ParaView's
// "Point Gaussian" representation (or Glyph by radius) shows them as spheres.
#include "dem/engine/snapshot.h"

#include "meshes/vtu_writer.h"

namespace wear::dem {

void write_particles_vtu(const Particles& p, const std::string& path) {
  meshes::VtuGrid g;
  const std::size_t n = p.n_real;
  g.points.assign(p.position.begin(), p.position.begin() + n);
  g.cell_type = meshes::VtkCell::vertex;
  g.connectivity.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    g.connectivity[i] = std::uint32_t(i);
  meshes::VtuArray radius{"radius [m]", 1, {p.radius.begin(), p.radius.begin() + n}};
  meshes::VtuArray id{"id", 1, {}}, v{"velocity [m/s]", 3, {}},
      w{"angular velocity [rad/s]", 3, {}};
  id.values.reserve(n);
  v.values.reserve(3 * n);
  w.values.reserve(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    id.values.push_back(double(p.id[i]));
    v.values.insert(v.values.end(), {p.velocity[i].x, p.velocity[i].y, p.velocity[i].z});
    w.values.insert(w.values.end(),
                    {p.angular_velocity[i].x, p.angular_velocity[i].y, p.angular_velocity[i].z});
  }
  g.point_data = {radius, v, w, id};
  write_vtu(g, path);
}

} // namespace wear::dem

// Particle snapshot: VTK vertex cells, one per particle, with point data; ParaView's
// "Point Gaussian" representation (or Glyph by radius) shows them as spheres.
#include "dem/engine/snapshot.h"

#include "meshes/vtu_writer.h"

namespace wear::dem {

void write_particles_vtu(const Particles& p, const std::string& path, const Clumps* clumps) {
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
  if (clumps && !clumps->empty()) {
    meshes::VtuArray body{"body", 1, std::vector<double>(n, -1.0)},
        orientation{"body orientation (w, x, y, z)", 4, std::vector<double>(4 * n, 0.0)},
        centre{"body centre [m]", 3, {}};
    for (std::size_t i = 0; i < n; ++i)
      centre.values.insert(centre.values.end(),
                           {p.position[i].x, p.position[i].y, p.position[i].z});
    for (std::size_t b = 0; b < clumps->size(); ++b)
      for (std::uint32_t k = clumps->member_begin[b]; k < clumps->member_begin[b + 1]; ++k) {
        const std::size_t i = clumps->member_slot[k];
        const Quaternion& q = clumps->orientation[b];
        const Vec3& x = clumps->position[b];
        body.values[i] = double(b);
        double* o = &orientation.values[4 * i];
        o[0] = q.w;
        o[1] = q.x;
        o[2] = q.y;
        o[3] = q.z;
        for (int d = 0; d < 3; ++d)
          centre.values[3 * i + std::size_t(d)] = x[d];
      }
    g.point_data.insert(g.point_data.end(), {body, orientation, centre});
  }
  write_vtu(g, path);
}

} // namespace wear::dem

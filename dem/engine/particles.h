#pragma once
// Particle storage as structure of arrays: one contiguous array per quantity, indexed by
// particle. Slots [n_real, n_real + n_ghost) hold periodic images (ghosts) that mirror
// an owner particle; the step loop never resizes these arrays.
#include "meshes/constants.h"
#include "meshes/vec3.h"

#include <cstdint>
#include <vector>

namespace wear::dem {

using meshes::Vec3;

struct Particles {
  std::vector<Vec3> position;         ///< [m]
  std::vector<Vec3> velocity;         ///< [m/s]
  std::vector<Vec3> angular_velocity; ///< [rad/s]
  std::vector<Vec3> force;            ///< [N]
  std::vector<Vec3> torque;           ///< [N m]
  std::vector<double> radius;         ///< [m]
  std::vector<double> mass;           ///< [kg]
  std::vector<double> inertia;        ///< [kg m^2] solid sphere 2/5 m r^2
  std::vector<int> material;          ///< material id
  std::vector<std::int64_t> id;       ///< stable id, survives reordering
  std::size_t n_real = 0;             ///< owned particles; ghosts follow

  std::size_t size() const { return n_real; }

  /// Appends one particle (before ghosts exist). Density from the material table.
  void add(const Vec3& x, const Vec3& v, double r, double density, int material_id) {
    position.push_back(x);
    velocity.push_back(v);
    angular_velocity.push_back({});
    force.push_back({});
    torque.push_back({});
    radius.push_back(r);
    const double m = density * 4.0 / 3.0 * pi * r * r * r;
    mass.push_back(m);
    inertia.push_back(0.4 * m * r * r);
    material.push_back(material_id);
    id.push_back(static_cast<std::int64_t>(n_real));
    ++n_real;
  }

  /// Resizes the ghost region to n_ghost slots (only at neighbour-list rebuilds).
  void resize_ghosts(std::size_t n_ghost) {
    const std::size_t n = n_real + n_ghost;
    position.resize(n);
    velocity.resize(n);
    angular_velocity.resize(n);
    force.resize(n);
    torque.resize(n);
    radius.resize(n);
    mass.resize(n);
    inertia.resize(n);
    material.resize(n);
    id.resize(n);
  }
};

} // namespace wear::dem

// Checks of the DEM parameters every scene uses (dem_parameters.h), and the engine's material
// from a case file's: E = 2 G (1 + nu).
#include "dem/scene/dem_parameters.h"

#include "dem/scene/particle_shapes.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

namespace {
std::string text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}
} // namespace

void require_dem(bool ok, const std::string& parameter, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("DEM/" + parameter + ": " + what);
}

Material engine_material(const std::string& name, const DemMaterial& m) {
  return {name, 2 * m.shear_modulus * (1 + m.poisson_ratio), m.poisson_ratio, m.density};
}

std::string particle_shape_documentation() {
  std::string doc =
      "Shape of the particles: 'sphere', a shape of the library, or a template file (a path "
      "ending in .txt, one member sphere per line, 'x y z r' in any length unit). Any other "
      "shape is a rigid clump of overlapping spheres whose size the PSD sets by its "
      "equivalent-volume diameter, inserted with a random orientation. The library:";
  for (const auto& e : particle_shapes())
    if (e.name != "sphere")
      doc += " '" + e.name + "': " + e.description + ";";
  doc.back() = '.';
  return doc + " Clumps run in one process and are not inserted by inlets.";
}

void validate(const DemParameters& p) {
  const auto check_material = [](const DemMaterial& m, const std::string& which) {
    require_dem(m.shear_modulus > 0 && std::isfinite(m.shear_modulus), which + " shear modulus",
                "must be positive [Pa]");
    require_dem(m.poisson_ratio > -1 && m.poisson_ratio < 0.5, which + " Poisson ratio",
                "must lie in (-1, 0.5)");
    require_dem(m.density > 0 && std::isfinite(m.density), which + " density",
                "must be positive [kg/m^3]");
  };
  check_material(p.particle, "Particle");
  check_material(p.sample, "Sample");
  check_material(p.walls, "Wall");
  check_material(p.holder, "Holder");
  for (const auto& [pair, which] :
       {std::pair{&p.particle_particle, "particle-particle"}, {&p.particle_wall, "particle-wall"}})
    require_dem(pair->rolling_friction >= 0 && pair->rolling_friction <= max_rolling_friction,
                std::string("Rolling friction ") + which,
                "must lie in [0, " + text(max_rolling_friction) + "], got " +
                    text(pair->rolling_friction) +
                    ": the rolling resistance torque mu_r F_n a is the normal force shifted mu_r "
                    "a off the line of centres (a the centre-to-contact distance), which above 1 "
                    "would lie outside the particle (DEM of granular materials: mostly 0.01 to "
                    "0.5)");
  p.psd.validate();
  require_dem(p.loose_factor >= 1.2, "Loose factor", "must be at least 1.2");
  require_dem(p.assumed_packing > 0.2 && p.assumed_packing < 0.74, "Assumed packing",
              "must lie in (0.2, 0.74)");
  require_dem(p.settle_time > 0, "Settle time", "must be positive [s]");
  require_dem(p.time_step_fraction > 0 && p.time_step_fraction <= 0.4, "Time step fraction",
              "must lie in (0, 0.4] of the Rayleigh time");
  require_dem(p.max_speed > 0, "Maximum speed", "must be positive [m/s]");
  require_dem(p.n_threads >= 0, "Threads", "must be 0 (all cores) or positive");
  particle_shape(p.particle_shape, "DEM/Particle shape"); // throws naming it
  require_dem(p.wall_loads.coarse_graining_width >= 0 &&
                  std::isfinite(p.wall_loads.coarse_graining_width),
              "Coarse-graining width", "must be 0 (the mean particle radius) or positive [m]");
}

} // namespace wear::dem

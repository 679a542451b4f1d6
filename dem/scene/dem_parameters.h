#pragma once
// The DEM parameters every scene uses, the wear tester among them: materials, contact pairs,
// particle size distribution, filling and settling, time step, seed, threads and how a
// window's wall loads are laid on the faces; and the part of the DEM subsection of a case
// file that fills them (visit_parameters, meshes/parameter_visitor.h). What only the wear
// tester uses (its fill height, rotation, revolutions, steady state) is in
// dem/tester/tester_parameters.h.
#include "dem/engine/filling.h"
#include "dem/engine/material.h"
#include "dem/wear/wall_loads.h"
#include "meshes/parameter_visitor.h"

#include <cstdint>
#include <string>

namespace wear::dem {

/// Elastic properties of one body in the DEM (contact stiffness, not the FEM material).
struct DemMaterial {
  double shear_modulus = 1e8; ///< [Pa]
  double poisson_ratio = 0.25;
  double density = 2650; ///< [kg/m^3]
};

/// The engine's material of `m` (Young's modulus from G and nu).
Material engine_material(const std::string& name, const DemMaterial& m);

/// [-] Mean particle speed over which a bed counts as settled (fill_to_height's tolerance;
/// no particle faster than ten times it).
constexpr double settled_mean_speed = 0.01; ///< [m/s]

/// The DEM part of a case that every scene uses (case file subsection "DEM"); defaults are
/// those of docs/wear-tester.md where it gives them.
struct DemParameters {
  DemMaterial particle{1e8, 0.25, 2650};
  DemMaterial sample{2.5e8, 0.40, 930};
  DemMaterial walls{7.9e10, 0.30, 7850};  ///< floor, cylinders, consolidator (assumed steel)
  DemMaterial holder{7.9e10, 0.30, 7850}; ///< the sample holder (steel, as the walls)
  PairProperties particle_particle{0.5, 0.55, 0.20};
  PairProperties particle_wall{0.5, 0.30, 0.10}; ///< also particle-sample and particle-holder
  SizeDistribution psd{{2.0e-3, 2.65e-3, 3.35e-3}, {0.25, 0.5, 0.25}, 4};
  /// "sphere", a shape of the library (dem/scene/particle_shapes.h) or a template file (.txt)
  std::string particle_shape = "sphere";
  double loose_factor = 2.5;       ///< [-] insertion region height / settled bed height
  double assumed_packing = 0.49;   ///< [-] settled solid fraction that sets the count
  double settle_time = 0.5;        ///< [s] at most, walls at rest
  double time_step_fraction = 0.2; ///< [-] of the Rayleigh time
  double max_speed = 20;           ///< [m/s] a faster particle stops the run
  std::uint64_t seed = 20111;      ///< insertion
  int n_threads = 0;               ///< 0: all cores
  WallLoadParameters wall_loads;   ///< how a window's loads are laid on a wall's faces
};

/// The description of DEM/Particle shape: the values it takes, the library's shapes with
/// what each stands for.
std::string particle_shape_documentation();

/// "Particle shear modulus", "Particle Poisson ratio", "Particle density" for which =
/// "Particle" (likewise "Sample", "Wall", "Holder").
template <typename Visitor>
void visit_parameters(const std::string& which, DemMaterial& m, Visitor& v) {
  v.real(which + " shear modulus", m.shear_modulus,
         "[Pa] Shear modulus of the " + which + " in the contact law (DEM stiffness).");
  v.real(which + " Poisson ratio", m.poisson_ratio, "[-] Poisson ratio of the " + which + ".");
  v.real(which + " density", m.density, "[kg/m^3] Solid density of the " + which + ".");
}

/// "Restitution particle-wall", "Friction particle-wall", ... for which = "particle-wall".
template <typename Visitor>
void visit_parameters(const std::string& which, PairProperties& p, Visitor& v) {
  v.real("Restitution " + which, p.restitution,
         "[-] Normal coefficient of restitution, " + which + ".");
  v.real("Friction " + which, p.friction, "[-] Static friction coefficient, " + which + ".");
  v.real("Rolling friction " + which, p.rolling_friction,
         "[-] Rolling friction coefficient mu_r, " + which +
             ": a constant directional torque mu_r F_n a against the relative spin, a the "
             "centre-to-contact distance. At most 1 (refused above): the torque is the normal "
             "force shifted mu_r a off the line of centres, which for mu_r above 1 would lie "
             "outside the particle; rolling friction coefficients in DEM of granular materials "
             "lie below about 1, mostly between 0.01 and 0.5.");
}

/// The DEM subsection's entries that every scene uses (inside the subsection: the caller
/// enters "DEM").
template <typename Visitor>
void visit_common_parameters(DemParameters& d, Visitor& v) {
  visit_parameters("Particle", d.particle, v);
  visit_parameters("Sample", d.sample, v);
  visit_parameters("Wall", d.walls, v);
  visit_parameters("Holder", d.holder, v);
  visit_parameters("particle-particle", d.particle_particle, v);
  visit_parameters("particle-wall", d.particle_wall, v);
  v.real_list("PSD diameters", d.psd.diameters,
              "[m] Diameter bins of the particle size distribution at scaling factor 1.");
  v.real_list("PSD mass fractions", d.psd.mass_fractions, "[-] Mass fraction of each bin.");
  v.real("Scaling factor", d.psd.scaling_factor,
         "[-] Particle scaling factor s: multiplies every diameter (1 to 4).");
  v.text("Particle shape", d.particle_shape, particle_shape_documentation());
  v.real("Loose factor", d.loose_factor,
         "[-] Height of the insertion region over the settled bed height (random loose "
         "insertion of a fill to a bed height: the tester's Fill height, a scene's Fill/Bed "
         "height).");
  v.real("Assumed packing", d.assumed_packing,
         "[-] Settled solid fraction used to count the particles for a bed height.");
  v.real("Settle time", d.settle_time,
         "[s] Longest settling of a fill to a bed height, with the walls at rest (it ends "
         "earlier once the mean particle speed is below 0.01 m/s and none moves faster than "
         "0.1 m/s).");
  v.real("Time step fraction", d.time_step_fraction,
         "[-] Time step as a fraction of the Rayleigh time of the smallest particle (<= 0.4).");
  v.real("Maximum speed", d.max_speed, "[m/s] A faster particle stops the run with a report.");
  v.count("Seed", d.seed, "Random seed of the insertion.");
  v.integer("Threads", d.n_threads, 0, 1024, "OpenMP threads; 0 uses all cores.");
  visit_parameters(d.wall_loads, v);
}

/// The DEM subsection of a scene.
template <typename Visitor>
void visit_parameters(DemParameters& d, Visitor& v) {
  v.enter("DEM");
  visit_common_parameters(d, v);
  v.leave();
}

/// Throws std::invalid_argument naming "DEM/<parameter>" for a non-physical value.
void validate(const DemParameters& p);

/// Throws std::invalid_argument naming "DEM/<parameter>" with `what` unless `ok`.
void require_dem(bool ok, const std::string& parameter, const std::string& what);

} // namespace wear::dem

#pragma once
// The DEM part of a wear-tester case: materials, contact pairs, particle size distribution,
// bed, rotation, time step and run length; and the DEM subsection of a case file that fills
// it (visit_parameters, meshes/parameter_visitor.h). validate() is in wear_tester.h.
#include "dem/engine/filling.h"
#include "dem/engine/material.h"
#include "meshes/parameter_visitor.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wear::dem {

/// Elastic properties of one body in the DEM (contact stiffness, not the FEM material).
struct DemMaterial {
  double shear_modulus = 1e8; ///< [Pa]
  double poisson_ratio = 0.25;
  double density = 2650; ///< [kg/m^3]
};

/// The DEM part of a wear-tester case (case file subsection "DEM"); defaults are those of
/// docs/wear-tester.md where it gives them.
struct TesterDemParameters {
  DemMaterial particle{1e8, 0.25, 2650};
  DemMaterial sample{2.5e8, 0.40, 930};
  DemMaterial walls{7.9e10, 0.30, 7850};  ///< floor, cylinders, consolidator (assumed steel)
  DemMaterial holder{7.9e10, 0.30, 7850}; ///< the sample holder (steel, as the walls)
  PairProperties particle_particle{0.5, 0.55, 0.20};
  PairProperties particle_wall{0.5, 0.30, 0.10}; ///< also particle-sample and particle-holder
  SizeDistribution psd{{2.0e-3, 2.65e-3, 3.35e-3}, {0.25, 0.5, 0.25}, 4};
  double fill_height = 0.130;      ///< [m] settled bed height above the floor
  double loose_factor = 2.5;       ///< [-] insertion region height / fill height
  double assumed_packing = 0.49;   ///< [-] settled solid fraction that sets the count
  double settle_time = 0.5;        ///< [s] at most, walls at rest
  double rotation_rate_deg = 90;   ///< [deg/s] of floor and cylinders
  double time_step_fraction = 0.2; ///< [-] of the Rayleigh time
  double max_speed = 20;           ///< [m/s] a faster particle stops the run
  std::uint64_t seed = 20111;      ///< insertion
  int n_threads = 0;               ///< 0: all cores
  int revolutions = 9;             ///< one revolution = one pass through the sector
  /// `wearsim dem` stops this many revolutions after the steady revolution (0: runs all
  /// `revolutions`, which stay the maximum).
  int revolutions_after_steady = 0;
  int samples_per_revolution = 10;          ///< evaluation samples (force, speeds, heights)
  double steady_threshold = 0.1;            ///< [-] coefficient of variation for steady state
  int steady_revolutions = 2;               ///< consecutive revolutions below the threshold
  std::vector<int> snapshot_revolutions{1}; ///< particle snapshots after these (plus the last)
  /// [m] width w of the kernel that coarse-grains the wall loads; 0: the number-mean particle
  /// radius at the scaling factor
  double coarse_graining_width = 0;
  bool coarse_grained_traction = true; ///< the FEM receives the coarse-grained traction
  bool coarse_grained_wear = false;    ///< the wear-law volume is coarse-grained too
};

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

/// The bed: size distribution, filling and settling.
template <typename Visitor>
void visit_bed_parameters(TesterDemParameters& d, Visitor& v) {
  v.real_list("PSD diameters", d.psd.diameters,
              "[m] Diameter bins of the particle size distribution at scaling factor 1.");
  v.real_list("PSD mass fractions", d.psd.mass_fractions, "[-] Mass fraction of each bin.");
  v.real("Scaling factor", d.psd.scaling_factor,
         "[-] Particle scaling factor s: multiplies every diameter (1 to 4).");
  v.real("Fill height", d.fill_height, "[m] Settled bed height above the floor.");
  v.real("Loose factor", d.loose_factor,
         "[-] Height of the insertion region over the fill height (random loose insertion).");
  v.real("Assumed packing", d.assumed_packing,
         "[-] Settled solid fraction used to count the particles for the fill height.");
  v.real("Settle time", d.settle_time, "[s] Longest settling with the walls at rest.");
}

/// The run: rotation, time step, threads, revolutions, evaluation and steady state.
template <typename Visitor>
void visit_run_parameters(TesterDemParameters& d, Visitor& v) {
  v.real("Rotation rate", d.rotation_rate_deg, "[deg/s] Rotation of the floor and cylinders.");
  v.real("Time step fraction", d.time_step_fraction,
         "[-] Time step as a fraction of the Rayleigh time of the smallest particle (<= 0.4).");
  v.real("Maximum speed", d.max_speed, "[m/s] A faster particle stops the run with a report.");
  v.count("Seed", d.seed, "Random seed of the insertion.");
  v.integer("Threads", d.n_threads, 0, 1024, "OpenMP threads; 0 uses all cores.");
  v.integer("Revolutions", d.revolutions, 1, 100000,
            "Revolutions to run (one revolution = one pass of the bed through the sector).");
  v.integer("Revolutions after steady", d.revolutions_after_steady, 0, 100000,
            "wearsim dem stops this many revolutions after the first steady revolution "
            "(see Steady threshold); 0 runs all Revolutions, which stay the maximum.");
  v.integer("Samples per revolution", d.samples_per_revolution, 2, 100000,
            "Evaluation samples per revolution (forces, speeds, bed height, wear rate).");
  v.real("Steady threshold", d.steady_threshold,
         "[-] Coefficient of variation below which a revolution counts as steady.");
  v.integer("Steady revolutions", d.steady_revolutions, 1, 1000,
            "Consecutive steady revolutions that judge the run steady.");
  v.int_list("Snapshot revolutions", d.snapshot_revolutions,
             "Revolutions after which particle snapshots are written (the last always is).");
}

/// How the contact loads on the sample become fields on its faces (wall_loads.h).
template <typename Visitor>
void visit_wall_load_parameters(TesterDemParameters& d, Visitor& v) {
  v.real("Coarse-graining width", d.coarse_graining_width,
         "[m] Width w of the Gaussian kernel, cut at 3w, that coarse-grains the contact loads "
         "on the sample into continuum fields (force and moment kept exactly); 0 uses the "
         "number-mean particle radius at the Scaling factor.");
  v.choice("Wall traction", d.coarse_grained_traction, "coarse-grained", "per face",
           "The traction the FEM receives: the coarse-grained field of the contact forces, "
           "independent of the triangulation, or each face's own window impulse over its area "
           "(noisier on finer meshes).");
  v.choice("Wear field", d.coarse_grained_wear, "coarse-grained", "per face",
           "The wear-law volume: per face as the contacts fell, or coarse-grained with the "
           "same kernel over the faces of each contact's label (label totals kept).");
}

/// The DEM subsection.
template <typename Visitor>
void visit_parameters(TesterDemParameters& d, Visitor& v) {
  v.enter("DEM");
  visit_parameters("Particle", d.particle, v);
  visit_parameters("Sample", d.sample, v);
  visit_parameters("Wall", d.walls, v);
  visit_parameters("Holder", d.holder, v);
  visit_parameters("particle-particle", d.particle_particle, v);
  visit_parameters("particle-wall", d.particle_wall, v);
  visit_bed_parameters(d, v);
  visit_run_parameters(d, v);
  visit_wall_load_parameters(d, v);
  v.leave();
}

} // namespace wear::dem

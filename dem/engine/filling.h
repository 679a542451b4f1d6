#pragma once
// Particle size distributions and filling a region with non-overlapping particles.
#include "dem/engine/particles.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace wear::dem {

/// Diameter bins with mass fractions; the scaling factor s multiplies every diameter.
struct SizeDistribution {
  std::vector<double> diameters;      ///< [m] at s = 1
  std::vector<double> mass_fractions; ///< [-] sum to 1
  double scaling_factor = 1;          ///< [-]
  /// Throws naming the bin when a value is non-physical or fractions do not sum to 1.
  void validate() const;
  /// Number fractions n_k ~ f_k / d_k^3 (equal density).
  std::vector<double> number_fractions() const;
  /// [m] number-weighted mean diameter, scaled: sum_k n_k d_k s
  double mean_diameter() const;
  double min_diameter() const; ///< [m] scaled
  double max_diameter() const; ///< [m] scaled
};

/// A region to fill: inside(x) for a centre x, plus its bounding box.
struct FillRegion {
  Vec3 lo, hi;                             ///< [m] bounding box of centres
  std::function<bool(const Vec3&)> inside; ///< centre admissible
};

/// Box [lo, hi] shrunk by `margin` (so spheres of radius margin stay inside).
FillRegion box_region(const Vec3& lo, const Vec3& hi, double margin);
/// Annular sector r_in..r_out, theta 0..angle, z_lo..z_hi, shrunk by margin.
FillRegion annular_sector_region(double r_in, double r_out, double angle, double z_lo, double z_hi,
                                 double margin);

/// Inserts up to n particles at random, without overlap, drawing diameters from the
/// distribution (deterministic for a seed). Returns the number inserted; stops after
/// max_attempts consecutive failures.
std::size_t insert_random(Particles& p, const FillRegion& region, const SizeDistribution& psd,
                          std::size_t n, double density, int material, std::uint64_t seed,
                          std::size_t max_attempts = 200000);

/// Simple cubic lattice of spacing a (cell centres at (i + 1/2) a) clipped to the region,
/// with a random displacement of amplitude `jitter` (LIGGGHTS' create_atoms + displace_atoms).
std::size_t insert_lattice(Particles& p, const FillRegion& region, double a, double diameter,
                           double density, int material, double jitter, std::uint64_t seed,
                           std::size_t max_n = ~std::size_t(0));

class System;
struct ClumpShape;

/// Inserts up to n rigid clumps of `shape` into `system` (before its setup) at random centres
/// and orientations (uniform over rotations), without overlap of any member with a particle
/// already there or a member of another clump, every member's centre inside `region`; each
/// clump scaled so that its equivalent-volume diameter is one drawn from the PSD (deterministic
/// for a seed). Returns the number inserted; stops after max_attempts consecutive failures.
std::size_t insert_random_clumps(System& system, const FillRegion& region,
                                 const SizeDistribution& psd, const ClumpShape& shape,
                                 std::size_t n, double density, int material, std::uint64_t seed,
                                 std::size_t max_attempts = 200000);

/// Result of fill_to_height.
struct FillReport {
  std::size_t n_particles = 0;
  double bed_height = 0;       ///< [m] above the floor: mean centre height of the top layer + r
  double packing_fraction = 0; ///< [-] solid fraction in the bed core (a diameter off each end)
  double settle_time = 0;      ///< [s] simulated
};

/// Fills a region whose floor is z = z_floor up to about `target_height`: estimates the count
/// from an assumed settled packing (`packing`), inserts at random (no overlaps) into a region
/// `loose_factor` times taller, then runs `system` (already holding walls and materials, not
/// yet set up) until the mean particle speed drops below `speed_tolerance` and the largest
/// below ten times it, or `max_time`
/// passes (`on_check(time)` after each check, for progress). `make_region(z_top)` gives the
/// insertion region up to z_top; `horizontal_area` is the floor area [m^2]. Throws if the region
/// cannot take the particles. `before_setup` is called once the particles are inserted, before
/// the engine sets up (a decomposition over ranks fitted to the bed). With `shape`, clumps of
/// that shape are inserted (insert_random_clumps: the PSD by equivalent-volume diameter, so the
/// count is the spheres'), and `make_region` must keep their members' centres a largest member
/// radius inside.
FillReport fill_to_height(System& system, const std::function<FillRegion(double)>& make_region,
                          double horizontal_area, double z_floor, double target_height,
                          const SizeDistribution& psd, double density, int material,
                          std::uint64_t seed, double loose_factor = 2.0,
                          double speed_tolerance = 0.01, double max_time = 2.0,
                          const std::function<void(double)>& on_check = {}, double packing = 0.6,
                          const std::function<void()>& before_setup = {},
                          const ClumpShape* shape = nullptr);

/// Solid fraction of the particles whose centres lie in z_lo..z_hi over a horizontal area.
double packing_fraction(const Particles& p, double horizontal_area, double z_lo, double z_hi);

} // namespace wear::dem

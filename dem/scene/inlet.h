#pragma once
// A particle source of a scene: an inlet that feeds a mass flow rate through a rectangle
// (outlet.h: the sinks).
#include "dem/engine/filling.h"
#include "dem/engine/system.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace wear::dem {

struct InletSpec {
  std::string name;      ///< for messages
  Vec3 corner;           ///< [m] a corner of the rectangle the particles enter through
  Vec3 edge_u, edge_v;   ///< [m] its two edges from the corner
  double mass_flow = 0;  ///< [kg/s]
  Vec3 velocity;         ///< [m/s] of each new particle; must cross the rectangle
  double start_time = 0; ///< [s]
  double end_time = std::numeric_limits<double>::infinity(); ///< [s]
  SizeDistribution psd;
  double density = 0; ///< [kg/m^3]
  int material = 0;
  std::uint64_t seed = 1;
  /// Clumps of this shape, scaled to the PSD's equivalent-volume diameters, each turned at
  /// random; none: spheres.
  std::shared_ptr<const ClumpShape> shape;
};

/// What an inlet has done so far: enough to continue it exactly (checkpoints).
struct InletState {
  double inserted_mass = 0;     ///< [kg]
  std::uint64_t n_inserted = 0; ///< [-]
  std::vector<double> pending;  ///< [m] diameters drawn but not yet placed, in order
  std::string rng;              ///< the generator's state (std::mt19937_64 as text)
};

/// Particles appear in the insertion box behind the rectangle (upstream of it along the
/// velocity, as deep as two of the largest diameters), at random places clear of each other
/// and of the particles already there, each with the inlet's velocity and no spin. A clump
/// takes the place of the sphere that holds its members (its reach, the bounding radius) and
/// a uniform random orientation from the inlet's generator; its mass is that of its
/// equivalent sphere. A batch
/// brings the mass owed up to time t: W (t - start) minus what was inserted, to within half
/// a particle; a particle that finds no place waits for the next batch (diameters are drawn
/// in advance from the number fractions, so a failed placement does not bias the sizes).
class Inlet {
public:
  /// Checks the spec; throws std::invalid_argument naming the inlet for a degenerate
  /// rectangle or one whose edges are not perpendicular, a velocity that does not cross it, a
  /// non-positive rate, or a rate that would fill the insertion box above a solid fraction of 0.2
  /// (too much for random placement).
  explicit Inlet(InletSpec spec);
  const InletSpec& spec() const { return spec_; }
  /// Unit normal of the rectangle along the flow; the insertion box lies behind it.
  const Vec3& normal() const { return normal_; }
  /// [m] Depth of the insertion box, upstream of the rectangle.
  double depth() const { return depth_; }
  /// [s] Time a particle takes to cross the insertion box: the batch interval.
  double interval() const { return depth_ / normal_speed_; }
  /// [-] Solid fraction of the insertion box at the requested rate.
  double box_solid_fraction() const;
  /// The particles to insert at time t, placed clear of the real particles of `existing`.
  /// Over ranks `existing` must hold every rank's particles that may_touch() the box (the
  /// same on every rank), so that every rank draws the same batch.
  std::vector<NewParticle> batch(double t, const Particles& existing);
  /// True when a particle centred at x [m] may touch a particle of the box: it lies in the box
  /// grown by a largest diameter.
  bool may_touch(const Vec3& x) const;
  /// [kg] Mass the inlet owes at time t: what the rate asks minus what it placed.
  double owed_mass(double t) const;
  InletState state() const;
  /// Continues from a state() of an inlet with the same spec.
  void restore(const InletState& s);

private:
  InletSpec spec_;
  Vec3 normal_;                    ///< unit normal of the rectangle, along the flow
  double normal_speed_ = 0;        ///< [m/s] velocity . normal
  double depth_ = 0;               ///< [m] of the insertion box, upstream of the rectangle
  std::vector<double> cumulative_; ///< number fractions, cumulative
  InletState done_;
  std::mt19937_64 rng_;
  double next_diameter(); ///< [m] the next size to place (pending first)
  /// [-] A particle's bounding radius over its equivalent radius (1 for a sphere).
  double reach_ratio() const;
};

} // namespace wear::dem

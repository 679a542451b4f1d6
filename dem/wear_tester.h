#pragma once
// The circular wear tester in DEM (wear-tester.md): a periodic sector of the annular bed
// with rotating floor and cylinders, the fixed sample as a wearing wall, an optional
// consolidator, a bed filled from the PSD and settled; then revolutions with per-face wear
// integrals, evaluations and, optionally, the reference node-moving deformation.
#include "dem/filling.h"
#include "dem/reference_deformation.h"
#include "dem/system.h"
#include "dem/tester_evaluation.h"
#include "dem/wear_law.h"
#include "meshes/geometry_parameters.h"

#include <functional>
#include <memory>
#include <optional>
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
/// wear-tester.md where it gives them.
struct TesterDemParameters {
  DemMaterial particle{1e8, 0.25, 2650};
  DemMaterial sample{2.5e8, 0.40, 930};
  DemMaterial walls{7.9e10, 0.30, 7850}; ///< floor, cylinders, consolidator (assumed steel)
  PairProperties particle_particle{0.5, 0.55, 0.20};
  PairProperties particle_wall{0.5, 0.30, 0.10}; ///< also particle-sample
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
};

/// Progress of a running tester, for a live line.
struct TesterProgress {
  std::string phase; ///< "settling" or "revolution"
  int revolution = 0;
  double fraction = 0; ///< [-] of the current phase
  double time = 0;     ///< [s] simulated
  double particle_steps_per_second = 0;
};

class WearTester {
public:
  /// `sample` is the sample surface in its own frame (meshes::generate_sample); it is placed
  /// in the tester by geometry.placement. Throws naming the parameter on bad input.
  WearTester(const meshes::GeometryParameters& geometry, const TesterDemParameters& dem,
             const WearLawParameters& wear_law, const ReferenceDeformationParameters& deformation,
             const meshes::SurfaceMesh& sample);

  /// Inserts the bed from the PSD and lets it settle with the walls at rest.
  FillReport fill_and_settle(const std::function<void(const TesterProgress&)>& progress = {});
  /// Runs one revolution with the walls rotating: evaluation samples, wear integrals, the
  /// reference deformation if enabled. Returns the record (also kept in evaluation()).
  const RevolutionRecord&
  run_revolution(const std::function<void(const TesterProgress&)>& progress = {});

  /// Replaces the sample surface (sample frame, e.g. worn and remeshed by the FEM; face
  /// order defines the face fields from now on). Particles that the new surface overlaps by
  /// more than `push_tolerance` of their radius are moved out along the surface normal to
  /// zero overlap; says how many and how far. Per-face sums restart on the new faces.
  struct PushReport {
    int n_pushed = 0;
    double max_distance = 0; ///< [m] largest displacement of a pushed particle
  };
  PushReport set_sample_surface(const meshes::SurfaceMesh& sample, double push_tolerance = 0.01);

  /// Continues a run from a checkpoint instead of fill_and_settle(): sets the system up with
  /// the state's particles and takes over the state, the revolution count and the evaluation
  /// records. The surface must be set first (set_sample_surface) when it changed.
  void restore(const SystemState& state, int revolutions_done,
               const std::vector<RevolutionRecord>& records);

  System& system() { return system_; }
  const System& system() const { return system_; }
  int sample_wall() const { return sample_wall_; }
  const meshes::SurfaceMesh& sample_mesh() const { return system_.wall(sample_wall_).mesh(); }
  const TesterEvaluation& evaluation() const { return *evaluation_; }
  TesterEvaluation& evaluation() { return *evaluation_; }
  const WearLaw& wear_law() const { return *law_; }
  const ReferenceDeformation* deformation() const { return deformation_.get(); }
  /// Integrals and removed volume per face [m^3] of the last completed revolution.
  const WearIntegrals& last_integrals() const { return last_integrals_; }
  const std::vector<double>& last_removed_volume() const { return last_removed_; }
  /// Removed volume per face summed over all revolutions [m^3].
  const std::vector<double>& cumulative_removed_volume() const { return cumulative_removed_; }
  std::uint64_t steps_per_revolution() const { return steps_per_revolution_; }
  double revolution_time() const { return revolution_time_; } ///< [s]
  int n_revolutions_done() const { return revolution_; }

private:
  meshes::GeometryParameters geometry_;
  TesterDemParameters dem_;
  ReferenceDeformationParameters deformation_parameters_;
  System system_;
  int sample_wall_ = -1, particle_material_ = 0;
  std::vector<int> rotating_walls_;
  std::unique_ptr<WearLaw> law_;
  std::unique_ptr<ReferenceDeformation> deformation_;
  std::unique_ptr<TesterEvaluation> evaluation_;
  WearIntegrals last_integrals_;
  std::vector<double> last_removed_, cumulative_removed_;
  double revolution_time_ = 0, sector_ = 0;
  std::uint64_t steps_per_revolution_ = 0;
  int revolution_ = 0;
  bool rotating_ = false;
  void start_rotation();
  void use_thread_count(); ///< DEM/Threads, or all cores, for the engine's loops
};

/// Throws std::invalid_argument naming "DEM/<parameter>" for a non-physical value.
void validate(const TesterDemParameters& p);

} // namespace wear::dem

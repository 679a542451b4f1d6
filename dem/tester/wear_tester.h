#pragma once
// The circular wear tester in DEM (docs/wear-tester.md): a periodic sector of the annular bed
// with rotating floor and cylinders, the fixed sample as a wearing wall, an optional
// consolidator, the sample's holder, a bed filled from the PSD and settled; then revolutions with
// per-face wear integrals, evaluations and, optionally, the reference node-moving deformation.
#include "dem/engine/filling.h"
#include "dem/engine/slab_decomposition.h"
#include "dem/engine/system.h"
#include "dem/evaluation/tester_evaluation.h"
#include "dem/wear/reference_deformation.h"
#include "dem/tester/tester_parameters.h"
#include "dem/wear/wall_loads.h"
#include "dem/wear/wear_law.h"
#include "meshes/geometry_parameters.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wear::dem {

/// Progress of a running tester, for a live line.
struct TesterProgress {
  std::string phase; ///< "settling" or "revolution"
  int revolution = 0;
  double fraction = 0; ///< [-] of the current phase
  double time = 0;     ///< [s] simulated
  double particle_steps_per_second = 0;
};

/// A revolution stopped before its end (advance_revolution with a stop request): where it
/// stands, for an in-stage checkpoint. The DEM state goes with it (System::export_state).
struct OpenRevolution {
  std::uint64_t steps_done = 0; ///< [-] of steps_per_revolution()
  double wall_seconds = 0;      ///< [s] spent on it so far (reporting only)
  RevolutionSamples samples;    ///< the evaluation's samples so far
};

class WearTester {
public:
  /// `sample` is the sample surface in its own frame (meshes::generate_sample); it is placed
  /// in the tester by geometry.placement. Throws naming the parameter on bad input.
  WearTester(const meshes::GeometryParameters& geometry, const TesterDemParameters& dem,
             const WearLawParameters& wear_law, const ReferenceDeformationParameters& deformation,
             const meshes::SurfaceMesh& sample);

  /// Decomposes the bed over the ranks of `link` (before fill_and_settle; every rank builds
  /// the same tester and calls the same functions): angular slabs of equal width over the
  /// sector (or the full circle), measured against the reach at the inner cylinder. The link
  /// must be a ring (the periodic seam, or the full circle, joins the last rank to the first)
  /// and outlive the tester. The results (wear integrals, evaluation, bed figures) are summed
  /// over the ranks in rank order and the same on every rank. restore() takes this rank's part
  /// of a state written on as many ranks, or a whole bed (merge_rank_states).
  void set_rank_link(RankLink* link);
  /// "over N MPI ranks, T threads each: angular slabs of D degrees" (set_rank_link), for logs.
  std::string rank_layout() const;
  /// [-] Particles over all ranks (on one rank: the System's).
  std::size_t n_particles() const { return n_particles_; }
  /// The real particles of the whole bed (position, velocity, spin, radius, id): on one rank
  /// the System's; over ranks every rank's gathered in rank order (every rank calls it
  /// together), for snapshots.
  const Particles& bed_particles();

  /// Inserts the bed from the PSD and lets it settle with the walls at rest.
  FillReport fill_and_settle(const std::function<void(const TesterProgress&)>& progress = {});
  /// Runs one revolution with the walls rotating: evaluation samples, wear integrals, the
  /// reference deformation if enabled. Returns the record (also kept in evaluation()).
  const RevolutionRecord&
  run_revolution(const std::function<void(const TesterProgress&)>& progress = {});
  /// The same, stoppable: `stop` is asked every few steps (stop_check_steps) and a true
  /// answer returns false with the revolution left open between two steps; the next call
  /// continues it. Returns true when the revolution is complete (its record is
  /// evaluation().history().back()). Stopping changes nothing in the results.
  bool advance_revolution(const std::function<void(const TesterProgress&)>& progress,
                          const std::function<bool()>& stop);
  /// The open revolution, if one was stopped (none with the reference deformation, whose
  /// node moves are not part of it).
  std::optional<OpenRevolution> open_revolution() const;
  static constexpr std::uint64_t stop_check_steps = 50;

  /// Replaces the sample surface (sample frame, e.g. worn and remeshed by the FEM; face
  /// order defines the face fields from now on). Particles that the new surface overlaps by
  /// more than `push_tolerance` of their radius are moved out along the surface normal to
  /// zero overlap; says how many and how far. Per-face sums restart on the new faces.
  using PushReport = dem::PushReport;
  PushReport set_sample_surface(const meshes::SurfaceMesh& sample, double push_tolerance = 0.01);

  /// Continues a run from a checkpoint instead of fill_and_settle(): sets the system up with
  /// the state's particles and takes over the state, the revolution count and the evaluation
  /// records. The surface must be set first (set_sample_surface) when it changed.
  void restore(const SystemState& state, int revolutions_done,
               const std::vector<RevolutionRecord>& records);
  /// The same inside a revolution: the revolution goes on from `open` at the next
  /// advance_revolution(). A state written by this rank of as many ranks continues exactly
  /// (System::resume_state); one written on another rank count is imported (a rebuild) with
  /// its wear window, and continues not bit for bit.
  void restore(const SystemState& state, int revolutions_done,
               const std::vector<RevolutionRecord>& records, const OpenRevolution& open);

  System& system() { return system_; }
  const System& system() const { return system_; }
  int sample_wall() const { return sample_wall_; }
  /// The holder's wall, -1 without a holder (Geometry/Tester/Holder = none).
  int holder_wall() const { return holder_wall_; }
  const meshes::SurfaceMesh& sample_mesh() const { return system_.wall(sample_wall_).mesh(); }
  const TesterEvaluation& evaluation() const { return *evaluation_; }
  TesterEvaluation& evaluation() { return *evaluation_; }
  const WearLaw& wear_law() const { return *law_; }
  const ReferenceDeformation* deformation() const { return deformation_.get(); }
  /// The loads on the sample wall over the last completed revolution, on sample_mesh() in
  /// the tester frame (empty fields before the first revolution).
  const WallLoads& last_loads() const { return last_loads_; }
  /// Removed volume per face summed over all revolutions [m^3].
  const std::vector<double>& cumulative_removed_volume() const { return cumulative_removed_; }
  /// How the loads are laid on the sample: the kernel width w [m] resolved from
  /// DEM/Coarse-graining width, and which fields are coarse-grained.
  const LoadSpreading& load_spreading() const { return spreading_; }
  std::uint64_t steps_per_revolution() const { return steps_per_revolution_; }
  double revolution_time() const { return revolution_time_; } ///< [s]
  int n_revolutions_done() const { return revolution_; }

private:
  meshes::GeometryParameters geometry_;
  TesterDemParameters dem_;
  ReferenceDeformationParameters deformation_parameters_;
  System system_;
  SlabDecomposition slabs_;     ///< over ranks (set_rank_link)
  Particles gathered_;          ///< over ranks: the particles over the sample, all ranks
  std::size_t n_particles_ = 0; ///< [-] over all ranks
  int sample_wall_ = -1, holder_wall_ = -1, particle_material_ = 0;
  std::vector<int> rotating_walls_;
  std::unique_ptr<WearLaw> law_;
  std::unique_ptr<ReferenceDeformation> deformation_;
  std::unique_ptr<TesterEvaluation> evaluation_;
  WallLoads last_loads_;
  LoadSpreading spreading_;
  std::vector<double> cumulative_removed_; ///< [m^3] per face, all revolutions
  double revolution_time_ = 0, sector_ = 0;
  std::uint64_t steps_per_revolution_ = 0;
  int revolution_ = 0;
  bool rotating_ = false;
  // The revolution under way between advance_revolution() calls.
  bool open_ = false;
  std::uint64_t steps_done_ = 0;
  double open_seconds_ = 0;          ///< [s] wall time of its earlier calls
  std::vector<double> node_applied_; ///< [m^3] per face, removed volume the nodes took up
  void open_revolution_now();
  void add_particles_of(const SystemState& state);
  const RevolutionRecord& close_revolution(double wall_seconds);
  void start_rotation();
  void use_thread_count(); ///< DEM/Threads, or all cores, for the engine's loops
  void count_particles();  ///< n_particles_ over the ranks
  /// The window's integrals on the sample wall, summed over the ranks.
  WearIntegrals sample_integrals() const { return system_.wear_integrals_over_ranks(sample_wall_); }
  /// The particles the evaluation samples: this rank's, or over ranks those over the sample
  /// from every rank (in rank order).
  const Particles& particles_for_evaluation();
  const Particles& gather_particles(bool only_over_sample);
};

/// Throws std::invalid_argument naming "DEM/<parameter>" for a non-physical value.
void validate(const TesterDemParameters& p);

} // namespace wear::dem

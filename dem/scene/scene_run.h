#pragma once
// A scene's DEM run: the user's walls with their motions, particles filled at the start, fed
// by inlets and drained by outlets, advanced window by window with a record per window.
#include "dem/engine/slab_decomposition.h"
#include "dem/engine/system.h"
#include "dem/scene/binned_fields.h"
#include "dem/scene/dem_parameters.h"
#include "dem/scene/flux_plane.h"
#include "dem/scene/inlet.h"
#include "dem/scene/outlet.h"
#include "dem/scene/scene_walls.h"
#include "dem/scene/wall_node_moves.h"
#include "dem/wear/wall_loads.h"
#include "dem/wear/wear_law.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace wear::dem {

/// The loads on one wall over a window, in the wall's frame (a moving wall's body frame):
/// window means of the force on it and of its moment about the origin, and the Archard
/// load-distance per label (window integral).
struct WallWindowLoads {
  Vec3 force;                          ///< [N]
  Vec3 torque;                         ///< [N m] about the origin
  double archard = 0;                  ///< [N m] integral of F_n |v_t| dt
  std::map<int, double> archard_label; ///< [N m] per face label
};

struct SceneWindow {
  double t_begin = 0, t_end = 0;               ///< [s]
  std::size_t n_particles = 0;                 ///< at the end (a clump counts once)
  std::uint64_t n_inserted = 0, n_removed = 0; ///< since the start
  double inserted_mass = 0;                    ///< [kg] since the start
  std::vector<double> outlet_mass;             ///< [kg] since the start, per outlet
  std::vector<double> flux_mass;        ///< [kg] net mass through each flux plane since the start
  std::vector<WallWindowLoads> walls;   ///< per scene wall
  double mean_speed = 0, max_speed = 0; ///< [m/s] of the particles at the end
  /// [s] time the walls' integrals cover: the window, from the engine's set-up on
  double integrated = 0;
  /// The window's integrals over the ranks of each wearing wall (Wears = true), by the wall's
  /// index in the scene, once the engine has integrated: what a part's loads are made of
  /// (SceneRun::wall_loads), reduced over the ranks once with the window's records.
  std::map<std::size_t, WearIntegrals> wearing;
  BinnedWindow fields; ///< on the grid of Scene/Fields (empty without one)
};

/// What a scene run needs to continue between two windows, bit for bit (same thread count).
struct SceneRunState {
  double time = 0;             ///< [s] scene time
  bool engine_ready = false;   ///< the engine was set up (there were particles)
  SystemState system;          ///< with its continuation part (System::resume_state)
  std::uint64_t n_removed = 0; ///< by the outlets so far
  std::vector<InletState> inlets;
  std::vector<double> outlet_mass;          ///< [kg] per outlet so far
  std::vector<std::uint64_t> outlet_counts; ///< per outlet so far
  std::vector<FluxPlaneState> flux_planes;
  /// Over ranks: the slabs' cuts [m or rad] (n_ranks + 1), which a resume on as many ranks
  /// keeps; empty on one process
  std::vector<double> rank_bounds;
  /// The node moves of the walls whose nodes move (SceneRun::move_wall_nodes), in that order
  std::vector<ReferenceDeformationState> node_moves;
};

struct SceneFillShape; // the Fill region as built once (scene_fill.h)

class SceneRun {
public:
  /// Takes the built walls (build_scene_walls) and checks what needs them: the fill box
  /// may not cut a wall (message naming the wall and its file). Throws before any particle
  /// exists. `impact`: what the wearing walls book per impact (the wear law's,
  /// dem::impact_measure).
  SceneRun(const SceneParameters& scene, const DemParameters& dem, std::vector<SceneWall> walls,
           const ImpactMeasure& impact = {});

  /// Decomposes the scene over the ranks of `link` (before setup() or resume(); null or one
  /// rank: one process): one slab per rank along Scene/Rank slabs along, cut as Scene/Rank
  /// slabs says. Every rank then calls the same functions in the same order; every figure
  /// (windows, loads, states) is the whole scene's on every rank. The link must be a ring
  /// for angular slabs and periodic scenes, a line otherwise.
  void set_rank_link(RankLink* link);
  /// "over N MPI ranks: slabs along x at -0.3, -0.01, 0.01, 0.3 m" (set_rank_link), for logs.
  std::string rank_layout() const;
  /// [-] The most particles a rank holds over the mean over the ranks (1 on one process or
  /// before the engine is set up). Every rank calls it together.
  double rank_imbalance() const;
  /// The same scene at the same moment with its bed cut anew into balanced slabs (between two
  /// windows; every rank calls it together): the ranks' parts merged into the whole bed, which
  /// a new run takes as a resume on another rank count does (it goes on from a rebuild, not
  /// bit for bit as without the new cuts, but the same on every repetition).
  std::unique_ptr<SceneRun> rebalanced() const;
  /// Materials, walls with their motions, the fill (settled when filled to a bed height)
  /// and the engine's set-up; `progress` hears what happens.
  void setup(const std::function<void(const std::string&)>& progress = {});
  /// Instead of setup(): continues from a state() taken between two windows of a run of the
  /// same scene (same walls, in particular a worn part's surface of that moment; the walls
  /// whose nodes move given to move_wall_nodes first, unmoved, and moved here).
  void resume(const SceneRunState& state);
  /// The state between two windows (after advance()). Over ranks (every rank calls it
  /// together) `system` is this rank's part; the rest is the whole scene's.
  SceneRunState state() const;
  /// Over ranks the real particles of every rank on rank 0, in rank order (position,
  /// velocity, spin, radius, id; other ranks get none); one process: a copy of its own.
  /// Every rank calls it together. For snapshots.
  Particles particles_on_first_rank() const;
  /// Runs on to time t_end [s]: every exchange interval the inlets place their batches and
  /// the outlets take their particles, then the engine steps. Returns the window's record.
  SceneWindow advance(double t_end);

  /// Window w's loads on wearing wall k (its integrals in w.wearing, over w.integrated), the
  /// wear law applied, in the wall's frame, the traction and the wear volume laid on the faces
  /// as the DEM subsection's coarse-graining says. Throws std::logic_error when w holds no
  /// integrals of wall k (a wall that does not wear, or a window before any particle).
  WallLoads wall_loads(std::size_t k, const WearLaw& law, const SceneWindow& w) const;
  /// Gives wall k a new surface (e.g. the worn part after a stage), same frame, motion and
  /// material. The particles keep their state; the new surface lies inside the old one where
  /// it wore, and the particles it overlaps by more than `push_tolerance` times their radius
  /// (a remesh's chords, a volume-restoring offset) are pushed out to touch it
  /// (System::push_out_of_wall). Every rank calls it together.
  PushReport replace_wall_surface(std::size_t k, const meshes::SurfaceMesh& mesh,
                                  double push_tolerance);

  /// Moves wall k's nodes inside the DEM from now on (the node-moving method, wall_node_moves.h):
  /// every `every` engine steps and at each window's end, by `amplification` times the removed
  /// volume of `law` since the last move. The wall must be a wearing triangle wall (Wears =
  /// true) that keeps its place (at rest or with a surface motion); its surface stays frozen at the
  /// last valid one after a distortion. The moved surface is the wall's (walls()[k], its loads laid
  /// on it). Throws naming the wall otherwise.
  void move_wall_nodes(std::size_t k, const WearLawParameters& law, std::uint64_t every,
                       double amplification);
  /// Wall k's node moves, or null when its nodes do not move.
  const WallNodeMoves* node_moves(std::size_t k) const;

  double time() const { return time_; } ///< [s]
  /// [s] Inlet batches and outlets act this often (the shortest inlet interval).
  double exchange_interval() const { return exchange_; }
  const System& system() const { return system_; }
  /// The engine itself, to be stepped directly by a benchmark (System::run): what a window
  /// runs between two exchanges in a scene without inlets, outlets or moving nodes.
  System& engine_for_timing() { return system_; }
  const std::vector<SceneWall>& walls() const { return walls_; }
  const std::vector<Outlet>& outlets() const { return outlets_; }
  const std::vector<Inlet>& inlets() const { return inlets_; }
  const std::vector<FluxPlane>& flux_planes() const { return flux_planes_; }
  /// The grid of Scene/Fields, or none.
  const std::optional<BinnedFields>& fields() const { return fields_; }

private:
  SceneParameters scene_;
  DemParameters dem_;
  std::vector<SceneWall> walls_;
  std::vector<Inlet> inlets_;
  std::vector<Outlet> outlets_;
  std::vector<FluxPlane> flux_planes_;
  std::optional<BinnedFields> fields_;
  SlabDecomposition slabs_;  ///< over ranks (set_rank_link)
  RankLink* link_ = nullptr; ///< over ranks (set_rank_link); null on one process
  std::shared_ptr<const SceneFillShape> fill_shape_; ///< none without a Fill region
  /// The clumps' shape (DEM/Particle shape); none for spheres.
  std::optional<ClumpShape> particle_shape_;
  ImpactMeasure impact_; ///< DemSettings::impact of the engine
  /// [m] How far a particle's surface reaches beyond the centres the fill places: the largest
  /// sphere's radius, or a clump's largest member radius at the largest size.
  double fill_margin() const;
  /// [m] The smallest and the largest radius of the engine's spheres: the PSD's, or for
  /// clumps their members' at the smallest and the largest size.
  std::pair<double, double> engine_radii() const;
  System system_;
  int particle_material_ = 0;
  double time_ = 0;     ///< [s] scene time (the engine's clock once it is set up)
  double exchange_ = 0; ///< [s]
  std::uint64_t n_removed_ = 0;
  std::vector<WallNodeMoves> node_moves_; ///< walls whose nodes move (move_wall_nodes)

  /// Over ranks: the cuts Scene/Rank slabs asks (balanced: each rank as many of the particles
  /// every rank holds before the engine's set-up), or balanced whatever it asks.
  void fit_rank_slabs(bool always_balanced = false);
  bool cut_balanced_ = false; ///< a rebalanced run: its whole bed is cut balanced
  /// The slabs along the scene's axis at `bound` (n_ranks + 1 values) to the engine.
  void use_rank_slabs(std::vector<double> bound);
  /// [m or rad] The range the slabs divide: the domain along the axis, the sector, or the
  /// full circle.
  std::pair<double, double> rank_range() const;
  RankLink* rank_link() const { return link_; }
  /// True once the engine is set up (a set-up builds the lists once at least).
  bool engine_ready() const { return system_.n_rebuilds() > 0; }
  void add_materials_and_walls();
  /// The labels of the faces wall k's window integrals are summed on: its triangles, or the
  /// one face of an exact surface of revolution.
  const std::vector<int>& accounting_labels(std::size_t k) const;
  void fill(const std::function<void(const std::string&)>& progress);
  /// Runs the engine `n` steps, moving the walls' nodes on the steps they are due.
  void run_steps(std::uint64_t n);
  /// Moves every moving wall's nodes now and gives the scene's wall its surface.
  void move_nodes();
  /// Inlet batches, flux-plane samples and outlets at the current time; sets the engine up
  /// at the first particle when it started empty.
  void exchange();
};

} // namespace wear::dem

#pragma once
// The DEM system: particles, walls, materials and the time loop (velocity Verlet).
#include "dem/engine/clump_shape.h"
#include "dem/engine/clumps.h"
#include "dem/engine/impact_measure.h"
#include "dem/engine/material.h"
#include "dem/engine/mesh_wall.h"
#include "dem/engine/neighbor_list.h"
#include "dem/engine/pair_kernel.h"
#include "dem/engine/particles.h"
#include "dem/engine/rank_link.h"
#include "dem/engine/revolution_wall.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace wear::dem {

/// Cylindrical periodic boundary: the sector 0 <= theta < angle about the z axis through the
/// origin. A particle leaving through one cut plane re-enters through the other, position,
/// velocity and spin rotated by the sector angle; pairs across the cut see ghost images.
struct PeriodicSector {
  bool enabled = false;
  double angle = 0; ///< [rad]
};

/// Planar periodic boundary: the slab lo <= x_axis < hi along one coordinate axis. A particle
/// leaving through one plane re-enters through the other, its position shifted by the period
/// L = hi - lo (velocity and spin unchanged); pairs across the planes see ghost images.
struct PeriodicSlab {
  bool enabled = false;
  int axis = 0;          ///< 0, 1, 2: x, y, z
  double lo = 0, hi = 0; ///< [m] the planes
};

struct DemSettings {
  Vec3 gravity{0, 0, -9.81};       ///< [m/s^2]
  double time_step = 0;            ///< [s]; 0: time_step_fraction x Rayleigh time
  double time_step_fraction = 0.2; ///< [-] of the Rayleigh time of the smallest particle
  bool force_time_step = false;    ///< allow a step above 40 % of the Rayleigh time
  double skin = 0;                 ///< [m] neighbour-list skin; 0: 0.25 x smallest diameter
  /// [m] The largest radius a particle may have, also one inserted later (the lists' reach);
  /// 0: the largest at setup.
  double max_radius = 0;
  /// [m] The largest distance of a clump's member centre from its body's centre, also of a
  /// clump inserted later (the ghosts' reach); 0: the largest at setup.
  double max_overhang = 0;
  double max_speed = 50; ///< [m/s] a faster particle stops the run
  /// What a wearing wall books per impact besides its count and energy (the impact law's).
  ImpactMeasure impact;
  double start_time = 0;                                           ///< [s] the clock at setup
  meshes::BoundingBox domain{{-1e3, -1e3, -1e3}, {1e3, 1e3, 1e3}}; ///< [m] leaving it is an error
  PeriodicSector periodic;
  PeriodicSlab periodic_slab; ///< excludes `periodic`
};

/// Values a wearing wall's window accumulator holds per face (and for the totals after the
/// last face): impulse [N s] x 3, normal impulse [N s], Archard [N m], sliding work [J],
/// contact-steps [-] (0 in the totals), first moment of the normal impulse [N s m] x 3,
/// moment of the impulse about the origin [N s m] x 3.
constexpr std::size_t n_wear_values = 16;

/// Extensive per-face integrals on a wearing wall over the current window (docs/theory.md section
/// 4). Points are the contact points on the wall (the closest point to the particle centre), in the
/// wall's frame (a moving wall's mesh as given, its body frame; vectors rotated there too); the
/// moments are about its origin.
struct WearIntegrals {
  std::vector<Vec3> impulse;          ///< [N s] integral of the force on the face
  std::vector<double> normal_impulse; ///< [N s] integral of F_n
  std::vector<double> archard;        ///< [N m] integral of F_n |v_t|
  std::vector<double> sliding_work;   ///< [J] integral of |F_t . v_t|
  std::vector<double> contact_steps;  ///< [-] contact-steps (split contacts count fractionally)
  /// [N s m] integral of x_c F_n: over normal_impulse, the face's load centroid
  std::vector<Vec3> normal_moment;
  std::vector<Vec3> impulse_moment; ///< [N s m] integral of x_c x F
  // Impacts: booked once per contact, at its first step (the particle approaching the wall).
  std::vector<double> impacts;        ///< [-] count (split contacts fractionally)
  std::vector<double> impact_energy;  ///< [J] sum of m v_n^2 / 2 at the impacts
  std::vector<double> impact_measure; ///< [-] sum of DemSettings::impact (impact_measure.h)
  /// Per-contact totals of the same window, summed before any splitting over faces.
  double total_archard = 0, total_normal_impulse = 0, total_sliding_work = 0;
  double total_impacts = 0, total_impact_energy = 0, total_impact_measure = 0;
  Vec3 total_impulse;        ///< [N s]
  Vec3 total_normal_moment;  ///< [N s m]
  Vec3 total_impulse_moment; ///< [N s m]
  /// Every per-face field sized n_faces and zero; the totals are left as they are.
  void zero_faces(std::size_t n_faces);
};

/// Particles pushed out of a wall's new surface (System::push_out_of_wall).
struct PushReport {
  int n_pushed = 0;
  double max_distance = 0; ///< [m] largest displacement of a pushed particle
};

/// Everything that decides how a set-up System continues: the real particles in the engine's
/// order, the pair list with its tangential histories, the wall-contact slots and the clock.
/// Imported into a System set up with the same particles, walls and thread count it continues
/// the run bit for bit (checkpoints): import_state() through a list rebuild (the coupler does
/// that at every stage boundary, resumed or not), resume_state() exactly as if the run had
/// never stopped, at any step (in-stage checkpoints), from the continuation part below.
struct SystemState {
  std::vector<Vec3> position, velocity, angular_velocity; ///< [m], [m/s], [rad/s]
  std::vector<Vec3> force, torque;                        ///< [N], [N m] of the last step
  std::vector<double> radius, mass, inertia;              ///< [m], [kg], [kg m^2]
  std::vector<int> material;
  std::vector<std::int64_t> id;
  std::vector<std::uint32_t> ghost_owner;    ///< real particle behind each ghost slot
  std::vector<std::uint32_t> pair_i, pair_j; ///< listed pairs (j >= n: ghost slot j - n)
  std::vector<Vec3> pair_history;            ///< [m] tangential overlap per listed pair
  std::vector<std::uint32_t> wall_particles; ///< particles owning wall-contact slots
  std::vector<Vec3> slot_normal, slot_delta; ///< [-], [m] per slot
  std::vector<std::int32_t> slot_wall;       ///< wall of each slot (-1: free)
  double time = 0;                           ///< [s]
  std::uint64_t n_steps = 0, n_rebuilds = 0;
  // Continuation: what the last rebuild decided and the open window, for resume_state().
  std::vector<Vec3> reference_position; ///< [m] positions at the last rebuild (its trigger)
  std::vector<std::uint32_t> wall_candidate_offset, wall_candidate; ///< per particle
  std::vector<double> particle_cost; ///< [-] the threads' split of the force evaluation
  /// The id the next inserted particle gets (0: one past the largest id).
  std::int64_t next_id = 0;
  /// [s] Time of the moving walls' poses at the last rebuild (their share of its trigger).
  double wall_reference_time = 0;
  /// The wear window's accumulators as the threads hold them: per thread, per wearing wall
  /// in wall order, n_wear_values per face and as many totals (WearIntegrals' order).
  std::vector<double> wear_window;
  int n_threads = 0;
  // Over ranks (System::set_rank_link; one process: rank 0 of 1, no rank ghosts): this rank's
  // part of the bed, continued only by the same rank of the same rank count.
  int rank = 0, n_ranks = 1;
  /// Ghost slots [0, n_periodic_ghosts) are periodic images, the first n_image_ghosts of all
  /// are turned across the periodic boundary (0 for both: every ghost an image, as before).
  std::uint64_t n_periodic_ghosts = 0, n_image_ghosts = 0;
  /// The ghosts of the rank below in their slots after the periodic ones, 14 values each:
  /// position, velocity, spin, radius, mass, inertia, material, id (the ghost message).
  std::vector<double> rank_ghosts;
  std::vector<std::uint32_t> rank_sent_up; ///< particles the rank above holds ghosts of
  /// The rigid bodies whose members are particles above (empty for a bed of spheres).
  ClumpsState clumps;
};

/// Wall-clock time of the step loop's phases, summed since the last reset_phase_times() [s].
/// The force evaluation's parts are averaged over the threads; `wait` is the time a thread
/// spends in the force evaluation's parallel region beyond its own pairs and walls (the fork,
/// the join and the imbalance of the split).
struct PhaseTimes {
  double pair = 0;        ///< [s] pair kernel
  double wall = 0;        ///< [s] particle-wall contacts
  double wait = 0;        ///< [s] idle in the force evaluation
  double integration = 0; ///< [s] kicks, drift, ghost refresh
  double rebuild = 0;     ///< [s] neighbour-list rebuilds
  std::uint64_t n_steps = 0;
};

/// A particle to add between steps (System::insert_particles).
struct NewParticle {
  Vec3 position;         ///< [m] (a clump's centre of mass)
  Vec3 velocity;         ///< [m/s]
  Vec3 angular_velocity; ///< [rad/s]
  double radius = 0;     ///< [m] (a clump's equivalent-volume radius)
  double density = 0;    ///< [kg/m^3]
  int material = 0;
  /// A clump of this shape, scaled to the equivalent diameter 2 radius and turned by
  /// `orientation`; nullptr: a sphere. The caller keeps it alive through the insertion.
  const ClumpShape* shape = nullptr;
  Quaternion orientation;
};

/// A particle taken out between steps (System::remove_particles).
struct RemovedParticle {
  std::int64_t id = 0;
  Vec3 position;   ///< [m]
  Vec3 velocity;   ///< [m/s]
  double mass = 0; ///< [kg]
};

struct Energy {
  double kinetic = 0, rotational = 0, potential = 0, elastic = 0; ///< [J]
  double total() const { return kinetic + rotational + potential + elastic; }
};

/// One past the largest of the n ids; throws std::invalid_argument for a negative, too large
/// (>= 2^32 - 1) or repeated id.
std::int64_t first_free_id(const std::int64_t* id, std::size_t n);

class System {
public:
  MaterialTable materials;
  Particles particles;
  DemSettings settings;

  /// Adds a wall; returns its index. Before setup() only. Mesh and revolution walls share one
  /// numbering (candidates, wall slots, wear integrals); a revolution wall lists face 0.
  int add_wall(const MeshWall& wall);
  int add_wall(const RevolutionWall& wall);
  /// Mesh wall w; throws std::invalid_argument for a revolution wall.
  const MeshWall& wall(int w) const;
  /// Revolution wall w; throws std::invalid_argument for a mesh wall.
  const RevolutionWall& revolution_wall(int w) const;
  WallKind wall_kind(int w) const { return wall_kind_.at(w); }
  int n_walls() const { return static_cast<int>(wall_kind_.size()); }

  /// Checks the input, fixes the time step, builds lists and initial forces. Throws with a
  /// message naming what is wrong (time step, material, overlap, particle outside domain).
  void setup();
  void step();
  void run(std::uint64_t n_steps);
  /// Threads used from now on (default: OpenMP's maximum at setup). Resets the wear
  /// integrals of the current window; results stay bitwise reproducible per thread count.
  void set_n_threads(int n);
  int n_threads() const { return n_threads_; }

  double time() const { return time_; } ///< [s]
  std::uint64_t n_steps() const { return n_steps_; }
  double time_step() const { return dt_; } ///< [s]
  double rayleigh_time() const;            ///< [s] of the smallest particle
  std::uint64_t n_rebuilds() const { return n_rebuilds_; }
  std::size_t n_pair_contacts() const { return n_pair_contacts_; } ///< pairs in contact now
  std::size_t n_neighbor_pairs() const { return neighbors_.n_pairs(); }
  std::size_t n_ghosts() const { return ghost_owner_.size(); }
  std::size_t n_wall_particles() const { return wall_particles_.size(); }  ///< near a wall
  std::size_t n_wall_candidates() const { return wall_candidate_.size(); } ///< faces listed
  /// Faces listed for particle i at the last rebuild, each (wall << 24) | face.
  std::pair<const std::uint32_t*, const std::uint32_t*> wall_candidates(std::size_t i) const {
    return {wall_candidate_.data() + wall_candidate_offset_.at(i),
            wall_candidate_.data() + wall_candidate_offset_.at(i + 1)};
  }
  Energy energy() const;
  /// Time spent per phase since the last reset (a reset also happens at set_n_threads()).
  const PhaseTimes& phase_times() const { return phase_times_; }
  void reset_phase_times() { phase_times_ = {}; }
  /// Bytes held per particle by the engine's arrays, excluding contact history.
  double bytes_per_particle() const;

  void set_wall_motion(int w, const WallMotion& m);
  /// True when some mesh wall has a rigid motion of its geometry (MeshWall::set_rigid_motion).
  bool has_moving_walls() const;
  /// Moves the vertices of wall w (same topology, e.g. a worn surface) and rebuilds the
  /// contact candidates; contact histories are kept.
  void set_wall_vertices(int w, const std::vector<Vec3>& vertices);

  /// Pushes the real particles that `mesh`, the new surface of mesh wall w (its frame: a moving
  /// wall's body frame, at the wall's current pose), would hold overlapping by more than
  /// `tolerance` times their radius out along closest point -> centre to touch it (a surface
  /// that recedes from the bed encloses none; a remesh's chords and a volume-restoring offset
  /// may reach a little outwards). Call before replace_wall_mesh(w, mesh). Over ranks every
  /// rank calls it together and the report is the whole bed's.
  PushReport push_out_of_wall(int w, const meshes::SurfaceMesh& mesh, double tolerance);
  /// Replaces the mesh of wall w (new topology allowed, e.g. a remeshed worn surface); its
  /// material, motion, wear flag, name and covered labels stay. The wall's wear integrals restart
  /// at zero.
  void replace_wall_mesh(int w, const meshes::SurfaceMesh& mesh);

  /// Adds particles between steps (after setup), each with a new stable id (next_id() on; a
  /// clump's members one each, in member order), their forces gravity only (a clump's on the
  /// body). A clump's members must fit the reach fixed at setup (DemSettings::max_radius and
  /// max_overhang). The caller places them clear of the other particles and the
  /// walls (an overlap would give a large repulsion at the next step). Rebuilds the lists;
  /// the others keep their contact histories. Throws for a non-positive radius or density or
  /// an unknown material, naming the batch entry.
  void insert_particles(const std::vector<NewParticle>& batch);
  /// Removes, between steps, the real particles for which remove(centre, radius) holds (an
  /// outlet), and returns them: the clumps for which it holds at the body's centre and reach
  /// (body_reach), whole, one record each (its first member's id, its centre, velocity and
  /// mass), then the free spheres in the engine's order. Rebuilds the lists; the pairs and
  /// wall contacts that stay keep their histories.
  std::vector<RemovedParticle>
  remove_particles(const std::function<bool(const Vec3&, double)>& remove);
  /// The stable id the next inserted particle gets: ids are never reused.
  std::int64_t next_id() const { return next_id_; }

  /// [m] The radius about body b's centre that holds its members.
  double body_reach(std::size_t b) const {
    double reach = 0;
    for (std::uint32_t k = clumps_.member_begin[b]; k < clumps_.member_begin[b + 1]; ++k)
      reach = std::max(reach, meshes::norm(clumps_.member_offset[k]) +
                                  particles.radius[clumps_.member_slot[k]]);
    return reach;
  }
  /// Grains over every rank: free spheres and clumps, each clump one (Every rank calls it
  /// together over ranks).
  std::size_t n_grains_over_ranks() const;

  /// Adds a rigid clump of `shape` (its body frame and size as they are) before setup():
  /// its members become particles of `material` with the next ids, the body's mass is
  /// density x the union's volume, its moments density x the shape's. The centre of mass at
  /// x, orientation q (body -> space), velocity v and angular velocity w (space frame).
  /// Returns the body's index. Throws std::invalid_argument for a non-positive density, an
  /// unknown material or a shape without members, and std::logic_error after setup().
  std::size_t add_clump(const ClumpShape& shape, double density, int material, const Vec3& x,
                        const Quaternion& q, const Vec3& v = {}, const Vec3& w = {});
  /// The bodies (empty for a bed of spheres).
  const Clumps& clumps() const { return clumps_; }
  /// Adds the bodies of a state (SystemState::clumps) before setup(), their members among the
  /// particles added from the same state, so that the state can be imported or resumed.
  /// Throws std::invalid_argument for arrays that do not fit together, std::logic_error after
  /// setup().
  void add_state_clumps(const ClumpsState& state);

  /// The state that decides the continuation (see SystemState).
  SystemState export_state() const;
  /// Takes over a state exported from a System with the same particles (radii, materials),
  /// walls and thread count, after setup(); rebuilds the lists from it. Forces are taken as
  /// stored, not recomputed, so tangential histories are not advanced twice. Over ranks the
  /// state is either this rank's own part (written by the same rank of the same rank count)
  /// or a whole bed as one process holds it (merge_rank_states, or a one-process state): then
  /// every rank takes the whole bed and keeps what its slab owns, with the histories of its
  /// pairs and its wall slots (a run continues on another rank count, not bit for bit).
  void import_state(const SystemState& state);
  /// Adds the open wear window of `state` (summed over its threads) to this System's, after
  /// import_state() of the same state: the part of a window that a merged or re-decomposed
  /// state carries into the revolution it continues. Over ranks, each rank adds its own part's
  /// window, or rank 0 alone a whole bed's. Throws when the window does not fit the walls.
  void add_wear_window(const SystemState& state);
  /// Takes over a state exported between two steps exactly as it was: lists, histories, wall
  /// slots, thread split and the open wear window; nothing is rebuilt. The run then continues
  /// as if it had never stopped, bit for bit (same thread count, which is checked).
  void resume_state(const SystemState& state);

  /// Window integrals of a wearing wall (summed over threads in a fixed order).
  WearIntegrals wear_integrals(int wall) const;
  void reset_wear_integrals();

  /// Decomposes the bed over ranks, one slab each (docs/dem.md, "A bed decomposed over
  /// ranks"); before setup(), which passes each particle to the rank that owns it and refuses
  /// slabs narrower than the reach. Every rank then calls the same functions in the same order
  /// (the steps exchange messages). `link` and `slabs` must outlive the System. No link or one
  /// rank: the engine of one process, bit for bit.
  void set_rank_link(RankLink* link, const RankSlabs* slabs);
  /// The ranks' messages (set_rank_link), null on one rank.
  RankLink* rank_link() const { return rank_link_; }
  /// [-] The real particles of every rank (every rank calls it together); on one rank n_real.
  std::size_t n_particles_over_ranks() const;
  /// wear_integrals(wall) added over the ranks field by field in rank order, the same bits on
  /// every rank (every rank calls it together); on one rank wear_integrals(wall).
  WearIntegrals wear_integrals_over_ranks(int wall) const;

private:
  /// Particles to add and a rule for those to remove, applied by a rebuild between steps.
  struct ParticleChanges {
    const std::vector<NewParticle>* insert = nullptr;
    const std::function<bool(const Vec3&, double)>* remove = nullptr;
    std::vector<RemovedParticle>* removed = nullptr; ///< receives the removed particles
  };
  /// `in_step`: called between the drift and the force evaluation, when the particles'
  /// forces hold gravity only (a wrapped particle's is then not rotated). `changes`: applied
  /// after the old lists' histories are keyed by id and before the new lists are built.
  void rebuild(bool in_step = false, const ParticleChanges* changes = nullptr);
  /// Appends a clump's members to the particles and its body to the bodies (add_clump and
  /// inserted clumps; q normalised); with `new_ids` the members take ids from next_id_ on.
  void place_clump(const ClumpShape& shape, double density, int material, const Vec3& x,
                   const Quaternion& q, const Vec3& v, const Vec3& w, bool new_ids);
  /// Removes and appends real particles (rebuild's step for `changes`; ghosts dropped).
  void apply_particle_changes(const ParticleChanges& changes);
  /// Real particle `from` into slot `to` (compaction after outlets and migration).
  void move_particle(std::size_t to, std::size_t from);
  // The steps of rebuild(), in its order (system_rebuild.cc). Each receives its inputs and
  // fills its outputs through its arguments; the buffers are those of rebuild_scratch_, so that
  // a rebuild in the step loop allocates nothing once they have grown to the bed's size.
  /// A pair's tangential history in the canonical frame and orientation, keyed by the two
  /// stable ids (lower << 32 | higher), so that it survives wrapping and reordering.
  struct CarriedHistory {
    std::uint64_t key;
    std::uint32_t lower; ///< current index of the lower-id particle
    Vec3 h;              ///< [m]
  };
  /// Carried histories bucketed by the lower id (counting sort, O(n)): those whose lower id
  /// is l are entries [bucket[l], bucket[l + 1]), a few each.
  struct HistoryTable {
    std::vector<std::uint32_t> bucket;
    std::vector<CarriedHistory> entry;
  };
  /// Collects the histories of the current list, in the canonical frame and orientation, into
  /// `old`, in list order (lookups match the whole key, so no order is relied on).
  void canonical_pair_histories(std::vector<CarriedHistory>& old);
  /// Where each particle's wall-contact slots are, by stable id: its index in
  /// wall_particles_, -1 for none.
  void wall_slots_by_id(std::vector<std::int32_t>& slots_of_id) const;
  /// Wraps the particles into [0, angle), rotating their state, their wall slots and the
  /// carried histories of which they are the lower-id particle.
  /// Wraps the bodies whose centre left the periodic domain (with their force and torque
  /// between steps); body_wrap[b] is +1, -1 or 0 as for a particle.
  void wrap_bodies(bool in_step, std::vector<signed char>& body_wrap);
  void wrap_into_sector(bool in_step, const std::vector<std::int32_t>& slots_of_id,
                        std::vector<CarriedHistory>& old);
  void bucket_by_lower_id(const std::vector<CarriedHistory>& old, HistoryTable& table);
  /// Ghosts: images of the particles within reach of the theta = angle plane, then those of
  /// the rank below (over ranks).
  void make_ghosts();
  /// Histories of the new pair list from the carried ones (zero for a new pair).
  void carry_pair_histories(const HistoryTable& old);
  /// The first half of rebuild(), for the particles as they are: the pair histories and
  /// wall slots keyed by stable id (rebuild_scratch_'s old_histories and slots_of_id), the
  /// particles wrapped into the periodic sector with what turns with them.
  void key_by_id(bool in_step);
  /// The second half of rebuild(), once the particles are where they belong: the carried
  /// histories bucketed, the spatial order, ghosts, the pair list with its histories, wall
  /// candidates with their slots, the threads' split and the rebuild's reference.
  void relist(const std::vector<CarriedHistory>& old, const std::vector<std::int32_t>& slots_of_id);
  /// Lists wall_candidate_ in particle order and the count per particle in `n_candidates`.
  void find_wall_candidates(std::vector<std::uint32_t>& n_candidates);
  /// wall_candidate_offset_ and wall_particles_ from the counts per particle.
  void index_wall_particles(const std::vector<std::uint32_t>& n_candidates);
  /// slots_ to the new wall_particles_, from where `slots_of_id` had them.
  void carry_wall_slots(const std::vector<std::int32_t>& slots_of_id);
  /// Closing half-kick of the previous step if `close_previous`; opening half-kick, drift,
  /// list rebuild if needed, forces.
  void advance(bool close_previous);
  /// The walls within reach of particle i's surface and the particles overlapping it, for the
  /// message of a run that stops on it (system_diagnostics.cc).
  std::string describe_surroundings(std::size_t i) const;
  void close_step(); ///< closing half-kick, clock
  // Clumps (system_clumps.cc): members move with their bodies, their forces act on them.
  Clumps clumps_;
  std::vector<std::int32_t> body_of_slot_; ///< per real slot: its body, -1 for a free sphere
  /// Bodies [first, second) of `thread` in the drift and kick: equal counts.
  std::pair<std::size_t, std::size_t> body_range(int thread) const;
  /// The drift pass for the bodies of `thread`: closing half-kick of the previous step if
  /// `close_previous`, opening half-kick, drift and rotation, the members placed and packed,
  /// their forces zeroed and the bodies' set to gravity; the members' largest squared
  /// displacement since the last rebuild into max_moved2.
  void drift_clumps(int thread, bool close_previous, double& max_moved2);
  void close_clumps(int thread); ///< closing half-kick of the bodies of `thread`
  /// The members' forces and torques onto their bodies (after the force evaluation).
  void gather_clump_forces();
  /// Particles [first, second) of `thread` in the drift and kick: equal counts.
  std::pair<std::size_t, std::size_t> kick_range(int thread) const;
  /// v += dt/2 F/m, w += dt/2 T/I for particle i.
  void closing_kick(std::size_t i, const Vec3& f, const Vec3& t);
  void reset_forces(); ///< gravity only, no torque: where the pair loop starts from
  /// Adds the forces the threads kept for particles they do not own, in thread order.
  void apply_foreign_forces();
  void refresh_ghosts();
  /// Places the moving walls at time t [s] (their contacts are evaluated there).
  void move_walls(double t);
  /// [m] The largest distance a moving wall's point may have moved since the last rebuild.
  double wall_displacement() const;
  /// The kernels' copies (packed positions and motion, which pairs touch, the wall candidates'
  /// bounds) from the particles' arrays, the pair histories and the candidate list: after a
  /// rebuild or a resumed state.
  void pack_particles();
  void sort_spatially();
  void compute_forces();
  /// The pairs and near-wall particles owned by `thread`; forces and torques are added to F
  /// and T (indexed by particle). pair_forces returns the pairs in contact.
  std::size_t pair_forces(int thread, Vec3* F, Vec3* T);
  void wall_forces(int thread, Vec3* F, Vec3* T);
  void check_particles_or_throw(const char* stage);
  /// Throws std::invalid_argument naming what does not fit when state s cannot be imported.
  /// `whole`: a whole bed taken over ranks (any particle count, written by one process).
  void check_importable(const SystemState& s, bool whole = false) const;
  /// The same for the continuation part that resume_state() takes over.
  void check_resumable(const SystemState& s) const;
  /// The real particles' arrays and the clock from s (both imports).
  void take_particles(const SystemState& s);
  /// Ghost slots of ghost_owner_ with their owners' properties and current state.
  void fill_ghost_slots();

  // A bed over ranks (system_ranks.cc); rank_link_ is null on one rank.
  RankLink* rank_link_ = nullptr;
  const RankSlabs* rank_slabs_ = nullptr;
  SlabCuts slab_cuts_;
  /// Ghost slots [n_real, n_real + n_periodic_ghosts_) are periodic images of this rank's
  /// particles, the rest ghosts of the rank below; the first n_image_ghosts_ of all are images
  /// across the periodic boundary (rotated; over ranks, rank 0's ghosts from the last rank).
  std::size_t n_periodic_ghosts_ = 0, n_image_ghosts_ = 0;
  /// The rank messages' buffers and what the last rebuild decided (kept between steps).
  struct RankScratch {
    std::vector<signed char> leaving; ///< per real particle: -1 to the rank below, +1 above
    std::vector<std::uint8_t> leaves_by_id;
    std::vector<std::uint32_t> sent_up; ///< particles the rank above holds ghosts of, in order
    std::vector<double> up, down, from_below, from_above;
    std::vector<std::uint8_t> body_stays; ///< per body: its centre stays in the slab
    std::vector<std::int64_t> member_ids; ///< a received body's members
    std::vector<Vec3> member_offsets;     ///< [m] and their body-frame centres
  };
  RankScratch rank_scratch_;
  /// setup(): every particle to its owner (each keeps its own when all ranks hold the same bed).
  void distribute_over_ranks();
  /// import_state() of a whole bed over ranks (see there).
  void import_whole_state(const SystemState& s);
  /// setup(): the Rayleigh time and the smallest radius as minima, r_max and the members'
  /// overhang as maxima, over ranks.
  void reduce_setup_values(double& t_r, double& r_max, double& r_min, double& overhang);
  /// The rank that owns real particle i: of its body's centre for a member (a body stays whole
  /// on one rank), of its own centre for a free sphere. body_of_slot_ indexed.
  int owner_rank(std::size_t i) const {
    const std::int32_t b = clumps_.empty() ? -1 : body_of_slot_[i];
    return slab_cuts_.owner(b >= 0 ? clumps_.position[std::size_t(b)] : particles.position[i]);
  }
  /// Keeps the bodies whose centre this rank's slab owns (after the particles were kept by
  /// owner_rank) and indexes their members.
  void keep_own_bodies();
  /// setup(): no periodic boundary, next_id_ over ranks, ids unique, slabs as wide as the reach.
  void check_ranks_at_setup();
  /// rebuild(): particles that left the slab go to the neighbour with their wall slots; the
  /// histories of their pairs go to both neighbours (appended to `old`, slots_of_id extended).
  void migrate_over_ranks(std::vector<std::int32_t>& slots_of_id, std::vector<CarriedHistory>& old);
  void exchange_rank_ghosts(); ///< sends the ghosts up, appends those from below to ghost_owner_
  /// Their slots from `message` (the ghost message's layout), after the periodic ghosts.
  void place_rank_ghosts(const std::vector<double>& message);
  void refresh_rank_ghosts(); ///< each step: positions, velocities and spins from the owners
  void return_ghost_forces(); ///< each step: forces on the ghosts back to the owners
  /// advance() over ranks: the common rebuild decision, ghosts, forces and their return.
  void ranked_forces(bool need_rebuild, double t_drift);

  // Walls in one numbering w: wall_kind_[w] says which array holds it, at wall_local_[w].
  std::vector<MeshWall> walls_;
  std::vector<RevolutionWall> revolution_walls_;
  std::vector<WallKind> wall_kind_;
  std::vector<std::int32_t> wall_local_;
  const std::string& wall_name(int w) const;
  bool wall_wearing(int w) const;
  std::size_t wall_faces(int w) const; ///< faces of its wear accounting
  void size_wear_accumulators();       ///< wear_acc_ for n_threads_ threads, zeroed
  /// The index in walls_ of mesh wall w; `what` names the caller in the error for another kind.
  std::size_t mesh_index(int w, const char* what) const;
  /// Checks a wall about to be added (before setup, known material, at most 256 walls) and
  /// gives it the next number, held by the array of its kind at index `local`.
  int register_wall(WallKind kind, std::size_t local, const std::string& name, int material);
  void add_wall_elastic_energy(double& e) const; ///< adds the wall contacts' Hertz energy [J]
  std::vector<ContactParameters> contact_;
  int n_mat_ = 0;
  NeighborList neighbors_;
  double dt_ = 0, time_ = 0, skin_ = 0, r_max_ = 0;
  /// [m] The largest distance of a member's centre from its body's centre (0 without clumps):
  /// a body wraps across a periodic boundary as one, by its centre, so its members may lie
  /// that far beyond the boundary.
  double member_overhang_ = 0;
  /// Clumps in the bed on any rank (setup): a part's import then restores the rank's bodies,
  /// however many it holds.
  bool has_clumps_ = false;
  /// [m] How far inside a periodic boundary a particle has an image: the contact reach of two
  /// particles and the skin, and the members' overhang.
  double ghost_reach() const { return 2 * r_max_ + skin_ + member_overhang_; }
  std::uint64_t n_steps_ = 0, n_rebuilds_ = 0;
  std::int64_t next_id_ = 0; ///< stable id of the next inserted particle
  bool set_up_ = false;
  int n_threads_ = 1;

  // Periodic boundary, a map from beyond the low boundary into the domain: points x -> R x +
  // shift, vectors v -> R v; R the rotation about z by the sector angle (cos_t_, sin_t_; the
  // identity for a slab), shift the slab's period along its axis (zero for a sector).
  double cos_t_ = 1, sin_t_ = 0;
  Vec3 shift_{0, 0, 0};
  bool periodic() const { return settings.periodic.enabled || settings.periodic_slab.enabled; }
  std::vector<std::uint32_t> ghost_owner_;

  // Pairs: tangential history per listed pair.
  std::vector<Vec3> pair_history_;
  std::vector<PairBlock> pair_block_; // one per thread
  // Force evaluation: thread t owns particles [owner_split_[t], owner_split_[t + 1]), the
  // pairs [pair_split_[t], ...) listed under them and the near-wall particles
  // [wall_split_[t], ...) among them; ranges of equal estimated cost (particle_cost_, set at
  // each rebuild). The drift and kick split the particles in equal counts.
  std::vector<double> particle_cost_;
  std::vector<std::size_t> owner_split_, pair_split_, wall_split_;
  void count_particle_costs();
  void split_ownership();
  void size_foreign_forces(); ///< foreign_ for the current split
  // Every thread adds the forces on the particles it owns into their own arrays; those on
  // other particles go to its ForeignForces, added after the evaluation in thread order.
  std::vector<ForeignForces> foreign_;
  std::vector<PackedPosition> packed_position_; // position and radius per slot, for the kernel
  std::vector<PackedMotion> packed_motion_;     // velocity, spin and mass per slot, for the kernel
  /// packed_motion_[k] from the particles' arrays.
  void pack_motion(std::size_t k) {
    const Vec3 &v = particles.velocity[k], &w = particles.angular_velocity[k];
    packed_motion_[k] = {v.x, v.y, v.z, particles.mass[k], w.x, w.y, w.z, 0.0};
  }
  std::vector<std::uint8_t> pair_touching_; // per listed pair: touched at the last evaluation
  int uniform_material_ = -1;               // the material of every particle, -1 when they differ
  std::size_t n_pair_contacts_ = 0;
  std::vector<Vec3> reference_position_;
  double wall_time_ = 0, wall_reference_time_ = 0; ///< [s] the moving walls' poses: now, rebuild

  // Wall contacts: candidates per particle (wall << 24 | face) and history slots.
  static constexpr int wall_slots = 6;
  std::vector<std::uint32_t> wall_candidate_offset_, wall_candidate_;
  // A copy of each mesh candidate's FaceBound, in candidate order: the step's rejection tests
  // read them in sequence instead of scattered over a fine wall's faces (unused for a
  // revolution wall's entry).
  std::vector<FaceBound> wall_candidate_bound_;
  std::vector<std::uint32_t> wall_particles_; // particles with at least one candidate
  // History slots of the wall contacts of near-wall particle q (in wall_particles_ order):
  // entries [wall_slots q, wall_slots q + wall_slots), valid entries first (wall >= 0).
  struct WallSlot {
    Vec3 normal, delta; ///< unit contact normal; tangential history [m]
    std::int32_t wall = -1;
  };
  std::vector<WallSlot> slots_;
  /// The buffers of the rebuild's steps (contents meaningful only within one rebuild).
  struct RebuildScratch {
    std::vector<std::size_t> thread_offset; ///< of each thread's carried histories
    std::vector<CarriedHistory> old_histories;
    HistoryTable old_by_id;
    std::vector<std::uint32_t> bucket_fill;
    std::vector<std::int32_t> slots_of_id;
    std::vector<signed char> wrap, body_wrap;
    std::vector<std::uint32_t> n_candidates;
    std::vector<std::vector<std::uint32_t>> chunk_candidates; ///< per chunk of particles
    std::vector<WallSlot> slots;
    std::vector<std::uint8_t> pair_touch; ///< per listed pair
    // sort_spatially(): cell keys, the permutation, a gathered copy of one array at a time
    std::vector<std::uint64_t> sort_key;
    std::vector<std::uint32_t> sort_perm;
    std::vector<Vec3> gather_vec3;
    std::vector<double> gather_double;
    std::vector<int> gather_int;
    std::vector<std::int64_t> gather_id;
    std::vector<std::int64_t> clump_slot_of_id; ///< Clumps::index_members' table
    std::vector<std::uint8_t> body_kept;        ///< per body: not taken by an outlet
    std::size_t bytes() const;                  ///< [B] the storage held
  };
  RebuildScratch rebuild_scratch_;
  /// The history of the untaken old slot (of a near-wall particle) of this wall whose normal
  /// is closest to `normal` (within about 25 degrees), which it marks taken; zero if none.
  /// `carried`: whether one was found (false: the contact begins, an impact).
  static Vec3 carried_wall_history(const WallSlot* old, bool* taken, std::uint32_t wall,
                                   const Vec3& normal, bool& carried);
  // Per thread, per wearing wall: n_wear_values doubles per face + totals.
  std::vector<std::vector<std::vector<double>>> wear_acc_;

  PhaseTimes phase_times_;
  std::vector<double> thread_pair_seconds_, thread_wall_seconds_; // of the last evaluation

  /// What a step's check found wrong with a particle (error_kind_).
  enum ErrorKind { no_error = 0, not_finite = 1, too_fast = 2, outside = 3, too_many_walls = 4 };
  // First problem seen inside a parallel loop (smallest particle index wins).
  std::vector<long> error_particle_;
  std::vector<int> error_kind_;
};

} // namespace wear::dem

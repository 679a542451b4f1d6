#pragma once
// The user's own equipment as a scene: the Scene subsection of a case file. Each wall named
// in `Scene/Walls` has a subsection `Wall <name>`: where its surface comes from (a CAD or mesh
// file with its length unit, or a primitive), its material, whether it wears and how it
// moves; beside them the fill, inlets, outlets, flux planes, binned fields, periodic
// boundaries, the stages of the wear loop and the cuts over MPI ranks. scene_walls.h builds
// and checks the surfaces (`wearsim scene`), scene_run.h runs the scene's DEM.
#include "dem/engine/filling.h"
#include "dem/engine/mesh_wall.h"
#include "dem/engine/rigid_motion.h"
#include "dem/scene/wall_catalogue.h"
#include "meshes/parameter_visitor.h"
#include "meshes/vec3.h"

#include <optional>
#include <string>
#include <vector>

namespace wear::dem {

struct SceneWallParameters {
  std::string name;            ///< from Scene/Walls
  std::string source = "file"; ///< file | plane | disc | cylinder | cone | box | sample | holder
  std::string file;            ///< STEP, IGES, BREP or STL (source = file)
  std::string unit = "m";      ///< m | mm, the file's length unit
  double mesh_size = 5e-3;     ///< [m] triangle size for CAD files and primitives
  std::vector<double> origin{0, 0, 0}; ///< [m] plane corner, disc centre, base centre, box corner
  std::vector<double> edge_u{1, 0, 0}; ///< [m] plane: first edge
  std::vector<double> edge_v{0, 1, 0}; ///< [m] plane: second edge
  std::vector<double> axis{0, 0, 1};   ///< [m] disc normal; cylinder/cone axis; box size
  double radius = 0;                   ///< [m] disc, cylinder; cone base
  double radius_top = 0;               ///< [m] cone top
  double radius_inner = 0;             ///< [m] disc: central hole (an annulus)
  bool caps = false;                   ///< cylinder, cone: with end discs
  bool exact =
      true; ///< a disc, open cylinder or open cone that can be an exact surface of revolution is
  std::string material = "wall";        ///< wall | sample | holder (the DEM subsection's)
  bool wears = false;                   ///< its faces accumulate wear (a closed solid)
  std::string wearing_surfaces = "all"; ///< a wearing wall's surfaces that wear: numbers or all
  std::string clamped_surfaces;         ///< a wearing wall's surfaces held fixed in the FEM
  std::string held_surfaces;    ///< a wearing wall's surfaces held on their sides in the FEM
  std::string motion = "fixed"; ///< fixed | rotation | translation | oscillation
  std::vector<double> axis_point{0, 0, 0};    ///< [m] rotation
  std::vector<double> rotation_axis{0, 0, 1}; ///< [-] rotation, right-handed
  double angular_velocity = 0;                ///< [rad/s] rotation
  std::vector<double> velocity{0, 0, 0};      ///< [m/s] translation
  std::vector<double> amplitude{0, 0, 0};     ///< [m] oscillation: A sin(2 pi f (t - t0))
  double frequency = 0;                       ///< [Hz] oscillation
  double start_time = 0;                      ///< [s] t0: the wall rests before it
  double end_time = 0;                        ///< [s] t1: and after it; 0: never stops
};

/// A rectangle that feeds particles at a mass flow rate (inlet.h).
struct SceneInletParameters {
  std::string name;                       ///< from Scene/Inlets
  std::vector<double> corner{0, 0, 0};    ///< [m]
  std::vector<double> edge_u{0.1, 0, 0};  ///< [m]
  std::vector<double> edge_v{0, 0.1, 0};  ///< [m]
  double mass_flow = 0;                   ///< [kg/s]
  std::vector<double> velocity{0, 0, -1}; ///< [m/s]
  double start_time = 0;                  ///< [s]
  double end_time = 0;                    ///< [s]; 0: to the end of the run
};

/// An axis-aligned box that removes the particles reaching it (outlet.h).
struct SceneOutletParameters {
  std::string name;                     ///< from Scene/Outlets
  std::vector<double> minimum{0, 0, 0}; ///< [m]
  std::vector<double> maximum{0, 0, 0}; ///< [m]
};

/// A plane through which the run counts the net mass (flux_plane.h).
struct SceneFluxPlaneParameters {
  std::string name;                     ///< from Scene/Flux planes
  std::vector<double> point{0, 0, 0};   ///< [m]
  std::vector<double> normal{0, 0, -1}; ///< [-] forward
};

/// Particles in place at the start: none, or a box filled at random to a count, or to a
/// bed height after settling.
struct SceneFillParameters {
  std::string region = "none";          ///< none | box | cylinder | mesh
  std::vector<double> minimum{0, 0, 0}; ///< [m] the box
  std::vector<double> maximum{0, 0, 0}; ///< [m]
  std::vector<double> origin{0, 0, 0};  ///< [m] the cylinder's base centre
  std::vector<double> axis{0, 0, 1};    ///< [m] the cylinder's axis, base to top
  double radius = 0;                    ///< [m] the cylinder's radius
  double radius_inner = 0;              ///< [m] the cylinder's hole (an annulus; 0: none)
  std::string file;                     ///< a closed mesh or CAD solid (Region = mesh)
  std::string unit = "m";               ///< m | mm, the file's length unit
  double mesh_size = 5e-3;              ///< [m] triangles of a CAD file
  std::uint64_t count = 0;              ///< particles; 0: fill to Bed height
  double bed_height = 0;                ///< [m] above the box's floor, settled
  std::string clear_above;              ///< walls in the region with no particle placed above
};

/// The wear tester's evaluation of a scene's sample (Source = sample), one record per period
/// (dem/scene/scene_evaluation.h): wear per column and element, normal force, bottom-layer
/// speed and spin, bed height, steady state.
struct SceneEvaluationParameters {
  std::string wall;              ///< the evaluated wall's name; empty: no evaluation
  double period = 0;             ///< [s] of one record (a revolution of the tester)
  double steady_threshold = 0.1; ///< [-] coefficient of variation below which a period is steady
  int steady_periods = 2;        ///< consecutive steady periods that judge the run steady
  /// the run stops this many periods after the first steady one (0: runs every stage)
  int periods_after_steady = 0;
};

/// A grid of boxes on which the run bins the particles' solid fraction and velocity.
struct SceneFieldParameters {
  std::vector<int> cells{0, 0, 0};      ///< nx, ny, nz; 0: no fields
  std::vector<double> minimum{0, 0, 0}; ///< [m]
  std::vector<double> maximum{0, 0, 0}; ///< [m]
};

struct SceneParameters {
  std::string wall_names;                     ///< "Walls": comma-separated names, "" for none
  std::vector<SceneWallParameters> walls;     ///< one per name, in that order
  std::string inlet_names;                    ///< "Inlets"
  std::vector<SceneInletParameters> inlets;   ///< one per name, in that order
  std::string outlet_names;                   ///< "Outlets"
  std::vector<SceneOutletParameters> outlets; ///< one per name, in that order
  std::string flux_plane_names;               ///< "Flux planes"
  std::vector<SceneFluxPlaneParameters> flux_planes; ///< one per name, in that order
  SceneFillParameters fill;
  SceneFieldParameters fields;
  SceneEvaluationParameters evaluation;
  std::vector<double> domain_min{-10, -10, -10}; ///< [m] particles and walls stay inside
  std::vector<double> domain_max{10, 10, 10};    ///< [m]
  std::vector<double> gravity{0, 0, -9.81};      ///< [m/s^2]
  double end_time = 1;                           ///< [s] simulated
  double output_interval = 0.05;                 ///< [s] between records
  bool particle_snapshots = true;                ///< particles_<k>.vtu at every record
  /// otherwise particles_<k>.vtu at these records k (counted from 1 after the fill settled)
  std::vector<int> snapshot_records;
  /// [s] DEM time of a stage of the wear loop (Coupling/Schedule) when a wall wears; 0: no
  /// stages, the scene runs to End time
  double stage_duration = 0;
  /// [deg] the scene is the sector 0 <= theta < angle about the z axis, periodic (0: none)
  double periodic_angle_deg = 0;
  /// the scene is periodic along this axis between periodic_from and periodic_to (none: not)
  std::string periodic_direction = "none"; ///< none | x | y | z
  double periodic_from = 0;                ///< [m]
  double periodic_to = 0;                  ///< [m]
  /// Over MPI ranks: one slab per rank along this coordinate (angle: about the z axis; auto:
  /// the period's, or x)
  std::string rank_slabs_along = "auto"; ///< auto | x | y | z | angle
  /// balanced: equal particle counts when the engine sets up; uniform: equal widths
  std::string rank_slabs = "balanced";
  /// [-] Over MPI ranks: cut anew when the largest rank's particles exceed the mean by this
  /// factor (0: never)
  double rank_rebalance = 1.25;
};

/// The names a case file gives to its scene's walls, inlets and outlets: they decide which
/// subsections exist (the case reader reads them first).
struct SceneNames {
  std::string walls, inlets, outlets, flux_planes;
};

/// Default parameters with one entry per name, so that their subsections are declared.
SceneParameters scene_with_names(const SceneNames& names);

/// The names listed in `text` ("a, b, c"); throws std::invalid_argument naming the parameter
/// `what` (e.g. Scene/Walls) for an empty or repeated name or one with characters other than
/// letters, digits, '_' and '-'.
std::vector<std::string> scene_names(const std::string& text, const std::string& what);

/// The Scene subsection. `s.walls`, `s.inlets` and `s.outlets` must already hold one entry
/// per name of the file (scene_with_names), so each one's subsection is declared and read.
template <typename Visitor>
void visit_parameters(SceneParameters& s, Visitor& v) {
  v.enter("Scene");
  v.text("Walls", s.wall_names,
         "Names of the scene's walls, comma-separated; each has a subsection 'Wall <name>'. "
         "Empty: a wear-tester case, whose scene is written from its Geometry and DEM "
         "subsections (`wearsim tester-scene` prints it).");
  v.text("Inlets", s.inlet_names,
         "Names of the particle inlets, comma-separated; each has a subsection 'Inlet <name>'.");
  v.text("Outlets", s.outlet_names,
         "Names of the outlets, comma-separated; each has a subsection 'Outlet <name>'.");
  v.text("Flux planes", s.flux_plane_names,
         "Names of planes through which the run counts the net mass, comma-separated; each "
         "has a subsection 'Flux plane <name>'.");
  v.real_list("Domain minimum", s.domain_min,
              "[m] x, y, z of the domain's lower corner: every wall vertex lies inside, and a "
              "particle that leaves the domain stops the run (put an outlet where they go).");
  v.real_list("Domain maximum", s.domain_max, "[m] x, y, z of the domain's upper corner.");
  v.real_list("Gravity", s.gravity, "[m/s^2] Gravitational acceleration vector.");
  v.real("End time", s.end_time, "[s] Simulated time of `wearsim scene-run`.");
  v.real("Output interval", s.output_interval,
         "[s] Simulated time between records of the run's series (and progress lines).");
  v.boolean("Particle snapshots", s.particle_snapshots,
            "Write the particles at every record (particles_<k>.vtu: position, velocity, "
            "radius, ...; for clumps each member's body, its orientation and centre); false: "
            "the tables and walls only (a long run's disk, or a timing), and the particles at "
            "the Snapshot records.");
  v.int_list("Snapshot records", s.snapshot_records,
             "With Particle snapshots = false, the particles are written at these records "
             "(particles_<k>.vtu; record k ends k Output intervals after the fill has "
             "settled): a few pictures of a long run. Empty: none.");
  v.real("Periodic sector", s.periodic_angle_deg,
         "[deg] The scene is the sector 0 <= theta < angle about the z axis through the "
         "origin, its two planes joined periodically (a particle leaving one enters through "
         "the other, rotated); 0: no periodic boundary. Walls may move only by surface "
         "motions then; the fill and the inlets must lie inside the sector.");
  v.selection("Periodic direction", s.periodic_direction, "none|x|y|z",
              "A planar periodic boundary: the scene is the slab Periodic from <= coordinate < "
              "Periodic to along this axis, its two planes joined (a particle leaving one enters "
              "through the other, shifted by the period; a slice of a wide chute or an endless "
              "belt). One axis; excludes Periodic sector. Walls may move only by surface motions "
              "then, and should reach past both planes by a few particle diameters; the fill "
              "and the inlets must lie inside the slab.");
  v.real("Periodic from", s.periodic_from, "[m] The slab's lower plane.");
  v.real("Periodic to", s.periodic_to, "[m] The slab's upper plane.");
  v.selection("Rank slabs along", s.rank_slabs_along, "auto|x|y|z|angle",
              "Under `mpirun -np N wearsim scene-run`, the scene is cut into N slabs, one per "
              "rank, along this coordinate (angle: about the z axis through the origin, round "
              "the full circle or across Periodic sector). A periodic scene is cut along its "
              "period: Periodic direction's axis, or angle for a sector; auto takes that, or x "
              "for a scene without a period. Each slab must be at least two largest particle "
              "diameters wide. One process: no effect.");
  v.selection("Rank slabs", s.rank_slabs, "balanced|uniform",
              "Where the slabs' cuts lie: balanced, so that each rank holds as many particles "
              "when the engine sets up (the fill, or the first inlet batch); uniform, equal "
              "widths of the domain (Domain minimum to maximum along the axis; the sector or "
              "the full circle for angle). The cuts then stay for the run and its resumes on as "
              "many ranks.");
  v.real("Rank rebalance", s.rank_rebalance,
         "[-] Over MPI ranks: when, at the end of a record's window, the rank holding the most "
         "particles holds more than this factor times the mean, the bed is cut anew into "
         "balanced slabs (as a resume on another rank count: the run goes on from a rebuild; "
         "the same inputs rebalance at the same moments, so a run stays reproducible). 0: "
         "never; otherwise above 1.");
  v.real("Stage duration", s.stage_duration,
         "[s] Simulated DEM time of each stage of the wear loop when a wall wears (the FEM "
         "part): the stages and their schemes are Coupling/Schedule's (staged, dem-only), "
         "End time is then their sum. 0: no stages; the scene runs to End time and only "
         "accumulates wear.");
  v.enter("Fill");
  v.selection("Region", s.fill.region, "none|box|cylinder|mesh",
              "Particles in place at the start: none, or random in an axis-aligned box, a "
              "cylinder, or the solid a closed mesh or CAD file encloses (the DEM subsection's "
              "size distribution and particle material). The region may not cut or touch a "
              "wall; a wall wholly inside it stands submerged in the fill (a part in a bed): "
              "no particle is placed inside it or within a largest diameter of its surface "
              "(of its bounding box when the wall is not a closed surface), and a bed "
              "height's count leaves out its volume.");
  v.text("File", s.fill.file,
         "Region = mesh: a closed STL, or a STEP, IGES or BREP solid, relative to the working "
         "directory (filled to a Count only).");
  v.selection("Unit", s.fill.unit, "m|mm", "Length unit of the file's coordinates.");
  v.real("Mesh size", s.fill.mesh_size, "[m] Triangle size for a CAD file.");
  v.real_list("Minimum", s.fill.minimum, "[m] The box's lower corner.");
  v.real_list("Maximum", s.fill.maximum, "[m] The box's upper corner.");
  v.real_list("Origin", s.fill.origin, "[m] The cylinder's base centre.");
  v.real_list("Axis", s.fill.axis,
              "[m] The cylinder's axis from its base to its top (along +z for a Bed height).");
  v.real("Radius", s.fill.radius, "[m] The cylinder's radius.");
  v.real("Inner radius", s.fill.radius_inner,
         "[m] A coaxial hole in the cylinder (an annulus, e.g. a trough between two walls); 0: "
         "none. In a periodic sector, a cylinder about the z axis is filled only within the "
         "sector.");
  v.count("Count", s.fill.count,
          "Particles to place; 0: as many as settle to Bed height above the region's floor.");
  v.real("Bed height", s.fill.bed_height,
         "[m] Settled bed height above the region's floor (the box's bottom, the cylinder's "
         "base) when Count is 0: the count is that of a bed of the DEM subsection's Assumed "
         "packing over the region's footprint, placed loosely above and settled under gravity "
         "before the run starts. A bed that spreads wider than the region (a container larger "
         "than it) settles lower.");
  v.text("Clear above", s.fill.clear_above,
         "Walls standing in the region (names, comma-separated) above which no particle is "
         "placed: a plate submerged in the bed, such as a leveller, would otherwise carry "
         "the particles dropped on it through the run. The column over the wall's bounding "
         "box, widened by a largest diameter, stays empty while the bed is placed.");
  v.leave();
  v.enter("Evaluation");
  v.text("Wall", s.evaluation.wall,
         "The wear tester's evaluation of this wall, the scene's sample (Source = sample, Wears = "
         "true): per Period, the wear-law volume per column of the pattern and per convex "
         "element, the normal force on the wear face, the bottom layer's speed and spin, the "
         "speed over the sample, the bed height and the coefficients of variation that judge "
         "steady state, as per revolution of the wear tester (docs/wear-tester.md); written "
         "to parts/<wall>/summary.csv and history.h5, which `wearsim compare --part <wall>` "
         "reads. Its samples are the records (Output interval). Empty: none.");
  v.real("Period", s.evaluation.period,
         "[s] Simulated time of one evaluation record (the tester's revolution): a whole "
         "number of Output intervals, at least two, and Stage duration a whole number of "
         "periods.");
  v.real("Steady threshold", s.evaluation.steady_threshold,
         "[-] Coefficient of variation (over a period's samples) of the speed over the "
         "sample, the bed height and the wear rate below which a period counts as steady.");
  v.integer("Steady periods", s.evaluation.steady_periods, 1, 1000,
            "Consecutive steady periods that judge the run steady.");
  v.integer("Periods after steady", s.evaluation.periods_after_steady, 0, 100000,
            "The run stops after the stage holding the period this many periods after the "
            "first steady one (0: runs every stage of Coupling/Schedule, which stay the "
            "maximum).");
  v.leave();
  v.enter("Fields");
  v.int_list("Cells", s.fields.cells,
             "Cells of the grid the run bins the particles on, nx, ny, nz (0, 0, 0: none): per "
             "record the window's mean solid fraction and mass-weighted velocity per cell "
             "(fields.xdmf); each particle counts in the cell of its centre, so make cells "
             "several particle diameters wide.");
  v.real_list("Minimum", s.fields.minimum, "[m] The grid's lower corner.");
  v.real_list("Maximum", s.fields.maximum, "[m] The grid's upper corner.");
  v.leave();
  for (auto& in : s.inlets) {
    v.enter("Inlet " + in.name);
    v.real_list("Corner", in.corner, "[m] A corner of the inlet rectangle.");
    v.real_list("Edge u", in.edge_u, "[m] The rectangle's first edge from Corner.");
    v.real_list("Edge v", in.edge_v, "[m] The rectangle's second edge from Corner.");
    v.real("Mass flow rate", in.mass_flow,
           "[kg/s] Particle mass fed per second; particles appear in the box behind the "
           "rectangle (upstream, two largest diameters deep), clear of each other.");
    v.real_list("Velocity", in.velocity,
                "[m/s] Velocity of each new particle; must cross the rectangle.");
    v.real("Start time", in.start_time, "[s] When the feed starts.");
    v.real("End time", in.end_time, "[s] When it stops; 0: at the end of the run.");
    v.leave();
  }
  for (auto& f : s.flux_planes) {
    v.enter("Flux plane " + f.name);
    v.real_list("Point", f.point, "[m] A point of the plane.");
    v.real_list("Normal", f.normal,
                "[-] The plane's normal: particles crossing along it count +, against it -.");
    v.leave();
  }
  for (auto& out : s.outlets) {
    v.enter("Outlet " + out.name);
    v.real_list("Minimum", out.minimum, "[m] The outlet box's lower corner.");
    v.real_list("Maximum", out.maximum,
                "[m] Its upper corner: particles whose centres enter the box leave the run "
                "and their mass is booked to the outlet.");
    v.leave();
  }
  for (auto& w : s.walls) {
    v.enter("Wall " + w.name);
    v.selection("Source", w.source, wall_source_names(),
                "Where the surface comes from: " + wall_source_descriptions() + ".");
    v.text("File", w.file,
           "STEP (.step, .stp), IGES (.iges, .igs), BREP (.brep) or STL (.stl), relative to "
           "the working directory (Source = file). CAD surfaces become labels 1, 2, ... in the "
           "file's order (`wearsim scene` lists them); STL labels as stored.");
    v.selection("Unit", w.unit, "m|mm", "Length unit of the file's coordinates.");
    v.real("Mesh size", w.mesh_size, "[m] Triangle size for CAD files and primitives.");
    v.real_list("Origin", w.origin,
                "[m] Plane: a corner; disc: its centre; cylinder, cone: the base centre; box: "
                "the lower corner.");
    v.real_list("Edge u", w.edge_u, "[m] Plane: the first edge from the corner.");
    v.real_list("Edge v", w.edge_v, "[m] Plane: the second edge from the corner.");
    v.real_list("Axis", w.axis,
                "[m] Disc: the normal (any length); cylinder, cone: base to top; box: its size.");
    v.real("Radius", w.radius, "[m] Disc, cylinder; the cone's base.");
    v.real("Top radius", w.radius_top, "[m] The cone's top (0: pointed).");
    v.real("Inner radius", w.radius_inner,
           "[m] Disc: a central hole of this radius (an annulus, e.g. a hopper's flat floor "
           "around its orifice); 0: none.");
    v.boolean("Caps", w.caps, "Cylinder, cone: with the end discs (a closed solid).");
    v.boolean(
        "Exact surface", w.exact,
        "A disc (an annulus with Inner radius), a cylinder or a cone without Caps that does not "
        "wear and does not move as a rigid body (Motion fixed or a surface motion) is an "
        "exact surface of revolution in the DEM: contacts with the surface itself, not "
        "with its triangles, so a round orifice's rim is a circle and a drum's wall is "
        "smooth; its triangles at Mesh size then only collect its loads (force, moment, "
        "Archard load-distance per face). false: the triangles are the wall. Other walls "
        "are triangles whatever this says.");
    v.selection("Material", w.material, "wall|sample|holder",
                "The DEM material of the wall: one of the DEM subsection's Wall, Sample and "
                "Holder materials.");
    v.boolean("Wears", w.wears,
              "The wall is the wearing part: a closed solid whose wearing surfaces accumulate "
              "wear and, with Scene/Stage duration, recede stage by stage while the FEM "
              "computes its stress (clamped at Clamped surfaces). Its CAD surfaces keep their "
              "numbers n as labels S<n> (wearing), S<n>-free, S<n>-clamped and S<n>-held.");
    v.text("Wearing surfaces", w.wearing_surfaces,
           "A wearing wall's surfaces that wear, by number (`wearsim scene` lists them), "
           "comma-separated, or 'all' for every surface neither clamped nor held; the others "
           "are free (traction from particles, no wear).");
    v.text("Clamped surfaces", w.clamped_surfaces,
           "A wearing wall's surfaces held fixed in the FEM (zero displacement: bolted to "
           "the structure), by number, comma-separated; a wear loop needs at least one.");
    v.text("Held surfaces", w.held_surfaces,
           "A wearing wall's surfaces held on their sides in the FEM (zero displacement "
           "normal to the surface, free to slide along it: a liner resting in a frame), by "
           "number, comma-separated; each must be normal to an axis of the part's frame "
           "(x, y or z) within 30 degrees. They do not wear.");
    v.selection("Motion", w.motion, wall_motion_names(),
                wall_motion_descriptions() +
                    ". A whole wall moves as a rigid body from Start time t0 on; a surface "
                    "moves from the start of the run on (a fill to a Bed height settles on "
                    "surfaces at rest), and only surface motions may be periodic.");
    v.real_list("Axis point", w.axis_point, "[m] A point of the rotation axis.");
    v.real_list("Rotation axis", w.rotation_axis, "[-] Direction of the rotation axis.");
    v.real("Angular velocity", w.angular_velocity, "[rad/s] Right-handed about Rotation axis.");
    v.real_list("Velocity", w.velocity, "[m/s] Translation velocity.");
    v.real_list("Amplitude", w.amplitude, "[m] Oscillation amplitude vector.");
    v.real("Frequency", w.frequency, "[Hz] Oscillation frequency.");
    v.real("Start time", w.start_time,
           "[s] The wall rests where its file or primitive puts it until this time, then "
           "moves (e.g. after the particles settled).");
    v.real("End time", w.end_time,
           "[s] The wall stops where the motion brought it (e.g. a gate that opened); 0: it "
           "never stops.");
    v.leave();
  }
  v.leave();
}

/// "Scene/Wall <name>": how messages name a wall's parameters.
std::string scene_wall_path(const SceneWallParameters& w);
/// The index of the wall named `name` in s.walls, or none.
std::optional<std::size_t> scene_wall_index(const SceneParameters& s, const std::string& name);
/// The three values of a checked list (x, y, z) as a vector.
meshes::Vec3 scene_vector(const std::vector<double>& v);

/// The wall's motion for the engine (dem/engine/rigid_motion.h): only the parameters of the
/// chosen Motion enter; a fixed wall gets the motion that does not move.
RigidMotion rigid_motion(const SceneWallParameters& w);

/// The surface numbers listed in `text` ("1, 4, 7"), ascending; throws
/// std::invalid_argument naming `what` for anything but numbers 1 ... 999, or a repeat.
std::vector<int> surface_numbers(const std::string& text, const std::string& what);

/// The wall's surface motion for the engine (MeshWall's WallMotion): the surface velocity of
/// a 'surface rotation' or 'surface translation', zero otherwise.
WallMotion surface_motion(const SceneWallParameters& w);
/// The axis of Scene/Periodic direction: 0, 1, 2 for x, y, z (meaningless for none).
int periodic_axis(const SceneParameters& s);
/// The coordinate a scene is cut along over ranks: Rank slabs along, auto resolved (the
/// period's axis, angle for a periodic sector, else x).
std::string rank_slab_axis(const SceneParameters& s);
/// True when the scene's slabs over ranks form a ring (the last rank's neighbour is the
/// first): angular slabs, or slabs along a periodic scene's period; else a line.
bool rank_ring(const SceneParameters& s);
/// True for the motions that move the wall's geometry (rotation, translation, oscillation).
bool moves_rigidly(const SceneWallParameters& w);

/// True when record k (from 1) writes the particles: every record with Particle snapshots, else
/// the Snapshot records.
bool snapshot_due(const SceneParameters& s, int k);

/// Checks the values on their own (list lengths, signs, a file given where needed); throws
/// std::invalid_argument naming the parameter by its case-file path.
void validate(const SceneParameters& s);

/// [-] The densest packing of equal spheres, pi / (3 sqrt 2) (Kepler's conjecture, proved by
/// Hales): spheres no smaller than d fill at most this fraction of a region.
constexpr double densest_sphere_packing = 0.74048048969306104;

/// True when the fill is a cylinder about the z axis through the origin in a periodic sector
/// (Scene/Periodic sector): it is filled in the sector only.
bool fills_sector_only(const SceneParameters& s);

/// Throws std::invalid_argument naming Scene/Fill/Count when Count exceeds the most particles
/// the fill region can hold: its volume V at the densest packing of spheres of the smallest
/// diameter d_min of `psd` (DEM/PSD diameters x Scaling factor), 0.7405 V / (pi/6 d_min^3).
/// No fill can exceed it: every particle is at least d_min across and lies wholly inside the
/// region. A box's or cylinder's volume follows from its parameters (a cylinder filled in the
/// sector only: the sector's share); a mesh region's is known once its file is read, and is
/// passed as `mesh_volume` [m^3] (while it is negative, a mesh region is not checked).
/// Nothing to check without a fill or for a fill to a Bed height.
void require_fill_count_fits(const SceneParameters& s, const SizeDistribution& psd,
                             double mesh_volume = -1);

} // namespace wear::dem

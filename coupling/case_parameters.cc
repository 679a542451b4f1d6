// Case-file parameters through deal.II's ParameterHandler.
//
// Values are in SI units (m, deg for angles as named). ParameterHandler refuses undeclared
// entries, which makes misspelled names errors; validate() in each module then checks
// physical sense and names the parameter. The resolved file is produced by declaring,
// setting every value from the structs and printing in PRM style, so it always round-trips.
#include "coupling/case_parameters.h"

#include "meshes/atomic_file.h"

#include <deal.II/base/utilities.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace wear::coupling {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

namespace {

// One table drives declaration, parsing and write-back, so the three never disagree.
template <typename Visitor>
void visit_dem(dem::TesterDemParameters& d, Visitor&& v) {
  v.enter("DEM");
  const auto material = [&](const std::string& which, dem::DemMaterial& m) {
    v.real(which + " shear modulus", m.shear_modulus,
           "[Pa] Shear modulus of the " + which + " in the contact law (DEM stiffness).");
    v.real(which + " Poisson ratio", m.poisson_ratio, "[-] Poisson ratio of the " + which + ".");
    v.real(which + " density", m.density, "[kg/m^3] Solid density of the " + which + ".");
  };
  material("Particle", d.particle);
  material("Sample", d.sample);
  material("Wall", d.walls);
  const auto pair = [&](const std::string& which, dem::PairProperties& p) {
    v.real("Restitution " + which, p.restitution,
           "[-] Normal coefficient of restitution, " + which + ".");
    v.real("Friction " + which, p.friction, "[-] Static friction coefficient, " + which + ".");
    v.real("Rolling friction " + which, p.rolling_friction,
           "[-] Rolling friction coefficient (constant directional torque), " + which + ".");
  };
  pair("particle-particle", d.particle_particle);
  pair("particle-wall", d.particle_wall);
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
  v.leave();
}

template <typename Visitor>
void visit(CaseParameters& c, Visitor&& v) {
  auto& g = c.geometry;
  auto& o = c.output;
  auto& s = g.sample;
  auto& p = s.pattern;
  v.enter("Geometry");
  {
    v.enter("Sample");
    v.choice("Type", s.convex, "convex", "plain",
             "Sample kind: 'convex' (half-ellipsoid pattern on the base) or 'plain' (base only).");
    v.real("Length", s.length, "[m] Base length along the flow direction.");
    v.real("Width", s.width, "[m] Base width in the radial direction.");
    v.real("Thickness", s.thickness, "[m] Base plate thickness; its bottom face is clamped.");
    v.real("Mesh size", s.mesh_size,
           "[m] Target element size on the wear face (base top and elements); 0.25e-3 to 2e-3.");
    v.real("Mesh size bottom", s.mesh_size_bottom,
           "[m] Element size at the clamped bottom face; the size grows linearly towards it.");
    v.boolean("Volume mesh", s.volume_mesh,
              "Generate the tetrahedral volume mesh (false: surface mesh only).");
    v.boolean("Curvature refinement", s.curvature_refinement,
              "Refine the surface mesh where the element surfaces are strongly curved.");
    {
      v.enter("Pattern");
      v.real("a", p.a, "[m] Semi-axis of the elliptical footprint along 'Orientation'.");
      v.real("b", p.b, "[m] Other semi-axis of the footprint.");
      v.real("c", p.c, "[m] Radial spacing of elements within a column.");
      v.real("d", p.d, "[m] Spacing of columns of the same kind; column pitch is d/2.");
      v.real("h", p.h, "[m] Element height above the base.");
      v.integer("Number of columns", p.n_columns, 1, 9,
                "Columns along the flow; column 1 meets the flow first.");
      v.integer("Elements per column", p.elements_per_column, 1, 9,
                "Elements in odd columns (even columns hold one less when staggered).");
      v.boolean("Stagger", p.stagger, "Offset even columns radially by c/2.");
      v.choice("Orientation", p.major_along_flow, "flow", "radial",
               "Direction of the semi-axis a: along the flow or radial.");
      v.real("First column offset", p.first_column_offset,
             "[m] Distance from the leading edge to the centre of column 1.");
      v.leave();
    }
    v.leave();
    v.enter("Placement");
    auto& pl = g.placement;
    v.real("Radius", pl.radius, "[m] Radius of the sample centre in the tester.");
    v.real("Angle", pl.angle_deg, "[deg] Polar angle of the sample centre within the sector.");
    v.real("Wear face height", pl.wear_face_height,
           "[m] Height of the base top face centre above the floor.");
    v.real("Incline", pl.incline_deg,
           "[deg] Incline along the flow; positive: leading (upstream) edge lower.");
    v.leave();
    v.enter("Tester");
    auto& t = g.tester;
    v.real("Inner radius", t.inner_radius, "[m] Inner cylindrical wall.");
    v.real("Outer radius", t.outer_radius, "[m] Outer cylindrical wall.");
    v.real("Sector angle", t.sector_angle_deg, "[deg] Periodic sector simulated.");
    v.real("Wall height", t.wall_height, "[m] Height of the cylindrical walls.");
    v.real("Wall mesh size", t.wall_mesh_size, "[m] Edge length of wall triangles.");
    v.boolean("Consolidator", t.consolidator, "Include the leveller plate.");
    v.real("Consolidator height", t.consolidator_height, "[m] Plate height above the floor.");
    v.real("Consolidator angle", t.consolidator_angle_deg,
           "[deg] Polar angle of the plate centre.");
    v.real("Consolidator extent", t.consolidator_extent_deg, "[deg] Angular extent of the plate.");
    v.leave();
  }
  v.leave();
  visit_dem(c.dem, v);
  v.enter("Wear law");
  {
    std::string doc = "Wear law by name:";
    std::string names;
    for (const auto& l : dem::wear_law_catalogue()) {
      doc += "\n  " + l.name + ": " + l.description;
      names += (names.empty() ? "" : "|") + l.name;
    }
    v.selection("Model", c.wear_law.model, names, doc);
    v.real("Archard coefficient", c.wear_law.archard_coefficient,
           "[1/Pa] alpha = k/H of the Archard law.");
    v.real("Work coefficient", c.wear_law.work_coefficient,
           "[m^3/J] Volume removed per frictional work (frictional-work law).");
  }
  v.leave();
  v.enter("Deformation");
  v.boolean("Reference method", c.deformation.enabled,
            "Move the sample's surface nodes inside the DEM by the local wear depth (the "
            "reference study's method); valid until the surface distorts.");
  v.count("Update interval", c.deformation.update_interval,
          "[steps] Node moves happen every this many DEM steps.");
  v.real("Amplification", c.deformation.amplification,
         "[-] Declared factor on the removed volume applied to the nodes (1: physical).");
  v.leave();
  v.enter("Coupling");
  {
    auto& k = c.coupling;
    v.text("Schedule", k.schedule,
           "Stages of `wearsim run`, in order, as 'N scheme' items separated by commas, e.g. "
           "'6 dem-only, 10 staged'. Schemes: 'staged' (DEM on the current surface, wear per "
           "face, FEM stress under the stage-averaged face loads, recession, mesh motion or "
           "remeshing, the new surface back to the DEM with the bed kept); 'reference' (the "
           "node-moving method inside the DEM, no FEM: shows where a fixed mesh distorts; runs "
           "alone); 'dem-only' (no geometry change: settling, steady state).");
    v.integer("Revolutions per stage", k.revolutions_per_stage, 1, 100000,
              "DEM revolutions per stage (one revolution = one pass through the sector).");
    v.real("Amplification", k.amplification,
           "[-] Declared wear-amplification factor on the removed volume of every stage (1: "
           "physical); recorded in every output. In `wearsim run` it also replaces "
           "Deformation/Amplification for the reference scheme.");
    v.real("Maximum depth fraction", k.max_depth_fraction,
           "[-] Largest recession one stage may ask at a surface vertex (removed volume over "
           "area of the wear faces around it), as a fraction of the longest edge there; a "
           "stage asking for more stops the run (lower the amplification or the revolutions "
           "per stage), or, with Adaptive amplification, runs at a lower amplification.");
    v.boolean("Adaptive amplification", k.adaptive_amplification,
              "A staged stage that would ask more than Maximum depth fraction at a vertex "
              "runs at the amplification that brings that vertex to the cap, A_stage = A x "
              "cap / fraction, instead of stopping the run (the step control of wear "
              "simulations: the wear of a step extrapolated only as far as the geometry "
              "allows). Each stage's amplification is recorded (stages.csv, summary.csv) and "
              "the equivalent test time follows it.");
    v.real("Minimum amplification", k.min_amplification,
           "[-] With Adaptive amplification, a stage that would need less than this stops the "
           "run as without it.");
    v.real("Push tolerance", k.push_tolerance,
           "[-] After a geometry update, particles the new surface overlaps by more than this "
           "fraction of their radius are pushed out to zero overlap (and counted).");
    v.boolean("Checkpoints", k.checkpoints,
              "Write checkpoint.h5 after every stage (atomically) so `wearsim run --resume` "
              "can continue a killed run bit for bit. Not for the reference scheme.");
    v.enter("Stress-informed wear");
    auto& si = k.stress_informed;
    v.boolean("Enabled", si.enabled,
              "Hypothesis to test, off by default: scale the wear coefficient per face by "
              "1 + Sensitivity (sigma_vM / Reference stress)^Exponent, sigma_vM the von Mises "
              "stress of the face's cell in the previous stage.");
    v.real("Sensitivity", si.sensitivity, "[-] Scale of the stress term.");
    v.real("Reference stress", si.reference_stress,
           "[Pa] Stress that doubles the coefficient "
           "at Sensitivity 1.");
    v.real("Exponent", si.exponent, "[-] Exponent of the stress ratio.");
    v.leave();
  }
  v.leave();
  v.enter("FEM");
  {
    auto& f = c.fem;
    auto& e = f.elasticity;
    v.real("Youngs modulus", e.youngs_modulus, "[Pa] Sample material (PE1000: 700 MPa).");
    v.real("Poisson ratio", e.poisson_ratio, "[-] Sample material (PE1000: 0.40).");
    v.real("Yield stress", e.yield_stress, "[Pa] For the safety factor (PE1000: about 20 MPa).");
    v.unsigned_integer("Degree", e.degree, 1, 2, "Polynomial degree of the simplex elements.");
    v.real("Solver tolerance", e.relative_tolerance, "[-] Relative residual of the AMG-CG solve.");
    v.real("Remesh scaled Jacobian", f.remesh_min_scaled_jacobian,
           "[-] Remesh when mesh motion leaves a cell below this scaled Jacobian (or inverted).");
    v.real("Feature angle", f.feature_angle_deg,
           "[deg] Edges sharper than this are kept as edges when remeshing the worn surface.");
    v.real("Chord tolerance", f.chord_tolerance,
           "[m] Largest gap between the remeshed and the worn surface the size field aims at.");
    v.real("Remesh tetrahedron quality", f.remesh_min_tet_quality,
           "[-] A remesh attempt that leaves a tetrahedron of lower quality (6 sqrt(2) |V| / "
           "l_max^3, 1 for a regular one) is refused and the next attempt tried; the last one, "
           "which keeps the worn surface triangles, refuses only flat tetrahedra.");
    v.real("Worn-through thickness", f.worn_through_thickness,
           "[m] A wear face with a vertex closer than this to the sample's clamped bottom is worn "
           "through: no material is left there, so the wear asked of it is recorded "
           "(stages.csv: worn_through_volume_m3) and not removed.");
  }
  v.leave();
  v.enter("Output");
  v.text("Directory", o.directory, "Results folder; created if missing.");
  v.leave();
}

std::string to_text(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

template <typename T>
std::string join(const std::vector<T>& x) {
  std::string s;
  for (const auto& v : x) {
    if constexpr (std::is_floating_point_v<T>)
      s += (s.empty() ? "" : ", ") + to_text(v);
    else
      s += (s.empty() ? "" : ", ") + std::to_string(v);
  }
  return s;
}

struct Declare {
  ParameterHandler& prm;
  void enter(const std::string& s) { prm.enter_subsection(s); }
  void leave() { prm.leave_subsection(); }
  void real(const std::string& n, double& x, const std::string& doc) {
    prm.declare_entry(n, to_text(x), Patterns::Double(), doc);
  }
  void integer(const std::string& n, int& x, int lo, int hi, const std::string& doc) {
    prm.declare_entry(n, std::to_string(x), Patterns::Integer(lo, hi), doc);
  }
  void unsigned_integer(const std::string& n, unsigned int& x, int lo, int hi,
                        const std::string& doc) {
    prm.declare_entry(n, std::to_string(x), Patterns::Integer(lo, hi), doc);
  }
  void boolean(const std::string& n, bool& x, const std::string& doc) {
    prm.declare_entry(n, x ? "true" : "false", Patterns::Bool(), doc);
  }
  void choice(const std::string& n, bool& x, const std::string& yes, const std::string& no,
              const std::string& doc) {
    prm.declare_entry(n, x ? yes : no, Patterns::Selection(yes + "|" + no), doc);
  }
  void text(const std::string& n, std::string& x, const std::string& doc) {
    prm.declare_entry(n, x, Patterns::Anything(), doc);
  }
  void selection(const std::string& n, std::string& x, const std::string& options,
                 const std::string& doc) {
    prm.declare_entry(n, x, Patterns::Selection(options), doc);
  }
  void count(const std::string& n, std::uint64_t& x, const std::string& doc) {
    prm.declare_entry(n, std::to_string(x), Patterns::Integer(0), doc);
  }
  void real_list(const std::string& n, std::vector<double>& x, const std::string& doc) {
    prm.declare_entry(n, join(x), Patterns::List(Patterns::Double()), doc);
  }
  void int_list(const std::string& n, std::vector<int>& x, const std::string& doc) {
    prm.declare_entry(n, join(x), Patterns::List(Patterns::Integer(0)), doc);
  }
};

struct Parse {
  ParameterHandler& prm;
  void enter(const std::string& s) { prm.enter_subsection(s); }
  void leave() { prm.leave_subsection(); }
  void real(const std::string& n, double& x, const std::string&) { x = prm.get_double(n); }
  void integer(const std::string& n, int& x, int, int, const std::string&) {
    x = static_cast<int>(prm.get_integer(n));
  }
  void unsigned_integer(const std::string& n, unsigned int& x, int, int, const std::string&) {
    x = static_cast<unsigned int>(prm.get_integer(n));
  }
  void boolean(const std::string& n, bool& x, const std::string&) { x = prm.get_bool(n); }
  void choice(const std::string& n, bool& x, const std::string& yes, const std::string&,
              const std::string&) {
    x = prm.get(n) == yes;
  }
  void text(const std::string& n, std::string& x, const std::string&) { x = prm.get(n); }
  void selection(const std::string& n, std::string& x, const std::string&, const std::string&) {
    x = prm.get(n);
  }
  void count(const std::string& n, std::uint64_t& x, const std::string&) {
    x = static_cast<std::uint64_t>(prm.get_integer(n));
  }
  void real_list(const std::string& n, std::vector<double>& x, const std::string&) {
    x = dealii::Utilities::string_to_double(dealii::Utilities::split_string_list(prm.get(n)));
  }
  void int_list(const std::string& n, std::vector<int>& x, const std::string&) {
    x = dealii::Utilities::string_to_int(dealii::Utilities::split_string_list(prm.get(n)));
  }
};

struct Store {
  ParameterHandler& prm;
  void enter(const std::string& s) { prm.enter_subsection(s); }
  void leave() { prm.leave_subsection(); }
  void real(const std::string& n, double& x, const std::string&) { prm.set(n, x); }
  void integer(const std::string& n, int& x, int, int, const std::string&) {
    prm.set(n, static_cast<long int>(x));
  }
  void unsigned_integer(const std::string& n, unsigned int& x, int, int, const std::string&) {
    prm.set(n, static_cast<long int>(x));
  }
  void boolean(const std::string& n, bool& x, const std::string&) { prm.set(n, x); }
  void choice(const std::string& n, bool& x, const std::string& yes, const std::string& no,
              const std::string&) {
    prm.set(n, x ? yes : no);
  }
  void text(const std::string& n, std::string& x, const std::string&) { prm.set(n, x); }
  void selection(const std::string& n, std::string& x, const std::string&, const std::string&) {
    prm.set(n, x);
  }
  void count(const std::string& n, std::uint64_t& x, const std::string&) {
    prm.set(n, static_cast<long int>(x));
  }
  void real_list(const std::string& n, std::vector<double>& x, const std::string&) {
    prm.set(n, join(x));
  }
  void int_list(const std::string& n, std::vector<int>& x, const std::string&) {
    prm.set(n, join(x));
  }
};

// deal.II's exception text is long; keep the part that says what is wrong.
std::string short_message(const std::exception& e) {
  std::string m = e.what();
  const auto pos = m.find("Additional information:");
  if (pos != std::string::npos)
    m = m.substr(pos + 23);
  const auto end = m.find("Stacktrace:");
  if (end != std::string::npos)
    m = m.substr(0, end);
  while (!m.empty() && (m.back() == '\n' || m.back() == ' ' || m.back() == '-'))
    m.pop_back();
  while (!m.empty() && (m.front() == '\n' || m.front() == ' '))
    m.erase(0, 1);
  return m;
}

} // namespace

void declare_parameters(ParameterHandler& prm) {
  CaseParameters defaults;
  visit(defaults, Declare{prm});
}

CaseParameters read_case(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("case file '" + path + "' does not exist");
  ParameterHandler prm;
  declare_parameters(prm);
  try {
    prm.parse_input(path, "", false);
  } catch (const std::exception& e) {
    throw std::runtime_error("case file '" + path + "': " + short_message(e));
  }
  CaseParameters p;
  p.case_file = path;
  visit(p, Parse{prm});
  try {
    meshes::validate(p.geometry);
    dem::validate(p.dem);
    dem::make_wear_law(p.wear_law);
    validate(p.coupling, p.fem);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("case file '" + path + "': " + e.what());
  }
  return p;
}

std::string resolved_parameters(const CaseParameters& p) {
  ParameterHandler prm;
  declare_parameters(prm);
  CaseParameters copy = p;
  visit(copy, Store{prm});
  std::ostringstream out;
  prm.print_parameters(out, ParameterHandler::PRM);
  return out.str();
}

void write_resolved_parameters(const CaseParameters& p, const std::string& path) {
  const std::string text = resolved_parameters(p);
  meshes::write_atomically(path, [&](std::ostream& out) {
    out << "# Fully resolved parameters";
    if (!p.case_file.empty())
      out << " of " << p.case_file;
    out << "\n" << text;
  });
}

void print_parameters(std::ostream& out) {
  ParameterHandler prm;
  declare_parameters(prm);
  prm.print_parameters(out, ParameterHandler::Text);
}

} // namespace wear::coupling

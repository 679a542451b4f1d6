// Case-file parameters through deal.II's ParameterHandler.
//
// Values are in SI units (m, deg for angles as named). ParameterHandler refuses undeclared
// entries, which makes misspelled names errors; validate() in each module then checks
// physical sense and names the parameter. The resolved file is produced by declaring,
// setting every value from the structs and printing in PRM style, so it always round-trips.
#include "coupling/case_parameters.h"

#include "meshes/atomic_file.h"

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace wear::coupling {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

namespace {

// One table drives declaration, parsing and write-back, so the three never disagree.
template <typename Visitor>
void visit(meshes::GeometryParameters& g, OutputParameters& o, Visitor&& v) {
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
};

struct Parse {
  ParameterHandler& prm;
  void enter(const std::string& s) { prm.enter_subsection(s); }
  void leave() { prm.leave_subsection(); }
  void real(const std::string& n, double& x, const std::string&) { x = prm.get_double(n); }
  void integer(const std::string& n, int& x, int, int, const std::string&) {
    x = static_cast<int>(prm.get_integer(n));
  }
  void boolean(const std::string& n, bool& x, const std::string&) { x = prm.get_bool(n); }
  void choice(const std::string& n, bool& x, const std::string& yes, const std::string&,
              const std::string&) {
    x = prm.get(n) == yes;
  }
  void text(const std::string& n, std::string& x, const std::string&) { x = prm.get(n); }
};

struct Store {
  ParameterHandler& prm;
  void enter(const std::string& s) { prm.enter_subsection(s); }
  void leave() { prm.leave_subsection(); }
  void real(const std::string& n, double& x, const std::string&) { prm.set(n, x); }
  void integer(const std::string& n, int& x, int, int, const std::string&) {
    prm.set(n, static_cast<long int>(x));
  }
  void boolean(const std::string& n, bool& x, const std::string&) { prm.set(n, x); }
  void choice(const std::string& n, bool& x, const std::string& yes, const std::string& no,
              const std::string&) {
    prm.set(n, x ? yes : no);
  }
  void text(const std::string& n, std::string& x, const std::string&) { prm.set(n, x); }
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
  visit(defaults.geometry, defaults.output, Declare{prm});
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
  visit(p.geometry, p.output, Parse{prm});
  try {
    meshes::validate(p.geometry);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("case file '" + path + "': " + e.what());
  }
  return p;
}

void write_resolved_parameters(const CaseParameters& p, const std::string& path) {
  ParameterHandler prm;
  declare_parameters(prm);
  CaseParameters copy = p;
  visit(copy.geometry, copy.output, Store{prm});
  meshes::write_atomically(path, [&](std::ostream& out) {
    out << "# Fully resolved parameters";
    if (!p.case_file.empty())
      out << " of " << p.case_file;
    out << "\n";
    prm.print_parameters(out, ParameterHandler::PRM);
  });
}

void print_parameters(std::ostream& out) {
  ParameterHandler prm;
  declare_parameters(prm);
  prm.print_parameters(out, ParameterHandler::Text);
}

} // namespace wear::coupling

// Case-file parameters through deal.II's ParameterHandler.
//
// Values are in SI units (m, deg for angles as named). Before the handler reads a file,
// case_file_lines.h walks its lines for what the handler does not see: an INCLUDE loop and a
// parameter set twice in one file, and the entries set. ParameterHandler refuses undeclared
// entries, which makes misspelled names errors; an entry the case does not use (a tester's
// parameter in a scene, a scene's in the tester: case_scope.h) is refused by name; validate() in
// each module then checks physical sense and names the parameter, and check_consistency
// (case_consistency.h) the combinations that would fail later, before anything is written. The
// resolved file is produced by declaring, setting every value from the structs and printing in PRM
// style, so it always round-trips.
#include "coupling/parameters/case_parameters.h"

#include "coupling/parameters/case_consistency.h"
#include "coupling/parameters/case_file_lines.h"
#include "coupling/parameters/case_scope.h"
#include "coupling/parameters/engine_version.h"
#include "dem/tester/tester_parameters.h"
#include "meshes/atomic_file.h"

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace wear::coupling {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

namespace {

// One composition drives declaration, parsing and write-back, so the three never disagree;
// the subsections in case-file order, each declared by the module that owns it.
template <typename Visitor>
void visit(CaseParameters& c, Visitor& v) {
  meshes::visit_parameters(c.geometry, v);
  dem::visit_parameters(c.scene, v);
  dem::visit_parameters(c.dem, v);
  dem::visit_parameters(c.wear_law, v);
  dem::visit_parameters(c.deformation, v);
  visit_parameters(c.coupling, v);
  fem::visit_parameters(c.fem, v);
  visit_parameters(c.output, v);
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

namespace {
/// Defaults with one scene wall, inlet and outlet per name, so that their subsections are
/// declared.
CaseParameters defaults_with_scene(const dem::SceneNames& names) {
  CaseParameters c;
  c.scene = dem::scene_with_names(names);
  return c;
}
} // namespace

void declare_parameters(ParameterHandler& prm, const dem::SceneNames& names) {
  CaseParameters defaults = defaults_with_scene(names);
  Declare declare{prm};
  visit(defaults, declare);
}

namespace {
/// The value of the entry at `path` ("DEM/Rotation rate") in `prm`.
std::string value_at(ParameterHandler& prm, const std::string& path) {
  std::vector<std::string> parts;
  for (std::size_t b = 0, e; b <= path.size(); b = e + 1) {
    e = std::min(path.find('/', b), path.size());
    parts.push_back(path.substr(b, e - b));
  }
  for (std::size_t k = 0; k + 1 < parts.size(); ++k)
    prm.enter_subsection(parts[k]);
  const std::string value = prm.get(parts.back());
  for (std::size_t k = 0; k + 1 < parts.size(); ++k)
    prm.leave_subsection();
  return value;
}

/// The entries of `set` whose value in `p` differs from its default, each compared in the
/// resolved form (the same text for the same value). A resolved parameters.prm sets every
/// entry, and one left at its default changes nothing whether the case uses it or not.
std::vector<CaseFileEntry> changed_entries(const CaseParameters& p,
                                           const std::vector<CaseFileEntry>& set) {
  const dem::SceneNames names{p.scene.wall_names, p.scene.inlet_names, p.scene.outlet_names,
                              p.scene.flux_plane_names};
  ParameterHandler given, defaults;
  declare_parameters(given, names);
  declare_parameters(defaults, names);
  CaseParameters copy = p, plain = defaults_with_scene(names);
  Store store_given{given}, store_defaults{defaults};
  visit(copy, store_given);
  visit(plain, store_defaults);
  std::vector<CaseFileEntry> changed;
  for (const auto& e : set)
    if (value_at(given, e.path) != value_at(defaults, e.path))
      changed.push_back(e);
  return changed;
}
} // namespace

CaseParameters read_case(const std::string& path, std::ostream& warnings) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("case file '" + path + "' does not exist");
  // Our own walk of the lines first: ParameterHandler would follow an INCLUDE loop until the
  // stack overflows, and keeps the last of two values of one entry without a word. The
  // repetitions are warned at once, before any refusal below that the value kept may cause.
  CaseFileWalk lines;
  try {
    lines = walk_case_file(path);
    for (const auto& note : lines.repeated)
      warnings << "warning: case file '" << path << "': " << note << "\n";
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("case file '" + path + "': " + e.what());
  }
  // Two readings: the first, which skips what it does not know, finds the names of the
  // scene's walls, inlets and outlets; the second declares a subsection per name and refuses
  // anything undeclared.
  dem::SceneNames names;
  try {
    ParameterHandler first;
    declare_parameters(first);
    first.parse_input(path, "", true);
    first.enter_subsection("Scene");
    names = {first.get("Walls"), first.get("Inlets"), first.get("Outlets"),
             first.get("Flux planes")};
    first.leave_subsection();
  } catch (const std::exception& e) {
    throw std::runtime_error("case file '" + path + "': " + short_message(e));
  }
  ParameterHandler prm;
  CaseParameters p;
  try {
    declare_parameters(prm, names);
    p = defaults_with_scene(names);
    prm.parse_input(path, "", false);
  } catch (const std::exception& e) {
    throw std::runtime_error("case file '" + path + "': " + short_message(e));
  }
  p.case_file = path;
  Parse parse{prm};
  visit(p, parse);
  std::vector<std::string> notes;
  try {
    require_used_parameters(p, changed_entries(p, lines.entries));
    meshes::validate(p.geometry);
    dem::validate(p.scene);
    dem::validate(p.dem);
    dem::make_wear_law(p.wear_law);
    validate(p.coupling, p.fem);
    notes = check_consistency(p);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("case file '" + path + "': " + e.what());
  }
  for (const auto& note : notes)
    warnings << "warning: case file '" << path << "': " << note << "\n";
  return p;
}

double stress_averaging_radius(const CaseParameters& p) {
  if (p.fem.elasticity.averaging_radius > 0)
    return p.fem.elasticity.averaging_radius;
  return 0.5 * p.dem.psd.mean_diameter();
}

CaseParameters read_case(const std::string& path) {
  return read_case(path, std::cerr);
}

std::string resolved_parameters(const CaseParameters& p) {
  ParameterHandler prm;
  declare_parameters(prm, {p.scene.wall_names, p.scene.inlet_names, p.scene.outlet_names,
                           p.scene.flux_plane_names});
  CaseParameters copy = p;
  Store store{prm};
  visit(copy, store);
  std::ostringstream out;
  prm.print_parameters(out, ParameterHandler::PRM);
  return out.str();
}

namespace {
/// The shortest text that reads back as the same double (1/3 -> 0.3333333333333333, 0.3 -> 0.3).
std::string shortest(double x) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  return {buffer, r.ptr};
}

/// A visitor that writes each parameter's value as case-file text, numbers in their shortest
/// exact form (where ParameterHandler keeps 16 digits).
struct Texts {
  /// One parameter: its subsections and name in order ("Scene", "Wall floor", "Source"), its
  /// value as text.
  struct Item {
    std::vector<std::string> path;
    std::string value;
  };
  std::vector<std::string> section; ///< the subsections entered
  std::vector<Item> items;          ///< in visiting order

  void enter(const std::string& s) { section.push_back(s); }
  void leave() { section.pop_back(); }
  void real(const std::string& n, double& x, const std::string&) { add(n, shortest(x)); }
  void integer(const std::string& n, int& x, int, int, const std::string&) {
    add(n, std::to_string(x));
  }
  void unsigned_integer(const std::string& n, unsigned int& x, int, int, const std::string&) {
    add(n, std::to_string(x));
  }
  void count(const std::string& n, std::uint64_t& x, const std::string&) {
    add(n, std::to_string(x));
  }
  void boolean(const std::string& n, bool& x, const std::string&) { add(n, x ? "true" : "false"); }
  void choice(const std::string& n, bool& x, const std::string& yes, const std::string& no,
              const std::string&) {
    add(n, x ? yes : no);
  }
  void selection(const std::string& n, std::string& x, const std::string&, const std::string&) {
    add(n, x);
  }
  void text(const std::string& n, std::string& x, const std::string&) { add(n, x); }
  void real_list(const std::string& n, std::vector<double>& x, const std::string&) {
    std::string t;
    for (const double v : x)
      t += (t.empty() ? "" : ", ") + shortest(v);
    add(n, t);
  }
  void int_list(const std::string& n, std::vector<int>& x, const std::string&) {
    std::string t;
    for (const int v : x)
      t += (t.empty() ? "" : ", ") + std::to_string(v);
    add(n, t);
  }

private:
  void add(const std::string& name, std::string value) {
    std::vector<std::string> path = section;
    path.push_back(name);
    items.push_back({std::move(path), std::move(value)});
  }
};
} // namespace

std::string changed_parameters(const CaseParameters& p) {
  const dem::SceneNames names{p.scene.wall_names, p.scene.inlet_names, p.scene.outlet_names,
                              p.scene.flux_plane_names};
  CaseParameters copy = p, plain = defaults_with_scene(names);
  // the lists of names are set whenever they name something (their default is empty)
  plain.scene.wall_names = plain.scene.inlet_names = plain.scene.outlet_names =
      plain.scene.flux_plane_names = "";
  Texts given, defaults;
  visit(copy, given);
  visit(plain, defaults);
  std::ostringstream out;
  std::vector<std::string> open; // the subsections written and not yet closed
  for (std::size_t k = 0; k < given.items.size(); ++k) {
    const auto& [parts, value] = given.items[k];
    if (value == defaults.items.at(k).value)
      continue;
    std::size_t common = 0;
    while (common < open.size() && common + 1 < parts.size() && open[common] == parts[common])
      ++common;
    while (open.size() > common) {
      open.pop_back();
      out << std::string(2 * open.size(), ' ') << "end\n";
    }
    for (std::size_t k2 = common; k2 + 1 < parts.size(); ++k2) {
      out << std::string(2 * open.size(), ' ') << "subsection " << parts[k2] << "\n";
      open.push_back(parts[k2]);
    }
    out << std::string(2 * open.size(), ' ') << "set " << parts.back() << " = " << value << "\n";
  }
  while (!open.empty()) {
    open.pop_back();
    out << std::string(2 * open.size(), ' ') << "end\n";
  }
  return out.str();
}

void write_resolved_parameters(const CaseParameters& p, const std::string& path) {
  const std::string text = resolved_parameters(p);
  meshes::write_atomically(path, [&](std::ostream& out) {
    out << "# Fully resolved parameters";
    if (!p.case_file.empty())
      out << " of " << p.case_file;
    // the report scripts read this line to tell which engine made a run
    out << "\n# Engine version: " << engine_version() << "\n" << text;
  });
}

void print_parameters(std::ostream& out) {
  ParameterHandler prm;
  declare_parameters(prm, {"example", "example", "example", "example"});
  prm.print_parameters(out, ParameterHandler::Text);
}

std::string run_part(const CaseParameters& p, const std::string& part) {
  if (!part.empty() || p.scene.walls.empty())
    return part;
  return p.scene.evaluation.wall;
}

void require_no_scene(const CaseParameters& p, const std::string& command) {
  if (!p.scene.walls.empty())
    throw std::invalid_argument(
        "case file '" + p.case_file + "': Scene/Walls lists walls, but `wearsim " + command +
        "` takes a wear-tester case; a scene is built and checked by `wearsim scene` and "
        "run by `wearsim run` (or `wearsim scene-run`)");
}

} // namespace wear::coupling

#pragma once
// The case file: a deal.II ParameterHandler `.prm` with one subsection per concern. Each
// subsection fills a plain struct owned by its module and is declared once, beside that
// struct, by the module's visit_parameters (meshes/parameter_visitor.h); the case file only
// composes them (meshes/ and dem/ have no deal.II dependency).
#include "coupling/parameters/coupling_parameters.h"
#include "dem/scene/scene_parameters.h"
#include "dem/tester/tester_parameters.h"
#include "dem/wear/reference_deformation.h"
#include "dem/wear/wear_law.h"
#include "fem/fem_parameters.h"
#include "meshes/geometry_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace wear::coupling {

struct OutputParameters {
  std::string directory = "output";  ///< results folder, relative to the working directory
  double checkpoint_interval = 1800; ///< [s] wall time between in-stage checkpoints (0: none)
};

/// The Output subsection.
template <typename Visitor>
void visit_parameters(OutputParameters& o, Visitor& v) {
  v.enter("Output");
  v.text("Directory", o.directory, "Results folder; created if missing.");
  v.real("Checkpoint interval", o.checkpoint_interval,
         "[s] Wall time between checkpoints inside a stage (the DEM state, the stage's loads "
         "so far and its open revolution), on top of the checkpoint after every stage and the "
         "one SIGINT, SIGTERM or SIGUSR1 asks for; 0 writes none. A stage is one or more "
         "revolutions, hours at the real particle size.");
  v.leave();
}

struct CaseParameters {
  meshes::GeometryParameters geometry;
  dem::SceneParameters scene; ///< the user's own walls; none: a wear-tester case
  dem::TesterDemParameters dem;
  dem::WearLawParameters wear_law;
  dem::ReferenceDeformationParameters deformation;
  CouplingParameters coupling;
  fem::FemParameters fem;
  OutputParameters output;
  std::string case_file; ///< path the parameters were read from ("" for defaults)
};

/// [m] The radius of the ball the stress is averaged over: FEM/Stress averaging radius, or
/// when that is 0 the number-weighted mean particle radius at the run's scaling factor
/// (the coarse-graining width of the wall loads).
double stress_averaging_radius(const CaseParameters& p);

/// Declares every subsection and parameter with its default and documentation; the Scene
/// subsection with one `Wall <name>`, `Inlet <name>`, `Outlet <name>` and `Flux plane <name>`
/// subsection per name in `names` (Scene/Walls, Inlets, Outlets, Flux planes).
void declare_parameters(dealii::ParameterHandler& prm, const dem::SceneNames& names = {});

/// Reads a case file. An INCLUDE loop (case_file_lines.h), unknown or misspelled parameters,
/// malformed values, physically impossible values and combinations that would fail later
/// (check_consistency, case_consistency.h) are errors naming the parameters and the file; a
/// parameter set twice in one file (case_file_lines.h, written as the file is read) and the
/// warnings of check_consistency go to `warnings`, each on a line
/// "warning: case file '<path>': ...".
CaseParameters read_case(const std::string& path, std::ostream& warnings);
/// read_case with the warnings on std::cerr.
CaseParameters read_case(const std::string& path);

/// The fully resolved parameters (every value, defaults included) in PRM form.
std::string resolved_parameters(const CaseParameters& p);

/// The entries of `p` that differ from their defaults, in PRM form (subsections nested and
/// indented by two spaces, in the order the case file declares them): a case file that reads
/// back as `p`.
std::string changed_parameters(const CaseParameters& p);

/// Writes the fully resolved parameters of a case (every value, defaults included) as .prm.
void write_resolved_parameters(const CaseParameters& p, const std::string& path);

/// Prints every parameter with its default and documentation (for --print-parameters); the
/// Scene's wall, inlet, outlet and flux-plane subsections as for one of each named `example`.
void print_parameters(std::ostream& out);

/// The wearing part whose figures a run's tables hold for `wearsim compare` and `calibrate`:
/// `part` when named (--part), else the part the scene evaluates as the tester's sample
/// (Scene/Evaluation/Wall); empty for a run of an older engine's built-in tester and for a
/// scene that evaluates none.
std::string run_part(const CaseParameters& p, const std::string& part);

/// Throws std::invalid_argument for a case with scene walls: `command` takes a wear-tester
/// case; a scene is built and checked by `wearsim scene` and run by `wearsim run`.
void require_no_scene(const CaseParameters& p, const std::string& command);

} // namespace wear::coupling

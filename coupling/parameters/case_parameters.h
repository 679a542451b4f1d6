#pragma once
// The case file: a deal.II ParameterHandler `.prm` with one subsection per concern. Each
// subsection fills a plain struct owned by its module and is declared once, beside that
// struct, by the module's visit_parameters (meshes/parameter_visitor.h); the case file only
// composes them (meshes/ and dem/ have no deal.II dependency).
#include "coupling/parameters/coupling_parameters.h"
#include "dem/tester/reference_deformation.h"
#include "dem/tester/tester_parameters.h"
#include "dem/tester/wear_law.h"
#include "fem/fem_parameters.h"
#include "meshes/geometry_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace wear::coupling {

struct OutputParameters {
  std::string directory = "output"; ///< results folder, relative to the working directory
};

/// The Output subsection.
template <typename Visitor>
void visit_parameters(OutputParameters& o, Visitor& v) {
  v.enter("Output");
  v.text("Directory", o.directory, "Results folder; created if missing.");
  v.leave();
}

struct CaseParameters {
  meshes::GeometryParameters geometry;
  dem::TesterDemParameters dem;
  dem::WearLawParameters wear_law;
  dem::ReferenceDeformationParameters deformation;
  CouplingParameters coupling;
  fem::FemParameters fem;
  OutputParameters output;
  std::string case_file; ///< path the parameters were read from ("" for defaults)
};

/// Declares every subsection and parameter with its default and documentation.
void declare_parameters(dealii::ParameterHandler& prm);

/// Reads a case file. Unknown or misspelled parameters, malformed values and physically
/// impossible values are errors naming the parameter and the file.
CaseParameters read_case(const std::string& path);

/// The fully resolved parameters (every value, defaults included) in PRM form.
std::string resolved_parameters(const CaseParameters& p);

/// Writes the fully resolved parameters of a case (every value, defaults included) as .prm.
void write_resolved_parameters(const CaseParameters& p, const std::string& path);

/// Prints every parameter with its default and documentation (for --print-parameters).
void print_parameters(std::ostream& out);

} // namespace wear::coupling

#pragma once
// Wear laws: removed volume per face from the extensive window integrals of a wearing wall.
// The laws form a catalogue of plugins (as in ASPECT): each entry in wear_law.cc holds the
// law's name (case file "Wear law/Model"), its description, the parameters it declares and
// its factory. The Wear law subsection, the selection of Model and its documentation are
// built from the catalogue, and make_wear_law finds a law by name. A new law is an entry in
// wear_law.cc (and a class only when it is not a coefficient times one window integral); a
// new coefficient is also a member of WearLawParameters.
#include "dem/engine/system.h"
#include "meshes/parameter_visitor.h"

#include <memory>
#include <string>
#include <vector>

namespace wear::dem {

struct WearLawParameters {
  std::string model = "archard";      ///< name of the law (see wear_law_catalogue())
  double archard_coefficient = 5e-9;  ///< [1/Pa] alpha = k / H of the Archard law
  double work_coefficient = 1.667e-8; ///< [m^3/J] volume per frictional work
};

class WearLaw {
public:
  virtual ~WearLaw() = default;
  virtual std::string name() const = 0;
  /// Removed volume per face [m^3] over the window the integrals cover.
  virtual std::vector<double> removed_volume(const WearIntegrals& w) const = 0;
  /// The same total computed from the per-contact sums (before any face splitting) [m^3].
  virtual double total_removed_volume(const WearIntegrals& w) const = 0;
};

/// A parameter a law declares in the Wear law subsection: a coefficient the law is linear
/// in, so it must be finite and non-negative (make_wear_law checks it, naming it). A name
/// belongs to one law.
struct WearLawParameter {
  std::string name;                  ///< in the case file, e.g. "Archard coefficient"
  double WearLawParameters::*member; ///< the value, e.g. &WearLawParameters::archard_coefficient
  std::string doc;                   ///< unit first, e.g. "[1/Pa] alpha = k/H ..."
};

/// One law of the catalogue.
struct WearLawEntry {
  std::string name;        ///< value of "Wear law/Model"
  std::string description; ///< printed in the documentation of Model
  /// The parameters the law declares; the first is the coefficient `wearsim calibrate` scales.
  std::vector<WearLawParameter> parameters;
  /// Builds the law from parameters make_wear_law has checked.
  std::unique_ptr<WearLaw> (*make)(const WearLawParameters& p);
};

/// Every law, in the order the documentation lists them.
const std::vector<WearLawEntry>& wear_law_catalogue();

/// The law named `name`; throws std::invalid_argument naming "Wear law/Model" and the known
/// laws for an unknown name.
const WearLawEntry& find_wear_law(const std::string& name);

/// Throws std::invalid_argument naming "Wear law/Model" and the known laws for an unknown
/// name, or the coefficient for a negative or non-finite one.
std::unique_ptr<WearLaw> make_wear_law(const WearLawParameters& p);

/// The Wear law subsection of a case file (meshes/parameter_visitor.h): Model, then the
/// parameters of every law in catalogue order.
template <typename Visitor>
void visit_parameters(WearLawParameters& p, Visitor& v) {
  v.enter("Wear law");
  std::string doc = "Wear law by name:";
  std::string names;
  for (const auto& law : wear_law_catalogue()) {
    doc += "\n  " + law.name + ": " + law.description;
    names += (names.empty() ? "" : "|") + law.name;
  }
  v.selection("Model", p.model, names, doc);
  for (const auto& law : wear_law_catalogue())
    for (const auto& c : law.parameters)
      v.real(c.name, p.*c.member, c.doc);
  v.leave();
}

} // namespace wear::dem

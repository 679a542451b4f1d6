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
#include <utility>
#include <vector>

namespace wear::dem {

struct WearLawParameters {
  /// Name of the law (see wear_law_catalogue()), or several joined by '+' ("archard +
  /// finnie"): their volumes add up, face by face and mechanism by mechanism.
  std::string model = "archard";
  double archard_coefficient = 5e-9;  ///< [1/Pa] alpha = k / H of the Archard law
  double work_coefficient = 1.667e-8; ///< [m^3/J] volume per frictional work
  double finnie_coefficient = 1e-10;  ///< [1/Pa] c / (p psi K) of Finnie's law
  double finnie_k = 2;                ///< [-] Finnie's force ratio K
  double oka_coefficient = 1e-9;      ///< [m^3/kg] K of Oka's E90 (at v', d', Hv = 1 GPa)
  double oka_hardness = 1;            ///< [GPa] Hv
  double oka_n1 = 0.71, oka_n2 = 2.4; ///< [-] angle-function exponents
  double oka_k1 = -0.12;              ///< [-] hardness exponent of E90
  double oka_k2 = 2.3;                ///< [-] speed exponent
  double oka_k3 = 0.19;               ///< [-] size exponent
  double sliding_coefficient = 5e-9;  ///< [1/Pa] the sliding-impact law's Archard part
  double impact_coefficient = 1e-9;   ///< [m^3/J] its volume per impact energy
};

class WearLaw {
public:
  virtual ~WearLaw() = default;
  virtual std::string name() const = 0;
  /// Removed volume per face [m^3] over the window the integrals cover.
  virtual std::vector<double> removed_volume(const WearIntegrals& w) const = 0;
  /// The same total computed from the per-contact sums (before any face splitting) [m^3].
  virtual double total_removed_volume(const WearIntegrals& w) const = 0;
  /// The per-face volume [m^3] by mechanism ("sliding", "impact"), summing to removed_volume;
  /// one entry for a law of one mechanism.
  virtual std::vector<std::pair<std::string, std::vector<double>>>
  removed_by_mechanism(const WearIntegrals& w) const = 0;
};

/// A parameter a law declares in the Wear law subsection: a coefficient the law is linear
/// in or a shape parameter of its angle function, finite and non-negative unless `signed_`
/// (make_wear_law checks it, naming it). A name belongs to one law.
struct WearLawParameter {
  std::string name;                  ///< in the case file, e.g. "Archard coefficient"
  double WearLawParameters::*member; ///< the value, e.g. &WearLawParameters::archard_coefficient
  std::string doc;                   ///< unit first, e.g. "[1/Pa] alpha = k/H ..."
  bool signed_ = false;              ///< may be negative (an exponent)
  /// The law's volume is linear in it as in the first parameter: `wearsim calibrate` scales it
  /// by the same factor (a law of two mechanisms keeps their ratio).
  bool scales_with_first = false;
};

/// One law of the catalogue.
struct WearLawEntry {
  std::string name;        ///< value of "Wear law/Model"
  std::string description; ///< printed in the documentation of Model
  /// The parameters the law declares; the first is the coefficient `wearsim calibrate` scales.
  std::vector<WearLawParameter> parameters;
  /// Builds the law from parameters make_wear_law has checked.
  std::unique_ptr<WearLaw> (*make)(const WearLawParameters& p);
  /// What the engine books per impact for this law (DemSettings::impact); nullptr: nothing
  /// beyond the count and the energy (a sliding law, or one of the impact energy).
  ImpactMeasure (*impact)(const WearLawParameters& p) = nullptr;
};

/// Every law, in the order the documentation lists them.
const std::vector<WearLawEntry>& wear_law_catalogue();

/// The law named `name`; throws std::invalid_argument naming "Wear law/Model" and the known
/// laws for an unknown name.
const WearLawEntry& find_wear_law(const std::string& name);

/// The laws a Model names, in its order: one, or several joined by '+'. Throws
/// std::invalid_argument naming "Wear law/Model" for an unknown or repeated name, an empty
/// term, or two laws whose impacts the engine books by different measures (finnie, oka).
std::vector<const WearLawEntry*> wear_laws_of(const std::string& model);

/// Throws std::invalid_argument naming "Wear law/Model" and the known laws for an unknown
/// name, or the coefficient for a negative or non-finite one. A Model of several laws gives
/// their sum.
std::unique_ptr<WearLaw> make_wear_law(const WearLawParameters& p);

/// The engine's per-impact measure for the law `p` names (DemSettings::impact).
ImpactMeasure impact_measure(const WearLawParameters& p);

/// The Wear law subsection of a case file (meshes/parameter_visitor.h): Model, then the
/// parameters of every law in catalogue order.
template <typename Visitor>
void visit_parameters(WearLawParameters& p, Visitor& v) {
  v.enter("Wear law");
  std::string doc = "Wear law by name, or several joined by '+' (archard + finnie), whose "
                    "volumes add up per face (at most one of the laws with an impact measure, "
                    "finnie or oka):";
  for (const auto& law : wear_law_catalogue())
    doc += "\n  " + law.name + ": " + law.description;
  v.text("Model", p.model, doc);
  for (const auto& law : wear_law_catalogue())
    for (const auto& c : law.parameters)
      v.real(c.name, p.*c.member, c.doc);
  v.leave();
}

} // namespace wear::dem

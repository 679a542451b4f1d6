#pragma once
// Wear laws: removed volume per face from the extensive window integrals of a wearing wall.
// A law is chosen by name (case file "Wear law/Model"); each carries a description that the
// parameter documentation prints.
#include "dem/system.h"

#include <memory>
#include <string>
#include <vector>

namespace wear::dem {

struct WearLawParameters {
  std::string model = "archard";      ///< name of the law (see wear_law_catalogue())
  double archard_coefficient = 5e-9;  ///< [1/Pa] alpha = k / H of the Archard law
  double work_coefficient = 1.667e-8; ///< [m^3/J] volume per frictional work
};

/// One entry of the catalogue of laws: name and the documentation text.
struct WearLawInfo {
  std::string name, description;
};
const std::vector<WearLawInfo>& wear_law_catalogue();

class WearLaw {
public:
  virtual ~WearLaw() = default;
  virtual std::string name() const = 0;
  /// Removed volume per face [m^3] over the window the integrals cover.
  virtual std::vector<double> removed_volume(const WearIntegrals& w) const = 0;
  /// The same total computed from the per-contact sums (before any face splitting) [m^3].
  virtual double total_removed_volume(const WearIntegrals& w) const = 0;
};

/// Throws std::invalid_argument naming "Wear law/Model" and the known laws for an unknown
/// name, or the coefficient for a negative or non-finite one.
std::unique_ptr<WearLaw> make_wear_law(const WearLawParameters& p);

} // namespace wear::dem

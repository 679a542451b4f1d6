// Wear laws on the extensive per-face integrals of docs/theory.md section 4:
//   archard:         dV_f = alpha * A_f,   A_f = integral of F_n |v_t| dt      [N m]
//   frictional-work: dV_f = k_w * W_f,     W_f = integral of |F_t . v_t| dt    [J]
// Both are linear in extensive integrals, so the volume of a face set is the law applied to
// the sum, and splitting contacts over faces conserves volume exactly. Each law is one entry
// of the catalogue (name, description, parameters, factory).
#include "dem/wear/wear_law.h"

#include <cmath>
#include <stdexcept>

namespace wear::dem {

namespace {

// Both laws are a coefficient times one extensive integral of the window: per face, and the
// same total from the per-contact sums.
class LinearWearLaw final : public WearLaw {
public:
  LinearWearLaw(const char* name, double coefficient, std::vector<double> WearIntegrals::*per_face,
                double WearIntegrals::*total)
      : name_(name), coefficient_(coefficient), per_face_(per_face), total_(total) {}
  std::string name() const override { return name_; }
  std::vector<double> removed_volume(const WearIntegrals& w) const override {
    const std::vector<double>& integral = w.*per_face_;
    std::vector<double> v(integral.size());
    for (std::size_t f = 0; f < v.size(); ++f)
      v[f] = coefficient_ * integral[f];
    return v;
  }
  double total_removed_volume(const WearIntegrals& w) const override {
    return coefficient_ * w.*total_;
  }

private:
  const char* name_;
  double coefficient_;
  std::vector<double> WearIntegrals::*per_face_;
  double WearIntegrals::*total_;
};

WearLawEntry archard_law() {
  return {"archard",
          "Archard sliding wear: removed volume dV = alpha F_n |v_t| dt per contact and step, "
          "alpha = k/H [1/Pa] ('Archard coefficient'). The reference study calibrated alpha = "
          "5e-9 1/Pa so that two simulated revolutions represent 56 h of the laboratory test.",
          {{"Archard coefficient", &WearLawParameters::archard_coefficient,
            "[1/Pa] alpha = k/H of the Archard law."}},
          [](const WearLawParameters& p) -> std::unique_ptr<WearLaw> {
            return std::make_unique<LinearWearLaw>("archard", p.archard_coefficient,
                                                   &WearIntegrals::archard,
                                                   &WearIntegrals::total_archard);
          }};
}

WearLawEntry frictional_work_law() {
  return {"frictional-work",
          "Frictional-work (energy) wear: dV = k_w |F_t . v_t| dt [m^3/J] ('Work coefficient'). "
          "Equals Archard with alpha = k_w mu where contacts fully slide; differs where they "
          "stick, which removes nothing here.",
          {{"Work coefficient", &WearLawParameters::work_coefficient,
            "[m^3/J] Volume removed per frictional work (frictional-work law)."}},
          [](const WearLawParameters& p) -> std::unique_ptr<WearLaw> {
            return std::make_unique<LinearWearLaw>("frictional-work", p.work_coefficient,
                                                   &WearIntegrals::sliding_work,
                                                   &WearIntegrals::total_sliding_work);
          }};
}

void check_coefficient(double c, const std::string& parameter) {
  if (!(c >= 0) || !std::isfinite(c))
    throw std::invalid_argument("Wear law/" + parameter +
                                ": must be a finite non-negative number, got " + std::to_string(c));
}

} // namespace

const std::vector<WearLawEntry>& wear_law_catalogue() {
  static const std::vector<WearLawEntry> laws = {archard_law(), frictional_work_law()};
  return laws;
}

const WearLawEntry& find_wear_law(const std::string& name) {
  std::string known;
  for (const auto& law : wear_law_catalogue()) {
    if (law.name == name)
      return law;
    known += (known.empty() ? "" : ", ") + law.name;
  }
  throw std::invalid_argument("Wear law/Model: unknown law '" + name + "' (known: " + known + ")");
}

std::unique_ptr<WearLaw> make_wear_law(const WearLawParameters& p) {
  const WearLawEntry& law = find_wear_law(p.model);
  for (const auto& c : law.parameters)
    check_coefficient(p.*c.member, c.name);
  return law.make(p);
}

} // namespace wear::dem

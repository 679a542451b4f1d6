// Wear laws on the extensive per-face integrals of docs/theory.md section 4:
//   archard:         dV_f = alpha * A_f,   A_f = integral of F_n |v_t| dt      [N m]
//   frictional-work: dV_f = k_w * W_f,     W_f = integral of |F_t . v_t| dt    [J]
//   finnie:          dV_f = k_F * sum over impacts of m |v|^2 f_K(alpha)       [kg m^2/s^2]
//   oka:             dV_f = K Hv^k1 * sum of m (v/v')^k2 (d/d')^k3 g(alpha)    [kg]
//   sliding-impact:  dV_f = alpha A_f + k_E E_f, E_f = sum of m v_n^2 / 2      [J]
// (the impact sums booked by the engine at each contact's first step, impact_measure.h).
// Every law is linear in extensive integrals, so the volume of a face set is the law applied
// to the sum, and splitting contacts over faces conserves volume exactly. Each law is one
// entry of the catalogue (name, description, parameters, factory, the engine's impact
// measure).
#include "dem/wear/wear_law.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

namespace {

// Both laws are a coefficient times one extensive integral of the window: per face, and the
// same total from the per-contact sums.
class LinearWearLaw final : public WearLaw {
public:
  LinearWearLaw(const char* name, const char* mechanism, double coefficient,
                std::vector<double> WearIntegrals::*per_face, double WearIntegrals::*total)
      : name_(name), mechanism_(mechanism), coefficient_(coefficient), per_face_(per_face),
        total_(total) {}
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
  std::vector<std::pair<std::string, std::vector<double>>>
  removed_by_mechanism(const WearIntegrals& w) const override {
    return {{mechanism_, removed_volume(w)}};
  }

private:
  const char* name_;
  const char* mechanism_;
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
            return std::make_unique<LinearWearLaw>("archard", "sliding", p.archard_coefficient,
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
            return std::make_unique<LinearWearLaw>("frictional-work", "sliding", p.work_coefficient,
                                                   &WearIntegrals::sliding_work,
                                                   &WearIntegrals::total_sliding_work);
          }};
}

// Sliding (Archard) plus impact energy: the shear and impact energy model of Xu, Luo and
// Zhao (2018), each part a coefficient times its own extensive integral.
class SlidingImpactLaw final : public WearLaw {
public:
  SlidingImpactLaw(double alpha, double k_e) : alpha_(alpha), k_e_(k_e) {}
  std::string name() const override { return "sliding-impact"; }
  std::vector<double> removed_volume(const WearIntegrals& w) const override {
    std::vector<double> v(w.archard.size());
    for (std::size_t f = 0; f < v.size(); ++f)
      v[f] = alpha_ * w.archard[f] + k_e_ * w.impact_energy[f];
    return v;
  }
  double total_removed_volume(const WearIntegrals& w) const override {
    return alpha_ * w.total_archard + k_e_ * w.total_impact_energy;
  }
  std::vector<std::pair<std::string, std::vector<double>>>
  removed_by_mechanism(const WearIntegrals& w) const override {
    std::vector<double> sliding(w.archard.size()), impact(w.archard.size());
    for (std::size_t f = 0; f < sliding.size(); ++f) {
      sliding[f] = alpha_ * w.archard[f];
      impact[f] = k_e_ * w.impact_energy[f];
    }
    return {{"sliding", std::move(sliding)}, {"impact", std::move(impact)}};
  }

private:
  double alpha_, k_e_;
};

WearLawEntry finnie_law() {
  return {"finnie",
          "Finnie's ductile erosion (1960): each impact removes dV = k_F m |v|^2 f_K(alpha), m "
          "the particle's mass, v the contact point's relative velocity at the contact's first "
          "step and alpha its angle to the wall; f_K = sin 2a - (6/K) sin^2 a while tan a <= "
          "K/6 (the particle leaves the surface still cutting), else K cos^2 a / 6 (its "
          "horizontal motion stops first). With K = 2 the erosion peaks at 16.8 degrees and "
          "vanishes at normal impact.",
          {{"Finnie coefficient", &WearLawParameters::finnie_coefficient,
            "[1/Pa] k_F = c / (p psi K): volume per impact kinetic energy at the peak's scale "
            "(finnie law)."},
           {"Finnie K", &WearLawParameters::finnie_k,
            "[-] Finnie's ratio of the vertical to the horizontal force on the particle's tip "
            "(finnie law); 2 in Finnie's analysis."}},
          [](const WearLawParameters& p) -> std::unique_ptr<WearLaw> {
            return std::make_unique<LinearWearLaw>("finnie", "impact", p.finnie_coefficient,
                                                   &WearIntegrals::impact_measure,
                                                   &WearIntegrals::total_impact_measure);
          },
          [](const WearLawParameters& p) {
            ImpactMeasure m;
            m.kind = ImpactMeasure::Kind::finnie;
            m.finnie_k = p.finnie_k;
            return m;
          }};
}

WearLawEntry oka_law() {
  return {"oka",
          "Oka et al. (2005): each impact removes dV = m E90 g(alpha), E90 = K Hv^k1 "
          "(|v|/104 m/s)^k2 (d/326 um)^k3, g = sin^n1(a) (1 + Hv (1 - sin a))^n2, m and d the "
          "particle's mass and diameter, v and alpha as for finnie, Hv the wall's Vickers "
          "hardness in GPa.",
          {{"Oka coefficient", &WearLawParameters::oka_coefficient,
            "[m^3/kg] K: volume per particle mass at normal impact at 104 m/s, 326 um and Hv = 1 "
            "GPa (oka law)."},
           {"Oka hardness", &WearLawParameters::oka_hardness,
            "[GPa] Vickers hardness Hv of the wearing material (oka law)."},
           {"Oka n1", &WearLawParameters::oka_n1, "[-] exponent of sin(alpha) (oka law)."},
           {"Oka n2", &WearLawParameters::oka_n2,
            "[-] exponent of the hardness term 1 + Hv (1 - sin alpha) (oka law)."},
           {"Oka k1", &WearLawParameters::oka_k1, "[-] hardness exponent of E90 (oka law).", true},
           {"Oka k2", &WearLawParameters::oka_k2, "[-] speed exponent of E90 (oka law)."},
           {"Oka k3", &WearLawParameters::oka_k3, "[-] size exponent of E90 (oka law)."}},
          [](const WearLawParameters& p) -> std::unique_ptr<WearLaw> {
            return std::make_unique<LinearWearLaw>(
                "oka", "impact", p.oka_coefficient * std::pow(p.oka_hardness, p.oka_k1),
                &WearIntegrals::impact_measure, &WearIntegrals::total_impact_measure);
          },
          [](const WearLawParameters& p) {
            ImpactMeasure m;
            m.kind = ImpactMeasure::Kind::oka;
            m.oka_n1 = p.oka_n1;
            m.oka_n2 = p.oka_n2;
            m.oka_hardness = p.oka_hardness;
            m.speed_exponent = p.oka_k2;
            m.size_exponent = p.oka_k3;
            return m;
          }};
}

WearLawEntry sliding_impact_law() {
  return {"sliding-impact",
          "Sliding plus impact energy (the shear and impact energy model of Xu, Luo and Zhao "
          "2018): dV = alpha F_n |v_t| dt per contact and step, plus k_E m v_n^2 / 2 per impact "
          "(v_n the approach speed at the contact's first step); the share of each is written "
          "per face.",
          {{"Sliding coefficient", &WearLawParameters::sliding_coefficient,
            "[1/Pa] alpha of the sliding part (sliding-impact law)."},
           {"Impact energy coefficient", &WearLawParameters::impact_coefficient,
            "[m^3/J] k_E: volume per normal impact energy (sliding-impact law); `wearsim "
            "calibrate` scales it with the Sliding coefficient, keeping their ratio.",
            false, true}},
          [](const WearLawParameters& p) -> std::unique_ptr<WearLaw> {
            return std::make_unique<SlidingImpactLaw>(p.sliding_coefficient, p.impact_coefficient);
          }};
}

// Several laws at once: their volumes add up per face, per mechanism and in total.
class SumWearLaw final : public WearLaw {
public:
  SumWearLaw(std::string name, std::vector<std::unique_ptr<WearLaw>> terms)
      : name_(std::move(name)), terms_(std::move(terms)) {}
  std::string name() const override { return name_; }
  std::vector<double> removed_volume(const WearIntegrals& w) const override {
    std::vector<double> sum(w.archard.size(), 0.0);
    for (const auto& law : terms_) {
      const std::vector<double> v = law->removed_volume(w);
      for (std::size_t f = 0; f < sum.size(); ++f)
        sum[f] += v[f];
    }
    return sum;
  }
  double total_removed_volume(const WearIntegrals& w) const override {
    double sum = 0;
    for (const auto& law : terms_)
      sum += law->total_removed_volume(w);
    return sum;
  }
  std::vector<std::pair<std::string, std::vector<double>>>
  removed_by_mechanism(const WearIntegrals& w) const override {
    std::vector<std::pair<std::string, std::vector<double>>> out;
    for (const auto& law : terms_)
      for (auto& [mechanism, volume] : law->removed_by_mechanism(w)) {
        auto at = std::find_if(out.begin(), out.end(),
                               [&](const auto& e) { return e.first == mechanism; });
        if (at == out.end()) {
          out.emplace_back(mechanism, std::move(volume));
          continue;
        }
        for (std::size_t f = 0; f < volume.size(); ++f)
          at->second[f] += volume[f];
      }
    return out;
  }

private:
  std::string name_;
  std::vector<std::unique_ptr<WearLaw>> terms_;
};

void check_coefficient(double c, bool signed_, const std::string& parameter) {
  if (!std::isfinite(c) || (!signed_ && !(c >= 0)))
    throw std::invalid_argument("Wear law/" + parameter + ": must be a finite " +
                                (signed_ ? "" : "non-negative ") + "number, got " +
                                std::to_string(c));
}

} // namespace

const std::vector<WearLawEntry>& wear_law_catalogue() {
  static const std::vector<WearLawEntry> laws = {archard_law(), frictional_work_law(), finnie_law(),
                                                 oka_law(), sliding_impact_law()};
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

std::vector<const WearLawEntry*> wear_laws_of(const std::string& model) {
  std::vector<const WearLawEntry*> laws;
  std::stringstream in(model);
  for (std::string term; std::getline(in, term, '+');) {
    const auto first = term.find_first_not_of(" \t"), last = term.find_last_not_of(" \t");
    if (first == std::string::npos)
      throw std::invalid_argument("Wear law/Model: '" + model + "' has an empty term");
    const WearLawEntry* law = &find_wear_law(term.substr(first, last - first + 1));
    if (std::find(laws.begin(), laws.end(), law) != laws.end())
      throw std::invalid_argument("Wear law/Model: '" + model + "' names '" + law->name +
                                  "' twice");
    for (const WearLawEntry* other : laws)
      if (law->impact && other->impact)
        throw std::invalid_argument("Wear law/Model: '" + model + "' sums '" + other->name +
                                    "' and '" + law->name +
                                    "', whose impacts the engine books by different measures; "
                                    "keep one of them");
    laws.push_back(law);
  }
  // getline yields no term after a trailing '+'
  if (laws.empty() || laws.size() != std::size_t(std::count(model.begin(), model.end(), '+')) + 1)
    throw std::invalid_argument("Wear law/Model: '" + model + "' has an empty term");
  return laws;
}

std::unique_ptr<WearLaw> make_wear_law(const WearLawParameters& p) {
  const std::vector<const WearLawEntry*> laws = wear_laws_of(p.model);
  for (const WearLawEntry* law : laws)
    for (const auto& c : law->parameters)
      check_coefficient(p.*c.member, c.signed_, c.name);
  if (laws.size() == 1)
    return laws[0]->make(p);
  std::vector<std::unique_ptr<WearLaw>> terms;
  std::string name;
  for (const WearLawEntry* law : laws) {
    terms.push_back(law->make(p));
    name += (name.empty() ? "" : " + ") + law->name;
  }
  return std::make_unique<SumWearLaw>(name, std::move(terms));
}

ImpactMeasure impact_measure(const WearLawParameters& p) {
  for (const WearLawEntry* law : wear_laws_of(p.model))
    if (law->impact)
      return law->impact(p);
  return ImpactMeasure{};
}

} // namespace wear::dem

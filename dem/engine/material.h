#pragma once
// Materials and per-pair contact parameters for the Hertz-Mindlin no-slip law.
#include <string>
#include <vector>

namespace wear::dem {

struct Material {
  std::string name;
  double youngs_modulus = 0; ///< [Pa]; infinity makes a rigid wall material
  double poisson_ratio = 0;  ///< [-]
  double density = 0;        ///< [kg/m^3]
  double shear_modulus() const { return youngs_modulus / (2 * (1 + poisson_ratio)); } ///< [Pa]
};

/// Interaction properties of a material pair.
struct PairProperties {
  double restitution = 0.5;      ///< [-] normal coefficient of restitution, in (0, 1]
  double friction = 0.5;         ///< [-] static (Coulomb) friction coefficient
  double rolling_friction = 0.0; ///< [-] constant-directional-torque coefficient, in [0, 1]
};

/// [-] The largest rolling friction coefficient mu_r a pair may have (MaterialTable::set_pair;
/// the case file's "Rolling friction ..." parameters are refused above it by name, validate()
/// of dem/tester). The rolling resistance is the torque mu_r F_n a, a the centre-to-contact
/// distance (docs/theory.md section 2): the couple of the normal force shifted off the line of
/// centres by mu_r a. That shift can reach at most the edge of the particle (a sphere's
/// contact patch, or for a real grain the face it rests on, lies within a radius of its
/// centre), so mu_r = 1 is a physical bound; DEM studies of granular materials stay below it,
/// mostly at 0.01 to 0.5. Keep the documentation of "Rolling friction ..." in step.
constexpr double max_rolling_friction = 1;

/// How the damping ratio is obtained from the restitution coefficient.
enum class RestitutionMapping {
  /// beta = ln e / sqrt(ln^2 e + pi^2) (docs/theory.md section 2). With the normal force clamped at
  /// zero
  /// the realised restitution is then somewhat higher than e.
  classical,
  /// beta solved so that the realised restitution of the clamped law equals e exactly
  /// (the law's restitution is independent of speed, size and stiffness, so one
  /// dimensionless solve per e suffices).
  exact
};

/// Precomputed contact constants of one material pair (docs/theory.md section 2).
struct ContactParameters {
  double e_star = 0; ///< [Pa] effective Young's modulus
  double g_star = 0; ///< [Pa] effective shear modulus
  double beta = 0;   ///< [-] damping ratio (<= 0)
  double friction = 0, rolling_friction = 0;
  double tangential_damping_ratio = 0; ///< [-] sqrt(4 G* / E*) = c_t / c_n
};

class MaterialTable {
public:
  /// Returns the material id. Throws naming the material for non-physical values.
  int add(const Material& m);
  /// Sets the properties of pair (a, b) (symmetric). Throws for values out of range.
  void set_pair(int a, int b, const PairProperties& p);
  void set_restitution_mapping(RestitutionMapping m) { mapping_ = m; }
  RestitutionMapping restitution_mapping() const { return mapping_; }

  int n_materials() const { return static_cast<int>(materials_.size()); }
  const Material& material(int id) const { return materials_.at(id); }
  const PairProperties& pair(int a, int b) const;

  /// Flattened n x n table of contact constants; call after all pairs are set.
  std::vector<ContactParameters> contact_table() const;

private:
  std::vector<Material> materials_;
  std::vector<PairProperties> pairs_; // n x n, grown on add
  std::vector<bool> pair_set_;
  RestitutionMapping mapping_ = RestitutionMapping::classical;
};

/// beta from e by docs/theory.md section 2's formula.
double classical_damping_ratio(double restitution);
/// Realised restitution of the clamped Hertz law with damping ratio beta (dimensionless
/// impact X'' = -max(0, X^1.5 - sqrt(5) beta X^0.25 X'), X(0) = 0, X'(0) = 1).
double realised_restitution(double beta);
/// beta for which realised_restitution(beta) == e (bisection, 1e-12).
double exact_damping_ratio(double restitution);

} // namespace wear::dem

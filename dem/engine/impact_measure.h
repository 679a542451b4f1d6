#pragma once
// What a wearing wall books per face at the onset of each contact (an impact), beside its
// count and normal kinetic energy: the unit-coefficient volume of the impact wear law in use,
// chosen by the law (dem/wear/wear_law.h) and evaluated in the engine, where the impact speed
// and angle are known. docs/theory.md section 4.3 gives the laws; impact_measure.cc evaluates
// them.
namespace wear::dem {

/// The measure m |v|^n g(alpha) (d / d_ref)^k3 of one impact: m the particle's mass (a clump
/// member's: its body's), v the relative velocity of the contact point at the contact's first
/// step, alpha its angle to the wall's tangent plane (sin alpha = v_n / |v|), d the (member)
/// sphere's diameter.
struct ImpactMeasure {
  enum class Kind {
    none,   ///< nothing beyond the count and the energy
    finnie, ///< m |v|^2 f_K(alpha): Finnie's two regimes (K the force ratio)  [kg m^2/s^2]
    oka     ///< m (|v| / v_ref)^k2 (d / d_ref)^k3 sin^n1(alpha) (1 + Hv (1 - sin alpha))^n2 [kg]
  };
  Kind kind = Kind::none;
  double finnie_k = 2;                ///< [-] Finnie's K: vertical over horizontal force on the tip
  double oka_n1 = 0.71;               ///< [-] Oka's exponent of sin alpha
  double oka_n2 = 2.4;                ///< [-] Oka's exponent of the hardness term
  double oka_hardness = 1;            ///< [GPa] Vickers hardness Hv of the wearing material
  double speed_exponent = 2.3;        ///< [-] Oka's k2
  double size_exponent = 0.19;        ///< [-] Oka's k3
  double reference_speed = 104;       ///< [m/s] Oka's v'
  double reference_diameter = 326e-6; ///< [m] Oka's d'

  /// The measure of one impact of a particle of mass m [kg] and diameter d [m] at speed v
  /// [m/s] and sin alpha in [0, 1].
  double operator()(double m, double d, double v, double sin_alpha) const;
};

/// [-] Finnie's angle function f_K(alpha) for alpha [rad] in [0, pi/2]: sin 2 alpha - (6 / K)
/// sin^2 alpha while tan alpha <= K / 6 (the particle leaves the surface still cutting), else
/// K cos^2 alpha / 6 (its horizontal motion stops before it leaves).
double finnie_angle_function(double alpha, double k);

/// [-] Oka's angle function g(alpha) = sin^n1(alpha) (1 + Hv (1 - sin alpha))^n2, Hv in GPa.
double oka_angle_function(double sin_alpha, double n1, double n2, double hardness);

} // namespace wear::dem

// johnson_cook_rod_law.h: the paper's rod law with Johnson-Cook strain-rate hardening and thermal
// softening (issue 33: the cutting speed and the heat of the cut must change the flow stress).
//
// Johnson and Cook (1983) scale the whole flow stress, (A + B eps_p^n), by
//     S = R(rate) Theta(T),  R = 1 + C ln(max(rate_eq / rate_ref, 1)),
//     Theta = max(1 - T*^m, 1e-3),  T* = clamp((T - T_ref) / (T_melt - T_ref), 0, 1)      [1]
// with C, rate_ref [1/s], m, T_melt [K], T_ref [K] the law's parameters. Here S scales the
// kinematic law's flow stresses (rod_law.h): the band |sigma - S alpha(eps_p)| <= S s_y, yield
// stress and back stress alike, so that the monotonic curve at a constant rate and temperature is
// S times the reference one and the band keeps its width 2 S s_y (the Bauschinger effect as in
// the paper, at the scaled stress level). Scaling only the band's half-width at fixed strain, the
// other reading of "the yield band scales", would leave the hardening unscaled; that is not
// Johnson-Cook, and a linear law would then answer differently from the same law written as a
// two-point curve. The floor 1e-3 keeps a rod at or above T_melt a (very soft) rod: the return
// map divides by S.
//
// The rate. Johnson-Cook's rate is the equivalent plastic strain rate; the rod knows its own axial
// strain rate. Two conversions, both documented in docs/physics.md ("Johnson-Cook in the rods"):
// - total for plastic: the law uses the rod's total strain rate, not its plastic rate, so that it
//   stays a pure function of (strain, rate, temperature, committed shift) with the one per-rod
//   state of the paper's law (a plastic rate would make the return map implicit in the rate).
//   At the steady flow where the factor is measured the elastic strain no longer changes (it
//   grows only with the hardening, by d(sigma)/E), so the two rates agree.
// - rod for equivalent: rate_eq = kappa |rate_rod|, with kappa (rate_to_equivalent) the factor by
//   which the calibration relates the rod's plastic strain to the equivalent plastic strain
//   (calibration.h): in cube-plane simple shear the carrying rods strain by gamma/2 and
//   gamma = sqrt(3) eps_eq, so kappa = 2/sqrt(3); in [100] tension every rod strains by eps/3,
//   kappa = 3. The rate is the time derivative of the same strain, so the same factor converts
//   it, and the rate factor of a rod flowing in the calibration's mode is the material's. In a
//   general flow the rods' rates spread around that (each rod sees n.D.n); kappa = 1 on the rod
//   route (rod.reference_rate is then a rod strain rate).
//
// The temperature is the mean of the rod's two ends' (Particles::temperature, filled by the
// ThermalSystem; 0 = not set, read as T_ref). The kernel reads it when the law's trait
// kReadsTemperature says so; it is that of the step's start and does not change during a step's
// tries (thermal_system.h), so the tangent has no temperature term. Without a temperature field
// (no [heat]) evaluate's four-argument form applies: T = T_ref, Theta = 1.
//
// At S = 1 (rate up to rate_ref and T <= T_ref) evaluate returns the base law's evaluation, bit
// for bit. Failure (tensile_strength, failure_strain) is the base law's, unscaled: Johnson-Cook's
// failure model has its own rate and temperature terms (D4, D5), not these.
//
// The linear law in terms of the plastic strain: eps_p = (E - k)/E eps0 and the back stress is
// alpha = k eps0 (H eps_p with H = E k/(E - k)); on the band's edge
//     E eps - (E - k) q = S (k q +- s_y)   =>   q = (E eps -+ S s_y) / (E - k + S k),
// and the plastic tangent is E S k / (E - k + S k) (k at S = 1). The hardening curve's return map
// is the unscaled one with the modulus E / S (evaluate_flow_curve), its tangent S E H / (E + S H).
// Plasticity is committed by the rods' commit as for every law (only after a converged step):
// evaluate changes nothing.
#pragma once

#include <algorithm>
#include <cmath>

#include "swarf/core/series_log.h"
#include "swarf/laws/rod_law.h"

namespace swarf {

/// The paper's law (or its hardening curve) with its flow stresses scaled by the strain rate and
/// the temperature.
struct JohnsonCookRodLaw {
  BilinearRodLaw base;                    ///< the law at rate_ref and T_ref (S = 1), SI units as there
  double rate_sensitivity = 0.0;          ///< C of the rate factor, 1, >= 0
  double reference_rate = 1.0;            ///< rate_ref (equivalent rate) up to which R = 1, 1/s, > 0
  double rate_to_equivalent = 1.0;        ///< kappa: equivalent plastic strain rate per rod strain rate, 1, > 0
  double softening_exponent = 1.0;        ///< m of the thermal factor, 1, > 0
  double melt_temperature = HUGE_VAL;     ///< T_melt, K (inf: no softening)
  double reference_temperature = 293.15;  ///< T_ref, K, < T_melt; a particle at 0 K (not set) is read as this

  /// The tangent reads the trial's strain and rate (d sigma / d rate is not the viscosity alone).
  static constexpr bool kTangentReadsMotion = true;
  /// The kernel gives evaluate and tangent the rod's temperature (the mean of its ends').
  static constexpr bool kReadsTemperature = true;
};

/// The rate factor R = 1 + C ln(max(kappa |rate| / rate_ref, 1)) of a rod strain rate, 1.
/// Branch-free and with the series logarithm (core/series_log.h), so that the rod kernel computes
/// it for a vector of rods at once; below rate_ref ln(max(x, 1)) = 0 exactly and R = 1.
inline double rate_factor(const JohnsonCookRodLaw& law, double strain_rate) {
  const double x = law.rate_to_equivalent * std::fabs(strain_rate) / law.reference_rate;
  return 1.0 + law.rate_sensitivity * series_log_at_least_one(x);
}

/// The homologous temperature T* = clamp((T - T_ref)/(T_melt - T_ref), 0, 1) of a rod at T (K), 1;
/// at or below T_ref (also T = 0, not set) T* = 0. Written as a quotient computed always and
/// selects of it, which a vector loop runs (an early return or a conditional division keeps it
/// scalar).
inline double homologous_temperature(const JohnsonCookRodLaw& law, double temperature) {
  const double t_ref = law.reference_temperature;
  double ts = (temperature - t_ref) / (law.melt_temperature - t_ref);
  ts = ts < 0.0 ? 0.0 : ts;
  return ts > 1.0 ? 1.0 : ts;
}

/// Theta for m = 1 (the steels' exponent), without the call to pow: a vector loop can run it.
inline double linear_thermal_factor(const JohnsonCookRodLaw& law, double temperature) {
  const double theta = 1.0 - homologous_temperature(law, temperature);
  return theta < 1e-3 ? 1e-3 : theta;
}

/// The thermal factor Theta = max(1 - T*^m, 1e-3) at the rod temperature T (K), 1; Theta = 1 at
/// or below T_ref.
inline double thermal_factor(const JohnsonCookRodLaw& law, double temperature) {
  if (law.softening_exponent == 1.0) return linear_thermal_factor(law, temperature);  // (pow(x, 1) is x)
  return std::max(1.0 - std::pow(homologous_temperature(law, temperature), law.softening_exponent), 1e-3);
}

/// The flow stress scale S = R(rate) Theta(T) of a rod at its strain rate (1/s) and temperature (K).
inline double flow_scale(const JohnsonCookRodLaw& law, double strain_rate, double temperature) {
  return rate_factor(law, strain_rate) * thermal_factor(law, temperature);
}

/// A rod's temperature from its ends' (0 = not set: T_ref), K.
inline double rod_temperature(const JohnsonCookRodLaw& law, double ti, double tj) {
  const double t_ref = law.reference_temperature;
  return 0.5 * ((ti > 0.0 ? ti : t_ref) + (tj > 0.0 ? tj : t_ref));
}

/// Whether the temperature can change the law (a finite T_melt): the kernel gathers it only then.
inline bool reads_temperature(const JohnsonCookRodLaw& law) { return std::isfinite(law.melt_temperature); }

/// The law at a fixed flow-stress scale S (the trial; nothing committed changes).
inline RodResponse evaluate_scaled(const JohnsonCookRodLaw& law, double strain, double strain_rate, double shift,
                                   double S) {
  const BilinearRodLaw& b = law.base;
  if (S == 1.0) return evaluate(b, strain, strain_rate, shift);
  if (b.flow.points > 0) return evaluate_flow_curve(b, strain, strain_rate, shift, S);
  const double E = b.youngs_modulus, k = b.hardening, sy = E * b.yield_strain;
  RodResponse r;
  r.shift = shift;
  const double trial = E * strain - (E - k) * shift;
  const double centre = S * k * shift, half = S * sy;
  if (trial > centre + half || trial < centre - half) {
    const double edge = trial > centre ? half : -half;
    r.shift = (E * strain - edge) / (E - k + S * k);
    r.stress = E * strain - (E - k) * r.shift;
  } else {
    r.stress = trial;
  }
  r.viscous_stress = b.viscosity * strain_rate;
  r.broken = strain > 0.0 && (r.stress > b.tensile_strength || strain > b.failure_strain);
  return r;
}

/// The law at the rod temperature T (K).
inline RodResponse evaluate(const JohnsonCookRodLaw& law, double strain, double strain_rate, double shift,
                            double temperature) {
  return evaluate_scaled(law, strain, strain_rate, shift,
                         rate_factor(law, strain_rate) * thermal_factor(law, temperature));
}

/// The law at T_ref (no temperature field).
inline RodResponse evaluate(const JohnsonCookRodLaw& law, double strain, double strain_rate, double shift) {
  return evaluate_scaled(law, strain, strain_rate, shift, rate_factor(law, strain_rate));
}

/// The plastic branch's slope at the trial state and the scale S, Pa.
inline double plastic_tangent(const JohnsonCookRodLaw& law, double trial_shift, double S) {
  const BilinearRodLaw& b = law.base;
  const double E = b.youngs_modulus;
  if (b.flow.points > 0) return S * b.flow.plastic_tangent(E / S, trial_shift);
  return E * S * b.hardening / (E - b.hardening + S * b.hardening);
}

/// The slopes of a trial at the rod temperature T (constant over the step). On the plastic branch
/// above rate_ref the stress also grows with the rate: at a fixed strain d sigma / dS =
/// (sigma / S) (1 - E_t / E) (both forms of the law; E_t the plastic tangent) and
/// dS / d rate = Theta C / rate, so d sigma / d rate = (sigma / R) (1 - E_t / E) C / rate.
inline RodTangent tangent(const JohnsonCookRodLaw& law, double strain, double strain_rate, double shift,
                          double trial_shift, double temperature) {
  if (trial_shift == shift) return tangent(law.base, strain, strain_rate, shift, trial_shift);
  const double R = rate_factor(law, strain_rate), S = R * thermal_factor(law, temperature);
  if (R == 1.0 && S == 1.0) return tangent(law.base, strain, strain_rate, shift, trial_shift);  // (the base's bits)
  const double E = law.base.youngs_modulus, Et = plastic_tangent(law, trial_shift, S);
  if (R == 1.0) return {Et, law.base.viscosity};
  const double sigma = evaluate_scaled(law, strain, strain_rate, shift, S).stress;
  return {Et, law.base.viscosity + sigma / R * (1.0 - Et / E) * law.rate_sensitivity / strain_rate};
}

/// The slopes at T_ref.
inline RodTangent tangent(const JohnsonCookRodLaw& law, double strain, double strain_rate, double shift,
                          double trial_shift) {
  return tangent(law, strain, strain_rate, shift, trial_shift, law.reference_temperature);
}

/// The slopes of a trial evaluated at a fixed scale S (evaluate_scaled) computed from a rate that
/// the trial does not change: Newton's lagged rate factor (integrate/newton.cpp), R read at the
/// rod's rate at the step's start. Then d S / d rate = 0 and the only rate term is the viscosity;
/// E_t is the plastic branch's slope at S (the base law's tangent, bit for bit, at S = 1).
inline RodTangent tangent_at_scale(const JohnsonCookRodLaw& law, double shift, double trial_shift, double S) {
  if (trial_shift == shift || S == 1.0) return tangent(law.base, 0.0, 0.0, shift, trial_shift);
  return {plastic_tangent(law, trial_shift, S), law.base.viscosity};
}

// The state means what it means in the base law (the same eps_p = (E - k)/E eps0 at every rate
// and temperature), so the plastic strain, the plastic work and the elastic energy are the base
// law's.
inline double plastic_strain(const JohnsonCookRodLaw& law, double shift) { return plastic_strain(law.base, shift); }
inline double plastic_work_density(const JohnsonCookRodLaw& law, double stress, double dshift) {
  return plastic_work_density(law.base, stress, dshift);
}
inline double elastic_energy_density(const JohnsonCookRodLaw& law, double stress) {
  return elastic_energy_density(law.base, stress);
}
inline double elastic_modulus(const JohnsonCookRodLaw& law) { return elastic_modulus(law.base); }
// (the scaled law keeps sigma = E eps - (E - k) q, and E (eps - q) on the hardening curve)
inline double shift_modulus(const JohnsonCookRodLaw& law) { return shift_modulus(law.base); }
inline bool uses_rate(const JohnsonCookRodLaw& law) { return law.rate_sensitivity != 0.0 || uses_rate(law.base); }

/// The base law with its flow stresses scaled by a fixed S: the same responses as the law at a
/// constant rate and temperature whose factors make S (for the hardening curve exactly the same
/// return map, to rounding; for the single slope the law with H and s_y scaled, written in its
/// own shift). The material lab runs its crystal with it at --temperature and --strain-rate.
inline BilinearRodLaw scaled_base(const JohnsonCookRodLaw& law, double S) {
  BilinearRodLaw b = law.base;
  if (b.flow.points > 0) {
    for (int i = 0; i < b.flow.points; ++i) b.flow.stress[i] *= S;
    b.yield_strain *= S;
    return b;
  }
  // The single slope: alpha = H eps_p with H = E k/(E - k); scaled, H' = S H, k' = E H'/(E + H').
  const double E = b.youngs_modulus, H = E * b.hardening / (E - b.hardening);
  b.hardening = E * S * H / (E + S * H);
  // The band's half-width in stress is s_y = E eps_y in the shift form (|sigma - k eps0| <= E eps_y
  // on the elastic branch); its scaled value S s_y.
  b.yield_strain *= S;
  return b;
}

inline RodLawDescription describe(const JohnsonCookRodLaw& law) {
  RodLawDescription d = describe(law.base);
  d.name = "johnson_cook";
  d.parameters.push_back({"rate_sensitivity", "1", {law.rate_sensitivity}});
  d.parameters.push_back({"reference_rate", "1/s", {law.reference_rate}});
  d.parameters.push_back({"rate_to_equivalent", "1", {law.rate_to_equivalent}});
  d.parameters.push_back({"thermal_softening_exponent", "1", {law.softening_exponent}});
  d.parameters.push_back({"melt_temperature", "K", {law.melt_temperature}});
  d.parameters.push_back({"reference_temperature", "K", {law.reference_temperature}});
  return d;
}

}  // namespace swarf

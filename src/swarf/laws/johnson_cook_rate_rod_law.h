// johnson_cook_rate_rod_law.h: the paper's rod law with Johnson-Cook strain-rate hardening
// (issue 33: the cutting speed must change the flow stress).
//
// Johnson and Cook (1983) scale the whole flow stress, (A + B eps_p^n), by the rate factor
//     R = 1 + C ln(max(|rate| / rate_ref, 1))          [1]
// with C [1] and rate_ref [1/s] the law's parameters. Here it scales the kinematic law's flow
// stresses (rod_law.h): the band |sigma - R alpha(eps_p)| <= R s_y, yield stress and back stress
// alike, so that the monotonic curve at a constant rate is R times the quasi-static one and the
// band keeps its width 2 R s_y (the Bauschinger effect as in the paper, at the rate's stress
// level). Scaling only the band's half-width at fixed strain, the other reading of "the yield
// band scales", would leave the hardening unscaled; that is not Johnson-Cook, and a linear law
// would then answer a rate differently from the same law written as a two-point curve.
//
// The rate is the rod's total strain rate, not its plastic strain rate: the law stays a pure
// function of (strain, rate, committed shift) with the one per-rod state of the paper's law
// (the shift), and at the constant rates where the factor is measured the two rates agree once
// the rod flows. Below rate_ref (R = 1) the law IS the paper's law: evaluate returns the base
// law's evaluation, bit for bit. Failure (tensile_strength, failure_strain) is the base law's,
// unscaled: Johnson-Cook's failure model has its own rate term (D4), not this one.
//
// The linear law in terms of the plastic strain: eps_p = (E - k)/E eps0 and the back stress is
// alpha = k eps0 (H eps_p with H = E k/(E - k)); on the band's edge
//     E eps - (E - k) q = R (k q +- s_y)   =>   q = (E eps -+ R s_y) / (E - k + R k),
// and the plastic tangent is E R k / (E - k + R k) (k at R = 1). The hardening curve's return map
// is the unscaled one with the modulus E / R (evaluate_flow_curve), its tangent R E H / (E + R H).
#pragma once

#include <cmath>

#include "swarf/laws/rod_law.h"

namespace swarf {

/// The paper's law (or its hardening curve) with its flow stresses scaled by the strain rate.
struct JohnsonCookRateRodLaw {
  BilinearRodLaw base;            ///< the quasi-static law (R = 1), SI units as there
  double rate_sensitivity = 0.0;  ///< C of the rate factor, 1, >= 0
  double reference_rate = 1.0;    ///< rate_ref below which the law is the quasi-static one, 1/s, > 0

  /// The tangent reads the trial's strain and rate (d sigma / d rate is not the viscosity alone).
  static constexpr bool kTangentReadsMotion = true;
};

/// The rate factor R = 1 + C ln(max(|rate| / rate_ref, 1)), 1.
inline double rate_factor(const JohnsonCookRateRodLaw& law, double strain_rate) {
  const double x = std::fabs(strain_rate) / law.reference_rate;
  return x > 1.0 ? 1.0 + law.rate_sensitivity * std::log(x) : 1.0;
}

inline RodResponse evaluate(const JohnsonCookRateRodLaw& law, double strain, double strain_rate, double shift) {
  const double R = rate_factor(law, strain_rate);
  const BilinearRodLaw& b = law.base;
  if (R == 1.0) return evaluate(b, strain, strain_rate, shift);
  if (b.flow.points > 0) return evaluate_flow_curve(b, strain, strain_rate, shift, R);
  const double E = b.youngs_modulus, k = b.hardening, sy = E * b.yield_strain;
  RodResponse r;
  r.shift = shift;
  const double trial = E * strain - (E - k) * shift;
  const double centre = R * k * shift, half = R * sy;
  if (trial > centre + half || trial < centre - half) {
    const double edge = trial > centre ? R * sy : -R * sy;
    r.shift = (E * strain - edge) / (E - k + R * k);
    r.stress = E * strain - (E - k) * r.shift;
  } else {
    r.stress = trial;
  }
  r.viscous_stress = b.viscosity * strain_rate;
  r.broken = strain > 0.0 && (r.stress > b.tensile_strength || strain > b.failure_strain);
  return r;
}

/// The plastic branch's slope at the trial state and the rate factor R, Pa.
inline double plastic_tangent(const JohnsonCookRateRodLaw& law, double trial_shift, double R) {
  const BilinearRodLaw& b = law.base;
  const double E = b.youngs_modulus;
  if (b.flow.points > 0) return R * b.flow.plastic_tangent(E / R, trial_shift);
  return E * R * b.hardening / (E - b.hardening + R * b.hardening);
}

/// The slopes of a trial. On the plastic branch above rate_ref the stress also grows with the
/// rate: at a fixed strain d sigma / dR = (sigma / R) (1 - E_t / E) (both forms of the law; E_t
/// the plastic tangent) and dR / d rate = C / rate.
inline RodTangent tangent(const JohnsonCookRateRodLaw& law, double strain, double strain_rate, double shift,
                          double trial_shift) {
  const double R = rate_factor(law, strain_rate);
  if (R == 1.0 || trial_shift == shift) return tangent(law.base, strain, strain_rate, shift, trial_shift);
  const double E = law.base.youngs_modulus, Et = plastic_tangent(law, trial_shift, R);
  const double sigma = evaluate(law, strain, strain_rate, shift).stress;
  return {Et, law.base.viscosity + sigma / R * (1.0 - Et / E) * law.rate_sensitivity / strain_rate};
}

// The state means what it means in the base law (the same eps_p = (E - k)/E eps0 at every rate),
// so the plastic strain, the plastic work and the elastic energy are the base law's.
inline double plastic_strain(const JohnsonCookRateRodLaw& law, double shift) { return plastic_strain(law.base, shift); }
inline double plastic_work_density(const JohnsonCookRateRodLaw& law, double stress, double dshift) {
  return plastic_work_density(law.base, stress, dshift);
}
inline double elastic_energy_density(const JohnsonCookRateRodLaw& law, double stress) {
  return elastic_energy_density(law.base, stress);
}
inline double elastic_modulus(const JohnsonCookRateRodLaw& law) { return elastic_modulus(law.base); }
inline bool uses_rate(const JohnsonCookRateRodLaw& law) { return law.rate_sensitivity != 0.0 || uses_rate(law.base); }

inline RodLawDescription describe(const JohnsonCookRateRodLaw& law) {
  RodLawDescription d = describe(law.base);
  d.name = "johnson_cook_rate";
  d.parameters.push_back({"rate_sensitivity", "1", {law.rate_sensitivity}});
  d.parameters.push_back({"reference_rate", "1/s", {law.reference_rate}});
  return d;
}

}  // namespace swarf

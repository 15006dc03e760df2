// rod_law.h: the elastic-plastic-viscous rod law with the Bauschinger effect
// (paper section 4.5, eqs. 23-31; docs/physics.md sections 2 to 4).
//
// The paper shifts the symmetric bilinear curve along h(eps) = k eps. That is exactly
// 1-D linear kinematic hardening: the elastic-plastic stress stays inside the band
//     k eps - (E - k) eps_y  <=  sigma  <=  k eps + (E - k) eps_y
// and moves with slope E between its edges. The state is one number, the shift eps0
// (sigma0 = k eps0, eq. 27); the stress is sigma = k eps0 + E (eps - eps0)  (eq. 29).
// When the elastic trial leaves the band it is clamped to the band edge and the shift
// follows from eq. 26: eps0 = (E eps - sigma) / (E - k).
//
// evaluate() is a pure function of (strain, strain rate, committed shift): it returns the
// trial shift and a trial break flag and changes nothing, so that an implicit step can
// iterate and commit only the converged state.
//
// The law in one file, and what every rod law brings (any_rod_law.h lists them; the kernels
// take the law as a template parameter, so these are plain inline calls in their loops):
//   evaluate(law, strain, rate, shift) -> RodResponse   the trial
//   tangent(law, strain, rate, shift, trial_shift)     d sigma/d eps and d sigma/d rate of it
//   plastic_tangent(law, trial_shift)                   the plastic branch's slope
//   plastic_strain(law, shift)                          the rod's plastic strain from its state
//   plastic_work_density(law, stress, dshift)           what a commit of dshift dissipates
//   elastic_energy_density(law, stress)                 the recoverable energy
//   elastic_modulus(law)                                the small-strain modulus E
//   shift_modulus(law)                                  d sigma / d shift at a fixed strain, negated
//   uses_rate(law)                                      whether evaluate reads the strain rate
//   describe(law)                                       name and parameters with units (echo)
// A law with the trait kReadsTemperature also has evaluate and tangent with a last argument, the
// rod's temperature in K (the kernels pass the mean of its ends' Particles::temperature).
// Consumers call these and never read a law's fields, so a second law cannot be misread.
// Its state per rod is the shift (Rods::shift); the commit writes the converged evaluation's
// shift and break flag back.
//
// Two options a ductile metal needs (the trusted-cut issue; docs/case-reference.md):
// - a piecewise-linear hardening curve (flow_curve.h) in place of the single slope k. Its
//   back stress is a function of the plastic strain, and the rod's state is then the plastic
//   strain itself (k = 0 makes eps0 = eps_p): the same kinematic construction, the same commit.
// - failure by the rod's strain in tension (failure_strain), besides the paper's stress
//   criterion: a saturating flow curve may never reach sigma_max, and a metal fails by strain.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "swarf/laws/flow_curve.h"

namespace swarf {

/// Parameters of one rod family (the paper's law). All SI units.
struct BilinearRodLaw {
  double youngs_modulus = 0.0;       ///< E of the rod, Pa
  double yield_strain = 0.0;         ///< eps_y = sigma_02 / E, 1 (may be +inf: no plasticity)
  double hardening = 0.0;            ///< slope k of the plastic branch, Pa, 0 <= k < E
  double tensile_strength = 0.0;     ///< sigma_max, Pa (may be +inf: unbreakable)
  double viscosity = 0.0;            ///< eta: viscous stress = eta * strain rate, Pa s
  double failure_strain = HUGE_VAL;  ///< rod strain in tension at which it fails, 1 (inf: never)
  FlowCurve flow;                    ///< piecewise-linear hardening; when it has points, hardening = 0 and the
                                     ///< shift is the plastic strain

  /// The tangent reads only the trial's shifts (forces/rod_tangent.cpp gathers no velocities).
  static constexpr bool kTangentReadsMotion = false;
  /// evaluate and tangent take no temperature (a thermal law's take the rod's: johnson_cook_rod_law.h).
  static constexpr bool kReadsTemperature = false;

  /// Half-width of the elastic band in stress, (E - k) eps_y, Pa.
  double band_half_width() const { return (youngs_modulus - hardening) * yield_strain; }
};

/// The name most of the code knows the paper's law by.
using RodLaw = BilinearRodLaw;

/// Result of one evaluation of the law. The shift and break flag are TRIAL values.
struct RodResponse {
  double stress = 0.0;          ///< elastic-plastic stress sigma, Pa (positive in tension)
  double viscous_stress = 0.0;  ///< eta * strain rate, Pa
  double shift = 0.0;           ///< trial shift eps0 after this evaluation, 1
  bool broken = false;          ///< sigma > sigma_max in tension: the rod fails
};

/// The slopes of the stress of one trial, for the implicit step's Jacobian (forces/rod_tangent.h).
struct RodTangent {
  double stiffness = 0.0;  ///< d sigma / d eps at the trial, Pa
  double damping = 0.0;    ///< d (sigma + sigma_v) / d rate at the trial, Pa s
};

/// One parameter of a law as the setup report, summary.json and the material lab echo it.
struct LawParameter {
  std::string name;            ///< as the case key spells it (rod.<name>)
  std::string unit;            ///< "Pa", "1", "Pa s", "1/s"
  std::vector<double> values;  ///< one value, or a table's points (may be empty: no table)
  bool table = false;          ///< a table (echoed as a list even with one point or none)
};

/// What describe() gives: the law's name as `rod.law` selects it and its parameters.
struct RodLawDescription {
  std::string name;
  std::vector<LawParameter> parameters;
};

/// The law with a hardening curve: the state is the plastic strain p, the stress E (eps - p),
/// the band alpha(p) +- s_y (flow_curve.h), both scaled by 'scale' (1 for this law; a rate or
/// temperature factor for a law built on this one, as Johnson-Cook's). With the scale R the
/// return map solves E (eps - q) = R (alpha(q) + s_y), which is the unscaled curve's map with
/// the modulus E / R. (A literal 1 folds away: the multiplications and the division by it are
/// exact, so this law's bits and cost are those of the unscaled code.)
inline RodResponse evaluate_flow_curve(const BilinearRodLaw& law, double strain, double strain_rate, double p,
                                       double scale = 1.0) {
  const double E = law.youngs_modulus;
  const FlowCurve& f = law.flow;
  RodResponse r;
  r.shift = p;
  const double trial = E * (strain - p);
  // (a rod that never yielded, most of a workpiece, has alpha(0) = 0 exactly: no search, no
  // division; the same bits)
  const double centre = p == 0.0 ? 0.0 : scale * f.back_stress(p), half = scale * f.stress[0];
  if (trial > centre + half || trial < centre - half) r.shift = f.return_map(E / scale, strain, p, trial > centre);
  r.stress = E * (strain - r.shift);
  r.viscous_stress = law.viscosity * strain_rate;
  r.broken = strain > 0.0 && (r.stress > law.tensile_strength || strain > law.failure_strain);
  return r;
}

/// The law itself. 'shift' is the committed eps0 of the rod.
inline RodResponse evaluate(const BilinearRodLaw& law, double strain, double strain_rate, double shift) {
  const double E = law.youngs_modulus;
  if (law.flow.points > 0) return evaluate_flow_curve(law, strain, strain_rate, shift);
  const double k = law.hardening;
  RodResponse r;
  r.shift = shift;
  const double trial = k * shift + E * (strain - shift);
  const double centre = k * strain;
  const double half = law.band_half_width();
  if (trial > centre + half) {
    r.stress = centre + half;
    r.shift = (E * strain - r.stress) / (E - k);
  } else if (trial < centre - half) {
    r.stress = centre - half;
    r.shift = (E * strain - r.stress) / (E - k);
  } else {
    r.stress = trial;
  }
  r.viscous_stress = law.viscosity * strain_rate;
  // Failure only in tension (eq. 31 and the paper's remark below it).
  r.broken = strain > 0.0 && (r.stress > law.tensile_strength || strain > law.failure_strain);
  return r;
}

/// The slope d sigma / d eps of the plastic branch the trial state 'trial_shift' lies on, Pa.
inline double plastic_tangent(const BilinearRodLaw& law, double trial_shift) {
  return law.flow.points > 0 ? law.flow.plastic_tangent(law.youngs_modulus, trial_shift) : law.hardening;
}

/// The slopes of the trial that moved the committed 'shift' to 'trial_shift': E on the elastic
/// branch (the shift kept), the plastic branch's slope otherwise; the viscosity is the only
/// rate term. (strain and rate are not needed by this law; a rate-dependent one reads them.)
inline RodTangent tangent(const BilinearRodLaw& law, double /*strain*/, double /*rate*/, double shift,
                          double trial_shift) {
  return {trial_shift != shift ? plastic_tangent(law, trial_shift) : law.youngs_modulus, law.viscosity};
}

/// The rod's plastic strain eps_p = eps - sigma/E = (E - k)/E eps0 from its state, 1 (with a
/// hardening curve k = 0 and the state is eps_p itself).
inline double plastic_strain(const BilinearRodLaw& law, double shift) {
  const double E = law.youngs_modulus;
  return E > 0 ? (E - law.hardening) / E * shift : 0.0;
}

/// Plastic work density of committing a change 'dshift' of the shift at stress sigma, J/m^3:
/// sigma d(eps_p), the plastic strain being eps_p = (E - k)/E eps0 (docs/physics.md sections 2 to 4).
inline double plastic_work_density(const BilinearRodLaw& law, double stress, double dshift) {
  return stress * ((law.youngs_modulus - law.hardening) / law.youngs_modulus) * dshift;
}

/// How far the stress falls per unit of shift at a fixed strain, Pa: sigma = E eps - (E - k) eps0
/// for the single slope, E (eps - eps0) for the hardening curve.
inline double shift_modulus(const BilinearRodLaw& law) {
  return law.flow.points > 0 ? law.youngs_modulus : law.youngs_modulus - law.hardening;
}

/// Recoverable elastic energy density of a rod at stress sigma, J/m^3 (sigma^2 / 2E).
inline double elastic_energy_density(const BilinearRodLaw& law, double stress) {
  return 0.5 * stress * stress / law.youngs_modulus;
}

/// The rod's small-strain modulus E, Pa (the lattice's elastic constants follow from it).
inline double elastic_modulus(const BilinearRodLaw& law) { return law.youngs_modulus; }

/// Whether evaluate reads the strain rate: only through the viscous part here (the kernel
/// gathers no velocities for an undamped rod).
inline bool uses_rate(const BilinearRodLaw& law) { return law.viscosity != 0.0; }

/// The parameters under their case keys' names (the hardening curve's two tables are empty
/// for the single slope).
inline RodLawDescription describe(const BilinearRodLaw& law) {
  const FlowCurve& f = law.flow;
  return {"bilinear",
          {{"youngs_modulus", "Pa", {law.youngs_modulus}},
           {"yield_strain", "1", {law.yield_strain}},
           {"hardening_modulus", "Pa", {law.hardening}},
           {"tensile_strength", "Pa", {law.tensile_strength}},
           {"failure_strain", "1", {law.failure_strain}},
           {"viscosity", "Pa s", {law.viscosity}},
           {"flow_plastic_strain", "1", {f.plastic_strain.begin(), f.plastic_strain.begin() + f.points}, true},
           {"flow_stress", "Pa", {f.stress.begin(), f.stress.begin() + f.points}, true}}};
}

}  // namespace swarf

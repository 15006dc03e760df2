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
// The law in one file: its parameters (RodLaw), its state per rod (the shift, Rods::shift),
// the trial (evaluate), the commit rule (the converged evaluation's shift and break flag are
// written back; plastic_work_density is what that commit dissipates) and the energy
// (elastic_energy_density). The rod kernel (forces/rod_forces.cpp) is a template on the law.
//
// Two options a ductile metal needs (the trusted-cut issue; docs/case-reference.md):
// - a piecewise-linear hardening curve (flow_curve.h) in place of the single slope k. Its
//   back stress is a function of the plastic strain, and the rod's state is then the plastic
//   strain itself (k = 0 makes eps0 = eps_p): the same kinematic construction, the same commit.
// - failure by the rod's strain in tension (failure_strain), besides the paper's stress
//   criterion: a saturating flow curve may never reach sigma_max, and a metal fails by strain.
#pragma once

#include <cmath>

#include "swarf/laws/flow_curve.h"

namespace swarf {

/// Parameters of one rod family. All SI units.
struct RodLaw {
  double youngs_modulus = 0.0;       ///< E of the rod, Pa
  double yield_strain = 0.0;         ///< eps_y = sigma_02 / E, 1 (may be +inf: no plasticity)
  double hardening = 0.0;            ///< slope k of the plastic branch, Pa, 0 <= k < E
  double tensile_strength = 0.0;     ///< sigma_max, Pa (may be +inf: unbreakable)
  double viscosity = 0.0;            ///< eta: viscous stress = eta * strain rate, Pa s
  double failure_strain = HUGE_VAL;  ///< rod strain in tension at which it fails, 1 (inf: never)
  FlowCurve flow;                    ///< piecewise-linear hardening; when it has points, hardening = 0 and the
                                     ///< shift is the plastic strain

  /// Half-width of the elastic band in stress, (E - k) eps_y, Pa.
  double band_half_width() const { return (youngs_modulus - hardening) * yield_strain; }
};

/// Result of one evaluation of the law. The shift and break flag are TRIAL values.
struct RodResponse {
  double stress = 0.0;          ///< elastic-plastic stress sigma, Pa (positive in tension)
  double viscous_stress = 0.0;  ///< eta * strain rate, Pa
  double shift = 0.0;           ///< trial shift eps0 after this evaluation, 1
  bool broken = false;          ///< sigma > sigma_max in tension: the rod fails
};

/// The law with a hardening curve: the state is the plastic strain p, the stress E (eps - p),
/// the band alpha(p) +- s_y (flow_curve.h).
inline RodResponse evaluate_flow_curve(const RodLaw& law, double strain, double strain_rate, double p) {
  const double E = law.youngs_modulus;
  const FlowCurve& f = law.flow;
  RodResponse r;
  r.shift = p;
  const double trial = E * (strain - p);
  const double centre = f.back_stress(p), half = f.stress[0];
  if (trial > centre + half || trial < centre - half) r.shift = f.return_map(E, strain, p, trial > centre);
  r.stress = E * (strain - r.shift);
  r.viscous_stress = law.viscosity * strain_rate;
  r.broken = strain > 0.0 && (r.stress > law.tensile_strength || strain > law.failure_strain);
  return r;
}

/// The law itself. 'shift' is the committed eps0 of the rod.
inline RodResponse evaluate(const RodLaw& law, double strain, double strain_rate, double shift) {
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
inline double plastic_tangent(const RodLaw& law, double trial_shift) {
  return law.flow.points > 0 ? law.flow.plastic_tangent(law.youngs_modulus, trial_shift) : law.hardening;
}

/// Plastic work density of committing a change 'dshift' of the shift at stress sigma, J/m^3:
/// sigma d(eps_p), the plastic strain being eps_p = (E - k)/E eps0 (docs/physics.md sections 2 to 4).
inline double plastic_work_density(const RodLaw& law, double stress, double dshift) {
  return stress * ((law.youngs_modulus - law.hardening) / law.youngs_modulus) * dshift;
}

/// Recoverable elastic energy density of a rod at stress sigma, J/m^3 (sigma^2 / 2E).
inline double elastic_energy_density(const RodLaw& law, double stress) {
  return 0.5 * stress * stress / law.youngs_modulus;
}

}  // namespace swarf

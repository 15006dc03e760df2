// derived.cpp: the derived quantities and lattice relations (see derived.h).
#include "setup/derived.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "lattice_gen/fcc_lattice.h"
#include "lattice_gen/membrane_lattice.h"
#include "setup/calibration.h"
#include "setup/rod_laws/rod_laws.h"
#include "swarf/core/errors.h"
#include "swarf/laws/bond_formation.h"

namespace swarf {

// Contacts: the stable step is at most a fifth of the Rayleigh time pi R sqrt(rho/G) /
// (0.1631 nu + 0.8766) of the smallest particle (rho the density of a solid sphere of that mass).
static void limit_by_contacts(const CaseSettings& cs, Derived& d) {
  if (!cs.contact.enabled) return;
  const double nu = cs.contact.poisson_ratio, G = cs.contact.youngs_modulus / (2.0 * (1.0 + nu));
  const double R = d.radius, rho_s = d.particle_mass / (4.0 / 3.0 * M_PI * R * R * R);
  d.rayleigh_time = M_PI * R * std::sqrt(rho_s / G) / (0.1631 * nu + 0.8766);
  d.dt_stable = std::min(d.dt_stable, 0.2 * d.rayleigh_time);
}

// The step, and the Newmark step's bounds, from the stable step in 'd'; 'modal' and 'zeta' only
// name the stable step's terms in the message that refuses an explicit step beyond it.
static Derived choose_step(const CaseSettings& cs, Derived d, double modal, double zeta) {
  const double m = d.particle_mass, kb = d.rod_stiffness, R = d.radius;
  const auto& g = cs.integrator;
  const bool newton = g.solver == "newton";
  // "auto" is Verlet unless the Newton solver is named (it solves only the Newmark step): measured
  // on the cut at 0.3-10 m/s, the fixed-point Newmark step costs 2.3-4.2 times Verlet's wall time
  // and Newton 1.3-2.8 times, with the same forces (validation/integrators/README.md).
  d.implicit = g.scheme == "newmark" || (g.scheme == "auto" && newton);
  d.dt = g.dt > 0 ? g.dt : g.dt_safety * d.dt_stable;
  d.dt_min = g.dt_min > 0 ? g.dt_min : 1e-3 * d.dt_stable;
  // A sweep contracts by about 4 beta (dt/dt_stable)^2: the default keeps that at 0.64
  // (0.8 of the stable step for beta = 1/4).
  // Newton converges beyond the explicit limit; its default and its cap (the Krylov
  // iterations grow with dt / dt_stable, and accuracy, not stability, bounds the step).
  constexpr double kNewtonDtMax = 10.0, kNewtonDtCap = 20.0;  // x dt_stable
  d.dt_max = g.dt_max > 0 ? g.dt_max : (newton ? kNewtonDtMax : 0.4 / std::sqrt(g.beta)) * d.dt_stable;
  if (newton && d.dt_max > kNewtonDtCap * d.dt_stable)
    throw InputError(
        fmt::format("{}: integrator.dt_max = {:.6g} s exceeds {} x the stable step ({:.6g} s), the most "
                    "the Newton solver allows",
                    cs.source, d.dt_max, kNewtonDtCap, kNewtonDtCap * d.dt_stable));
  // The steps must be finite positive times whatever produced them (an absurd radius,
  // density or modulus makes the stable step 0, inf or NaN, and a NaN step is never "below
  // dt_min": the step control would retry it for ever).
  auto check_time = [&](const char* what, double v, const char* key, bool key_given) {
    if (v > 0.0 && std::isfinite(v)) return;
    if (key_given)
      throw InputError(fmt::format("{}: key 'integrator.{}' = {} s: the {} must be a finite positive time", cs.source,
                                   key, v, what));
    throw InputError(fmt::format(
        "{}: the {} derived from the case is {} s, not a finite positive time (stable step {:.4g} s from particle "
        "mass m = {:.4g} kg, rod stiffness kb = {:.4g} N/m, radius R = {:.4g} m{}): check workpiece.radius, "
        "material.density and the moduli, or set integrator.{}",
        cs.source, what, v, d.dt_stable, m, kb, R,
        cs.contact.enabled ? fmt::format(", Rayleigh time {:.4g} s", d.rayleigh_time) : std::string(), key));
  };
  check_time("step dt", d.dt, "dt", g.dt > 0);
  if (d.implicit) {
    check_time("smallest step dt_min", d.dt_min, "dt_min", g.dt_min > 0);
    check_time("largest step dt_max", d.dt_max, "dt_max", g.dt_max > 0);
  }
  if (d.implicit) {
    if (d.dt < d.dt_min || d.dt > d.dt_max)
      throw InputError(
          fmt::format("{}: the first step dt = {:.6g} s lies outside [dt_min, dt_max] = [{:.6g}, {:.6g}] s "
                      "(integrator.dt, dt_min, dt_max)",
                      cs.source, d.dt, d.dt_min, d.dt_max));
    return d;  // the step control keeps the fixed-point iteration convergent
  }
  if (d.dt > d.dt_stable && !g.allow_unstable_dt)
    throw InputError(
        fmt::format("{}: key 'integrator.dt' = {:.6g} s exceeds the stable step {:.6g} s of the explicit scheme "
                    "((2/omega_max)(sqrt(1+(2 zeta)^2) - 2 zeta), omega_max^2 = {} kb/m, m = {:.4g} kg, kb = {:.4g} "
                    "N/m, zeta = {}); lower dt or set "
                    "integrator.allow_unstable_dt = true to run anyway",
                    cs.source, d.dt, d.dt_stable, modal, m, kb, zeta));
  return d;
}

MembraneRelations membrane_relations_of(const CaseSettings& cs) {
  const MembraneSettings& ms = cs.membrane;
  MembraneMaterial mm;
  mm.spacing = 2.0 * ms.radius;
  mm.modulus_2d = ms.youngs_modulus * ms.thickness;
  mm.poisson_ratio = ms.poisson_ratio;
  mm.areal_density = ms.areal_density > 0 ? ms.areal_density : ms.density * ms.thickness;
  mm.pre_tension = ms.pre_tension;
  try {
    return membrane_relations(mm);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", cs.source, e.what()));
  }
}

// The membrane's sheet: rods of stiffness k (the rod law with plasticity and failure
// off: one law, one kernel, and the dashpot comes with it), the mass per site, the stable step
// of the triangular lattice (omega_max^2 = 6 (k + f/d) / m), and the CFL step of its waves.
static Derived membrane_derived(const CaseSettings& cs, const Lattice& lat, Derived d) {
  const MembraneSettings& ms = cs.membrane;
  const MembraneRelations r = membrane_relations_of(cs);
  d.membrane = true;
  d.cell_edge = 0.0;
  d.particle_mass = r.particle_mass;
  d.rod_area = d.nn_distance * d.nn_distance;  // any area: the rod modulus below makes E A / L0 = k
  const double l0 = lat.rest_length.empty() ? d.nn_distance : lat.rest_length.front();
  d.rod_stiffness = d.rod_stiffness_max = r.bond_stiffness;
  const double kb = r.bond_stiffness, m = r.particle_mass, zeta = ms.damping_ratio;
  d.rod_damping = zeta * 2.0 * std::sqrt(kb * m / 2.0);
  d.rod_viscosity = d.rod_damping * l0 / d.rod_area;
  RodLaw law;
  law.youngs_modulus = kb * l0 / d.rod_area;
  law.yield_strain = kInf;
  law.tensile_strength = kInf;
  law.viscosity = d.rod_viscosity;
  d.law = law;
  d.omega_max = r.omega_max;
  // As for the FCC block (below): the zone-edge mode, omega^2 = modal kb/m, has sqrt(modal/2)
  // times the two-particle mode's damping ratio.
  const double modal = m * r.omega_max * r.omega_max / kb, zeta_max = std::sqrt(modal / 2.0) * zeta;
  d.dt_stable = 2.0 / d.omega_max * (std::sqrt(1.0 + zeta_max * zeta_max) - zeta_max);
  limit_by_contacts(cs, d);
  d.wave_speed = r.wave_longitudinal;
  d.membrane_modulus_2d = ms.youngs_modulus * ms.thickness;
  d.membrane_areal_density = m / r.site_area;
  d.membrane_tension = ms.pre_tension;
  d.membrane_pre_strain = r.pre_strain;
  d.membrane_lambda = r.lambda;
  d.membrane_wave_longitudinal = r.wave_longitudinal;
  d.membrane_wave_shear = r.wave_shear;
  d.membrane_wave_transverse = r.wave_transverse;
  d.membrane_dt_cfl = r.dt_cfl;
  d = choose_step(cs, d, modal, zeta);
  // The waves: a step longer than d / c_L lets a wave cross more than one spacing per step,
  // which the explicit limit already forbids (dt_stable < dt_cfl) but Newmark's control may not.
  const double longest = d.implicit ? d.dt_max : d.dt;
  if (longest > d.membrane_dt_cfl && !cs.integrator.allow_unstable_dt)
    throw InputError(fmt::format(
        "{}: the {} step {:.6g} s exceeds the membrane's CFL step d / c_L = {:.6g} s (c_L = {:.4g} m/s): the "
        "waves are not resolved; lower integrator.{} or set integrator.allow_unstable_dt = true to run anyway",
        cs.source, d.implicit ? "largest" : "explicit", longest, d.membrane_dt_cfl, r.wave_longitudinal,
        d.implicit ? "dt_max" : "dt"));
  return d;
}

Derived compute_derived(const CaseSettings& cs, const Lattice& lat) {
  Derived d;
  if (lat.position.empty() && cs.inflows.empty())
    throw InputError(cs.source + ": the case has no particles (no workpiece, [[particle]], [particles] or [[inflow]])");
  if (cs.membrane.enabled) {
    d.radius = *std::min_element(lat.radius.begin(), lat.radius.end());
    d.nn_distance = 2.0 * d.radius;
    return membrane_derived(cs, lat, d);
  }
  // The smallest particle sets the contacts' step: an inflow's smallest too.
  d.radius = lat.radius.empty() ? HUGE_VAL : *std::min_element(lat.radius.begin(), lat.radius.end());
  for (const auto& f : cs.inflows) d.radius = std::min(d.radius, f.radius_min);
  d.nn_distance = 2.0 * d.radius;
  d.cell_edge = lat.cell_edge > 0 ? lat.cell_edge : std::sqrt(2.0) * d.nn_distance;
  const double R = d.radius, rho = cs.material.density;
  // Free particles (no workpiece) are spheres; lattice particles follow mass_basis.
  d.particle_mass = cs.material.mass_basis == "sphere" || !cs.workpiece.enabled
                        ? rho * 4.0 / 3.0 * M_PI * R * R * R
                        : rho * std::pow(d.nn_distance, 3) / std::sqrt(2.0);
  d.rod_area = cs.rod.area > 0 ? cs.rod.area : M_PI * R * R;
  double l0 = d.nn_distance;
  if (!lat.rest_length.empty()) l0 = *std::min_element(lat.rest_length.begin(), lat.rest_length.end());
  // The rod law: given directly, or derived from macroscopic properties along [100]
  // (docs/physics.md section 1): E100 = 4 kb/(3a), every rod strained by eps/3 in magnitude
  // under uniaxial stress, so sigma_y = 3 E100 eps_y, H = E100 k/E, sigma_f = 3 (E100/E) sigma_max.
  RodSettings rod = cs.rod;
  const double a_cell = d.cell_edge;
  if (cs.material.macroscopic) {
    const auto& mt = cs.material;
    const double kb = 3.0 * a_cell * mt.youngs_modulus / 4.0;
    rod.youngs_modulus = kb * l0 / d.rod_area;
    rod.yield_strain = mt.yield_stress / (3.0 * mt.youngs_modulus);
    rod.hardening_modulus = mt.hardening_modulus * rod.youngs_modulus / mt.youngs_modulus;
    rod.tensile_strength = mt.tensile_strength * rod.youngs_modulus / (3.0 * mt.youngs_modulus);
    d.converted = true;
    if (mt.flow_curve) {
      MacroscopicMaterial macro;
      macro.youngs_modulus = mt.youngs_modulus;
      macro.flow_plastic_strain = mt.flow_plastic_strain;
      macro.flow_stress = mt.flow_stress;
      macro.failure_strain = mt.failure_strain;
      macro.calibration = mt.calibration;
      const RodCalibration c = calibrate_rods(macro, a_cell, d.rod_area, l0);
      rod.youngs_modulus = c.youngs_modulus;
      rod.flow_plastic_strain = c.flow_plastic_strain;
      rod.flow_stress = c.flow_stress;
      rod.failure_strain = c.failure_strain;
      d.calibration_mismatch = c.shear_mismatch;
      d.calibration_points = c.shear_points_reached;
      rod.tensile_strength = mt.tensile_strength * rod.youngs_modulus / (3.0 * mt.youngs_modulus);
    }
  }
  // A failure elongation (m) is a failure strain of the lattice's rod length: the same stretch
  // at every resolution (case-reference.md, rod.failure_elongation).
  if (std::isfinite(cs.rod.failure_elongation)) rod.failure_strain = cs.rod.failure_elongation / l0;
  if (!rod.flow_plastic_strain.empty()) {
    // The hardening curve carries the hardening (the shift is then the plastic strain); its
    // first stress is the yield stress, its first slope the bar's first hardening tangent.
    rod.yield_strain = rod.flow_stress[0] / rod.youngs_modulus;
    rod.hardening_modulus = 0.0;
  }
  const double E = rod.youngs_modulus;
  d.rod_stiffness = E * d.rod_area / l0;
  const double kb = d.rod_stiffness, m = d.particle_mass, zeta = cs.rod.damping_ratio;
  d.rod_damping = zeta * 2.0 * std::sqrt(kb * m / 2.0);
  d.rod_viscosity = d.rod_damping * l0 / d.rod_area;
  // The jitter moves each end of a rod by at most jitter x R, so no rod is shorter than
  // L0 - 2 jitter R: the stable step takes that stiffest rod, whatever the seed (the same step
  // for every repetition of a case). Ordered, kb_max = kb bit for bit.
  const auto& w = cs.workpiece;
  d.disorder_seed = w.enabled ? w.disorder_seed : 0;
  d.position_jitter = w.enabled && w.disorder_seed > 0 ? w.position_jitter : 0.0;
  d.rod_stiffness_max = E * d.rod_area / (l0 - 2.0 * d.position_jitter * R);
  // Bond formation (rod.bond_overlap) lets a flowing particle's 12 rods crowd towards one axis
  // (the FCC lattice spreads them isotropically: sum n n^T = 4 I); the bound of 12 along one
  // axis makes the highest mode omega^2 = 24 kb/m instead of 8 kb/m, the step sqrt(3) shorter.
  const double modal = BondFormation{cs.rod.bond_overlap}.enabled() ? 24.0 : 8.0;
  d.omega_max = std::sqrt(modal * d.rod_stiffness_max / m);
  // The rod dashpots damp like the stiffness (c/kb times K): the modal damping ratio grows
  // with the frequency, and the zone-boundary mode (omega^2 = 8 kb/m) has twice the ratio of
  // the two-particle mode (omega^2 = 2 kb/m) that zeta refers to. Each rod's dashpot is
  // eta A / L0 for its own L0, so the ratio c/k is the same for every rod, and the stiffest
  // rods' mode has sqrt(kb_max/kb) times the ratio.
  const double zeta_max = std::sqrt(modal / 2.0) * zeta * std::sqrt(d.rod_stiffness_max / kb);
  d.dt_stable = lat.rods.empty() ? HUGE_VAL : 2.0 / d.omega_max * (std::sqrt(1.0 + zeta_max * zeta_max) - zeta_max);
  limit_by_contacts(cs, d);
  d.wave_speed = d.nn_distance * std::sqrt(kb / m);

  const double a = d.cell_edge;
  d.c11 = 2.0 * kb / a;
  d.c12 = kb / a;
  d.youngs_modulus_100 = 4.0 * kb / (3.0 * a);
  d.poisson_ratio_100 = 1.0 / 3.0;
  d.youngs_modulus_voigt = 2.0 * kb / a;
  d.bulk_density = m / (a * a * a / 4.0);
  d.bar_stress_factor = 3.0 * d.youngs_modulus_100 / E;
  d.bar_yield_strain = 3.0 * rod.yield_strain;
  d.bar_yield_stress = d.youngs_modulus_100 * d.bar_yield_strain;
  d.bar_hardening_tangent = d.youngs_modulus_100 * rod.hardening_modulus / E;
  if (!rod.flow_plastic_strain.empty()) {
    const double H = (rod.flow_stress[1] - rod.flow_stress[0]) / rod.flow_plastic_strain[1];
    d.bar_hardening_tangent = d.youngs_modulus_100 * (H / (E + H));
  }
  d.bar_failure_stress = d.bar_stress_factor * rod.tensile_strength;

  RodLaw law;
  law.youngs_modulus = E;
  law.yield_strain = rod.yield_strain;
  law.hardening = rod.hardening_modulus;
  law.tensile_strength = rod.tensile_strength;
  law.viscosity = d.rod_viscosity;
  law.failure_strain = rod.failure_strain;
  if (!rod.flow_plastic_strain.empty()) {
    // The hardening curve carries the hardening; its first stress is the yield stress.
    law.flow = make_flow_curve(rod.flow_plastic_strain, rod.flow_stress);
  }
  d.law = rod_law_setup(rod.law).build(law, cs, rod);  // (the law rod.law names: setup/rod_laws/)

  return choose_step(cs, d, modal, zeta);
}

}  // namespace swarf

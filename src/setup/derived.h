// derived.h: every quantity that follows from the case settings, computed in one place.
//
// Particle mass, rod stiffness and damping, the stable step, and the FCC lattice relations
// (docs/physics.md sections 1, 7 and 8) that predict the macroscopic response. Printed at start-up
// and written to summary.json.
#pragma once

#include "setup/case_config.h"
#include "swarf/laws/any_rod_law.h"

namespace swarf {

struct Lattice;

struct Derived {
  double radius = 0;         ///< R (smallest in the lattice), m
  double nn_distance = 0;    ///< d = 2R, m
  double cell_edge = 0;      ///< a = sqrt(2) d, m
  double particle_mass = 0;  ///< m of a particle of radius R, kg
  double rod_area = 0;       ///< A, m^2
  double rod_stiffness = 0;  ///< kb = E A / L0 (shortest rod), N/m
  double rod_damping = 0;    ///< c = zeta 2 sqrt(kb m/2), N s/m
  double rod_viscosity = 0;  ///< eta = c L0 / A, Pa s
  double omega_max = 0;      ///< sqrt(8 kb_max/m) (kb_max below; 24 with bond formation), rad/s
  double dt_stable = 0;      ///< (2/w)(sqrt(1+(2 zeta)^2) - 2 zeta), w = omega_max; sqrt(m/(2 kb)) undamped, s
  double dt = 0;             ///< step used (newmark: the first step), s
  bool implicit = false;     ///< the Newmark scheme (scheme "newmark", or "auto" with solver "newton")
  double dt_min = 0;         ///< newmark: smallest step before the run stops, s
  double dt_max = 0;         ///< newmark: largest step, s
  double wave_speed = 0;     ///< longitudinal wave speed along [100], c_L = d sqrt(kb/m), m/s
  double rayleigh_time = 0;  ///< contacts: pi R sqrt(rho/G)/(0.1631 nu + 0.8766); the stable step uses 0.2 of it, s
  // Lattice relations (central springs kb, cubic cell a).
  double c11 = 0;                   ///< 2 kb / a, Pa
  double c12 = 0;                   ///< kb / a (= C44, Cauchy relation), Pa
  double youngs_modulus_100 = 0;    ///< E along [100] = 4 kb/(3a), Pa
  double poisson_ratio_100 = 0;     ///< 1/3
  double youngs_modulus_voigt = 0;  ///< isotropic (Voigt) average 2 kb / a, Pa
  double bulk_density = 0;          ///< m / (a^3/4), kg/m^3
  // Uniaxial stress along [100]: every rod carries strain eps/3 in magnitude.
  double bar_yield_strain = 0;       ///< 3 eps_y, 1
  double bar_yield_stress = 0;       ///< E100 3 eps_y, Pa
  double bar_hardening_tangent = 0;  ///< E100 k / E, Pa
  double bar_failure_stress = 0;     ///< 3 (E100/E) sigma_max (first rods break), Pa
  double bar_stress_factor = 0;      ///< 3 E100 / E: sigma_bar = factor * sigma_rod(eps_bar/3), 1

  // [membrane] (membrane_lattice.h): the sheet's relations; the rods are the sheet's.
  bool membrane = false;                  ///< the particles are a [membrane]
  double membrane_modulus_2d = 0;         ///< E_2D = E t, N/m
  double membrane_areal_density = 0;      ///< rho_A, kg/m^2
  double membrane_tension = 0;            ///< isotropic pre-tension T, N/m
  double membrane_pre_strain = 0;         ///< rod strain carrying T, 1
  double membrane_lambda = 0;             ///< in-plane Lame constant = mu = sqrt(3) k/4, N/m
  double membrane_wave_longitudinal = 0;  ///< c_L along a rod direction (pre-stress included), m/s
  double membrane_wave_shear = 0;         ///< c_S, m/s
  double membrane_wave_transverse = 0;    ///< c_T = sqrt(T / rho_A), m/s
  double membrane_dt_cfl = 0;             ///< d / c_L: a wave crosses one spacing per step, s

  AnyRodLaw law;                    ///< the rod law with the viscosity filled in
  bool converted = false;           ///< the rod law was derived from [material] macroscopic properties
  double calibration_mismatch = 0;  ///< shear calibration: largest |lattice/flow curve - 1| left, 1
  int calibration_points = 0;       ///< flow-curve points beyond the yield that the shear test reached

  // The disorder (workpiece.disorder_seed, position_jitter; lattice_disorder.h): on when both are > 0.
  int disorder_seed = 0;         ///< as given; 0 = the ordered lattice
  double position_jitter = 0;    ///< largest displacement in radii R, 1; 0 when the disorder is off
  double rod_stiffness_max = 0;  ///< kb_max = E A / (L0 - 2 jitter R), the stiffest rod the jitter can make, N/m
};

/// Computes everything from the settings and the ordered lattice (radii, rest lengths, before
/// the disorder's jitter: the rod law and the lattice relations are those of the ordered block,
/// whatever the seed; only the stable step allows for the jitter's shortest rod). Throws
/// InputError if dt exceeds the stable step and allow_unstable_dt is false.
Derived compute_derived(const CaseSettings& cs, const Lattice& lattice);

struct MembraneRelations;
/// The [membrane]'s relations (membrane_lattice.h); throws InputError naming the case.
MembraneRelations membrane_relations_of(const CaseSettings& cs);

}  // namespace swarf

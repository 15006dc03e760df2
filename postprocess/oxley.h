// oxley.h: Oxley's predictive machining theory for orthogonal cutting with a continuous chip
// (P.L.B. Oxley, "The Mechanics of Machining", Ellis Horwood 1989; with the Johnson-Cook flow
// stress as in Lalwani, Mehta, Jain 2009, "Extension of Oxley's predictive machining theory for
// Johnson and Cook flow stress model", J. Mater. Process. Technol. 209:5305). A physics
// cross-check for the cut's forces, not a simulation: plain structs in, plain struct out.
//
// Model (all angles in rad, lengths in m, speeds in m/s, stresses in Pa, temperatures in K):
//  - Parallel-sided primary shear zone AB of length l_AB = h / sin(phi); shear velocity
//    V_s = V cos(alpha) / cos(phi - alpha), chip velocity V_c = V sin(phi) / cos(phi - alpha).
//  - At AB: strain eps_AB = cos(alpha) / (2 sqrt(3) sin(phi) cos(phi - alpha)), strain rate
//    epsdot_AB = C V_s / (sqrt(3) l_AB), C the strain-rate constant (Oxley 1989, ch. 4).
//  - Temperatures after Boothroyd (Oxley 1989, ch. 5): R_T = rho c V h / k, the fraction of the
//    shear-zone heat conducted into the work beta = 0.5 - 0.35 log10(R_T tan phi) (R_T tan phi
//    up to 10), 0.3 - 0.15 log10(R_T tan phi) above; dT_SZ = (1 - beta) chi F_s V_s /
//    (rho c h V w) (chi the Taylor-Quinney fraction), T_AB = T_0 + eta dT_SZ (eta = 0.9, the
//    part of the zone's rise reached at AB). Chip: dT_C = chi F V_c / (rho c h V w), the maximum
//    rise in the chip dT_M = dT_C 10^(0.06 - 0.195 delta sqrt(R_T h_c / l_c) +
//    0.5 log10(R_T h_c / l_c)), rake-face temperature T_int = T_0 + dT_SZ + psi dT_M (psi = 0.7).
//    Primary zone: k and c at T_AB; chip: at the mean chip temperature T_C = T_0 + dT_SZ + dT_C
//    (Oxley's choice; both solved by bisection, not lagged).
//  - Stress distribution on AB: tan(theta) = 1 + 2 (pi/4 - phi) - C n_eq, n_eq the local strain
//    hardening exponent d ln(sigma) / d ln(eps) of Johnson-Cook at eps_AB; resultant
//    R = F_s / cos(theta), F_s = k_AB l_AB w, lambda = theta - phi + alpha; F_c = R cos(lambda -
//    alpha), F_t = R sin(lambda - alpha); chip thickness h_c = h cos(phi - alpha) / sin(phi);
//    contact length l_c = h sin(theta) / (cos(lambda) sin(phi)) (1 + C n_eq / (3 (1 + 2 (pi/4 -
//    phi) - C n_eq))).
//  - Tool-chip interface: tau_int = F / (l_c w) with F = R sin(lambda); the chip's shear flow
//    stress there k_chip at strain 2 eps_AB + eps_M / 2 (eps_M = l_c / (sqrt(3) delta h_c)),
//    strain rate V_c / (sqrt(3) delta h_c), temperature T_int (delta h_c the thickness of the
//    secondary zone).
//  - phi is where tau_int = k_chip; C where the normal stress at B from the shear-plane side,
//    k_AB (1 + pi/2 - 2 alpha - 2 C n_eq), equals the mean interface normal stress N / (l_c w);
//    delta where F_c is least (Oxley's minimum-work choice).
// Without thermal softening the rake-face layer never gets soft enough to carry only tau_int:
// then there is no phi, and the result says so (solved = false, with a reason).
// All searches are bounded grids and bisections, so the function always returns (about 0.5 s):
// phi over [1, 60] deg (0.5 deg grid, the first root going up), C over [1, 20] (grid of 1, the
// first root), delta over [0.005, 0.5] (25 log-spaced points, then golden section next to the
// least F_c); temperatures below T_melt and T_0 + 3000 K, k(T) and c(T) floored at 10 % of their
// values at T_0. A delta at the end of its range means the least F_c may lie beyond it.
#pragma once

#include <string>

namespace swarf {

/// Work material for Oxley's model. Johnson-Cook flow stress
///   sigma = (A + B eps^n) (1 + C ln(max(epsdot / epsdot_0, 1))) (1 - T*^m),
///   T* = (T - T_ref) / (T_melt - T_ref) clamped to [0, 1].
struct OxleyMaterial {
  double jc_a = 0;                   ///< A, Pa
  double jc_b = 0;                   ///< B, Pa
  double jc_n = 0;                   ///< n, dimensionless
  double jc_c = 0;                   ///< C (rate sensitivity), dimensionless
  double jc_m = 1;                   ///< m (thermal softening exponent), dimensionless
  double reference_strain_rate = 1;  ///< epsdot_0, 1/s
  double t_ref = 293.15;             ///< T_ref, K
  double t_melt = 1733;              ///< T_melt, K (infinity: no thermal softening)
  double density = 7850;             ///< rho, kg/m^3
  /// Thermal conductivity k(T) = conductivity + conductivity_slope (T - property_t0), W/(m K).
  double conductivity = 0;        ///< W/(m K) at property_t0
  double conductivity_slope = 0;  ///< W/(m K^2)
  /// Specific heat c(T) = heat_capacity + heat_capacity_slope (T - property_t0), J/(kg K).
  double heat_capacity = 0;        ///< J/(kg K) at property_t0
  double heat_capacity_slope = 0;  ///< J/(kg K^2)
  double property_t0 = 273.15;     ///< K, where conductivity and heat_capacity are given
  /// chi, fraction of the plastic work (both zones) turned into heat. Oxley's model takes all of
  /// it (chi = 1); its only 0.9 is eta below.
  double taylor_quinney = 1;
  double eta = 0.9;  ///< Oxley's eta: T_AB = T_0 + eta dT_SZ (AB lies inside the zone), dimensionless
  double psi = 0.7;  ///< Oxley's psi: mean over maximum chip temperature rise at the rake face
};

/// AISI 1045 with Jaspers' Johnson-Cook set (Jaspers, Dautzenberg 2002, J. Mater. Process.
/// Technol. 122:322): A 553.1 MPa, B 600.8 MPa, n 0.234, C 0.0134, m 1, T_ref 20 deg C,
/// T_melt 1733 K; k = 52.61 - 0.0281 T W/(m K), c = 420 + 0.504 T J/(kg K) (T in deg C);
/// rho 7850 kg/m^3; chi = 1, eta = 0.9, psi = 0.7 (Oxley's). The "Taylor-Quinney 0.9" of the
/// reference table (shared/reference/cutting-data.md) is read as Oxley's eta, the one 0.9 in
/// his model: with chi = 0.9 on top, F_c / w rises another 5-10 % (to 12-27 % above that table).
OxleyMaterial oxley_aisi1045_jaspers();

/// One orthogonal cut.
struct OxleyCut {
  double speed = 0;                     ///< V, cutting speed, m/s (> 0)
  double uncut_thickness = 0;           ///< h, m (> 0)
  double width = 0;                     ///< w, m (> 0)
  double rake = 0;                      ///< alpha, rake angle, rad (-pi/2 < alpha < pi/2)
  double initial_temperature = 293.15;  ///< T_0, K (> 0)
};

struct OxleyResult {
  bool solved = false;                 ///< a solution was found; otherwise only reason is meaningful
  std::string reason;                  ///< why there is no solution (empty when solved)
  double cutting_force = 0;            ///< F_c, N
  double thrust_force = 0;             ///< F_t, N
  double cutting_force_per_width = 0;  ///< F_c / w, N/m
  double shear_angle = 0;              ///< phi, rad
  double chip_thickness = 0;           ///< h_c, m
  double chip_ratio = 0;               ///< r = h / h_c, dimensionless
  double primary_temperature = 0;      ///< T_AB, K
  double rake_temperature = 0;         ///< T_int, mean tool-chip interface temperature, K
  double contact_length = 0;           ///< l_c, m
  double strain_rate_constant = 0;     ///< C (of the model, not Johnson-Cook's), dimensionless
  double secondary_zone_ratio = 0;     ///< delta, secondary zone thickness / h_c, dimensionless
  double shear_flow_stress = 0;        ///< k_AB, Pa
  double interface_shear_stress = 0;   ///< tau_int, Pa
};

/// Oxley's solution for the cut. Throws InputError naming the field on bad input (non-positive
/// speed, thickness, width, temperature or material constants; |rake| >= 90 deg).
OxleyResult oxley(const OxleyCut& cut, const OxleyMaterial& material);

}  // namespace swarf

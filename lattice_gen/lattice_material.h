// lattice_material.h: virtual material tests of the bonded FCC lattice (the material lab).
//
// What the lattice is as a material: its homogeneous (Cauchy-Born, cauchy_born.h) response to
// uniaxial stress along a lattice direction and to simple shear, increment by increment,
// quasi-static (rod strain rate 0), each increment's converged state committed like the engine
// commits its rods. 'swarf material' (docs/material-lab.md) drives these and writes the curves.
//
// Measures (MaterialPoint):
// - uniaxial: strain = log axial strain ln U11, stress = true (Cauchy) axial stress sigma_11;
//   equivalent strain |ln U11|; E_mode = Young's modulus along the direction.
// - simple shear F = I + gamma s (x) m: strain = gamma, stress = sigma_12 = s.sigma.m;
//   equivalent strain gamma / sqrt(3); E_mode = 3 C_smsm (so that the equivalent plastic strain
//   is gamma_p / sqrt(3) when the normal stresses are small).
// - equivalent stress: von Mises of the full Cauchy stress, sqrt(3/2 s:s), s the deviator.
// - plastic strain: equivalent_strain - equivalent_stress / E_mode (the equivalent plastic
//   strain of the test's own measures; on a reversal it is the distance from the elastic line
//   through the origin, so it is meant for monotonic tests).
// The test frame: axis 1 = the loading direction (uniaxial) or s (shear), 2 = a lateral axis
// (uniaxial, see uniaxial_test) or m (shear), 3 = 1 x 2.
#pragma once

#include <array>
#include <vector>

#include "swarf/laws/any_rod_law.h"

namespace swarf {

struct MaterialPoint {
  double strain = 0;              ///< the test's strain measure: log axial strain (uniaxial), shear gamma (shear), 1
  double stress = 0;              ///< true (Cauchy) axial stress, or the shear stress sigma_12, Pa
  double equivalent_strain = 0;   ///< von Mises equivalent: |log strain| uniaxial, gamma/sqrt(3) shear, 1
  double equivalent_stress = 0;   ///< von Mises equivalent of the full Cauchy stress, Pa
  double plastic_strain = 0;      ///< equivalent plastic strain: equivalent_strain - equivalent_stress/E_mode, 1
  double volume_ratio = 1;        ///< det F, 1
  double mean_stress = 0;         ///< tr(sigma)/3, Pa
  std::array<double, 6> sigma{};  ///< xx yy zz yz xz xy in the TEST frame, Pa
  int broken = 0;                 ///< rod directions broken (of 6)
  // (beyond the calibration's interface)
  std::array<double, 9> deformation{1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< F in the test frame, row-major, 1
  double closest_unbonded = 0;  ///< closest neighbour not joined by an intact rod, m (contact below 2R = l0)
  double max_rod_strain = 0;    ///< the largest strain of an intact rod, 1
};

/// Uniaxial stress along the lattice direction 'direction' (e.g. {1,0,0} or {1,1,0}; any
/// length). The deformation in the test frame is a symmetric stretch U with U11 = exp(strain);
/// the other five components are solved at each increment so that the five stresses other than
/// sigma_11 vanish (Newton with a central finite-difference Jacobian, backtracking; converged
/// when each is below 1e-10 kb/a, about 1e-8 of a steel-like yield stress). For [100] and [110]
/// the lateral axes (for [110]: [-110] and [001]) are principal by symmetry and the off-diagonal
/// components stay zero. 'turning_points' are log axial strains, the first 0 (e.g. {0, 0.5}
/// tension, {0, -0.5} compression, {0, 0.02, -0.02, 0.02} cyclic); 'increment' the log-strain
/// step (each segment in equal steps of at most that, its end reached exactly). Stops when
/// all rods are broken, when the stress has dropped to zero after a rod broke, or when the
/// lattice has collapsed: an unbonded neighbour closer than l0/2 (the rods alone cannot stop
/// it; the DEM's contacts engage at l0, see closest_unbonded). Throws
/// InputError on bad arguments, SimulationError when the lateral solve fails.
std::vector<MaterialPoint> uniaxial_test(const AnyRodLaw& law, double cell_edge, double rod_area,
                                         const std::array<double, 3>& direction,
                                         const std::vector<double>& turning_points, double increment);

/// Simple shear F = I + gamma s (x) m (s shear direction, m plane normal, in the lattice frame,
/// orthonormal, any length) from 0 to gamma_max in steps of at most 'increment'; the
/// deformation is prescribed entirely (periodic, homogeneous), so sigma_11, sigma_22, sigma_33
/// are the lattice's normal-stress (Poynting-like) effects. Stops early like uniaxial_test.
std::vector<MaterialPoint> simple_shear_test(const AnyRodLaw& law, double cell_edge, double rod_area,
                                             const std::array<double, 3>& direction,
                                             const std::array<double, 3>& normal, double gamma_max, double increment);

}  // namespace swarf

// material_summary.h: what a material test's curve says (lattice_material.h): initial modulus,
// 0.2 % offset yield, flow stresses at given equivalent plastic strains, failure, volume change,
// the strain at which unbonded neighbours come within contact range.
//
// Everything is read from the von Mises equivalents of MaterialPoint (plastic_strain is
// equivalent_strain - equivalent_stress / E_mode); yield and flow stresses are those of the intact
// lattice (before the first rod break: what follows is a damaged specimen); a value a test
// never reached is NaN.
#pragma once

#include <array>
#include <vector>

#include "lattice_gen/lattice_material.h"

namespace swarf {

/// The equivalent plastic strains at which the flow stress is reported, 1.
inline constexpr std::array<double, 3> kFlowPlasticStrains{0.1, 0.5, 1.0};
/// The offset of the yield stress, 1 (0.2 %).
inline constexpr double kYieldOffset = 0.002;

struct CurveSummary {
  double initial_modulus = 0;    ///< stress / strain of the first increment (E along the axis; C_smsm in shear), Pa
  double yield_stress = 0;       ///< equivalent stress at equivalent plastic strain 0.002 (first crossing), Pa
  double yield_test_stress = 0;  ///< the test's own stress there (sigma_11 or tau), Pa
  double yield_strain = 0;       ///< the test's strain there, 1
  std::array<double, 3> flow_stress{};       ///< equivalent stress at kFlowPlasticStrains (first crossing), Pa
  std::array<double, 3> flow_test_stress{};  ///< the test's own stress there, Pa
  double failure_strain = 0;                 ///< the test's strain at the first increment that broke a rod, 1
  double peak_stress = 0;                    ///< the largest equivalent stress before the first rod break, Pa
  double peak_strain = 0;                    ///< the test's strain there, 1
  double end_strain = 0;                     ///< the test's strain at the last point, 1
  double end_volume_ratio = 1;               ///< det F at the last point, 1
  double end_plastic_volume_strain = 0;      ///< ln det F - mean stress / K at the last point (K the bulk modulus), 1
  double contact_strain = 0;  ///< the test's strain at which an unbonded neighbour first comes within l0 = 2R, 1
  std::array<double, 2> lateral_ratio{};  ///< uniaxial, first increment: -ln F22 / ln F11, -ln F33 / ln F11 (Poisson)
  bool failed = false;                    ///< a rod broke
  bool collapsed = false;                 ///< the test stopped with an unbonded neighbour closer than l0/2
};

/// Reads a curve. 'rest_length' l0 (m), 'bulk_modulus' K = (C11 + 2 C12)/3 of the lattice (Pa),
/// 'shear' whether it is a simple-shear curve (no lateral ratios).
CurveSummary summarize_curve(const std::vector<MaterialPoint>& curve, double rest_length, double bulk_modulus,
                             bool shear);

/// The test's stress at equivalent plastic strain 'ep' (first crossing before a rod broke, linear
/// between points); NaN when not reached. 'equivalent' picks the von Mises equivalent instead of the test's own stress.
double stress_at_plastic_strain(const std::vector<MaterialPoint>& curve, double ep, bool equivalent);

}  // namespace swarf

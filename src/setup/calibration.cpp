// calibration.cpp: the rod law from macroscopic properties (see calibration.h).
#include "setup/calibration.h"

#include <algorithm>
#include <cmath>

#include "lattice_gen/lattice_material.h"

namespace swarf {

namespace {

/// The lattice's von Mises stress at equivalent plastic strain e along a lab curve (linear
/// between its points), or NaN where the curve does not reach it.
double stress_at(const std::vector<MaterialPoint>& curve, double e) {
  for (std::size_t k = 1; k < curve.size(); ++k) {
    const double e0 = curve[k - 1].plastic_strain, e1 = curve[k].plastic_strain;
    if (e0 <= e && e <= e1 && e1 > e0)
      return curve[k - 1].equivalent_stress +
             (e - e0) / (e1 - e0) * (curve[k].equivalent_stress - curve[k - 1].equivalent_stress);
  }
  return NAN;
}

}  // namespace

FlowCurve make_flow_curve(const std::vector<double>& plastic_strain, const std::vector<double>& stress) {
  FlowCurve f;
  f.points = static_cast<int>(plastic_strain.size());
  for (int i = 0; i < f.points; ++i) {
    f.plastic_strain[i] = plastic_strain[i];
    f.stress[i] = stress[i];
  }
  return f;
}

RodLaw calibrated_law(const RodCalibration& c) {
  RodLaw law;
  law.youngs_modulus = c.youngs_modulus;
  law.tensile_strength = HUGE_VAL;
  law.failure_strain = c.failure_strain;
  law.flow = make_flow_curve(c.flow_plastic_strain, c.flow_stress);
  law.yield_strain = law.flow.stress[0] / law.youngs_modulus;
  return law;
}

void correct_in_shear(RodCalibration& c, const MacroscopicMaterial& m, double cell_edge, double rod_area) {
  // Fixed point on the rod curve's stresses: each is scaled by target / lattice at its
  // macroscopic point, in cube-plane simple shear at finite strain (the material lab), and the
  // curve kept non-decreasing (the rod law does not soften). Where the lattice hardens more
  // than the target even with flat rods (its rods rotate and new ones stretch), the clamp
  // holds and the mismatch stays: it is reported, not hidden.
  const std::size_t n = c.flow_stress.size();
  const double gamma_max = std::sqrt(3.0) * m.flow_plastic_strain.back() * 1.05 + 0.01;
  c.shear_points_reached = 0;
  for (int iteration = 0; iteration < 12; ++iteration) {
    RodLaw law = calibrated_law(c);
    law.failure_strain = HUGE_VAL;  // (the flow curve, not the failure, is matched)
    const auto curve = simple_shear_test(law, cell_edge, rod_area, {1, 0, 0}, {0, 0, 1}, gamma_max, 2e-3);
    c.shear_mismatch = 0.0;
    c.shear_points_reached = 0;
    for (std::size_t i = 1; i < n; ++i) {
      const double lattice = stress_at(curve, m.flow_plastic_strain[i]);
      if (!std::isfinite(lattice)) break;
      ++c.shear_points_reached;
      const double ratio = m.flow_stress[i] / lattice;
      c.shear_mismatch = std::max(c.shear_mismatch, std::fabs(1.0 / ratio - 1.0));
      c.flow_stress[i] *= ratio;
    }
    for (std::size_t i = 1; i < n; ++i) c.flow_stress[i] = std::max(c.flow_stress[i], c.flow_stress[i - 1]);
  }
}

std::vector<double> johnson_cook_points() { return {0.0, 0.01, 0.03, 0.08, 0.2, 0.5, 1.0, 2.0}; }

std::vector<double> johnson_cook_stress(double a, double b, double n, const std::vector<double>& eps_p) {
  std::vector<double> s;
  for (double e : eps_p) s.push_back(a + b * std::pow(e, n));
  return s;
}

RodCalibration calibrate_rods(const MacroscopicMaterial& m, double cell_edge, double rod_area, double rest_length) {
  RodCalibration c;
  // E100 = 4 kb / (3 a) with kb = E_rod A / l0.
  const double kb = 3.0 * cell_edge * m.youngs_modulus / 4.0;
  c.youngs_modulus = kb * rest_length / rod_area;
  const double ratio = c.youngs_modulus / m.youngs_modulus;  // E_rod / E100
  const bool shear = m.calibration == "shear";
  // Rod plastic strain per equivalent plastic strain, and rod stress per equivalent stress.
  const double strain_factor = shear ? std::sqrt(3.0) / 2.0 : 1.0 / 3.0;
  const double stress_factor = shear ? ratio / (1.5 * std::sqrt(3.0)) : ratio / 3.0;
  for (std::size_t i = 0; i < m.flow_plastic_strain.size(); ++i) {
    c.flow_plastic_strain.push_back(m.flow_plastic_strain[i] * strain_factor);
    c.flow_stress.push_back(m.flow_stress[i] * stress_factor);
  }
  if (!std::isfinite(m.failure_strain)) {
    c.failure_strain = HUGE_VAL;
  } else if (shear) {
    const double gamma = std::sqrt(3.0) * m.failure_strain;
    c.failure_strain = std::sqrt(((1.0 + gamma) * (1.0 + gamma) + 1.0) / 2.0) - 1.0;
  } else {
    // Uniaxial along [100] at small strain: every rod at eps/3 (the lab shows how far finite
    // strain moves it).
    c.failure_strain = m.failure_strain / 3.0;
  }
  if (shear && m.finite_strain) correct_in_shear(c, m, cell_edge, rod_area);
  return c;
}

}  // namespace swarf

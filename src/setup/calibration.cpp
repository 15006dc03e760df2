// calibration.cpp: the rod law from macroscopic properties (see calibration.h).
#include "setup/calibration.h"

#include <cmath>

namespace swarf {

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
  return c;
}

}  // namespace swarf

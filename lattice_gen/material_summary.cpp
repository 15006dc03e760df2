// material_summary.cpp: reading a material test's curve (see material_summary.h).
#include "lattice_gen/material_summary.h"

#include <cmath>

namespace swarf {

namespace {

// The first crossing of plastic_strain >= ep before any rod broke: the index i with the crossing
// between i-1 and i, and the fraction along; i = 0 when never reached.
std::size_t crossing(const std::vector<MaterialPoint>& c, double ep, double& f) {
  for (std::size_t i = 1; i < c.size() && c[i].broken == 0; ++i)
    if (c[i].plastic_strain >= ep && c[i - 1].plastic_strain < ep) {
      f = (ep - c[i - 1].plastic_strain) / (c[i].plastic_strain - c[i - 1].plastic_strain);
      return i;
    }
  return 0;
}

double lerp(double a, double b, double f) { return a + f * (b - a); }

}  // namespace

double stress_at_plastic_strain(const std::vector<MaterialPoint>& c, double ep, bool equivalent) {
  double f = 0;
  const std::size_t i = crossing(c, ep, f);
  if (i == 0) return NAN;
  return equivalent ? lerp(c[i - 1].equivalent_stress, c[i].equivalent_stress, f)
                    : lerp(c[i - 1].stress, c[i].stress, f);
}

CurveSummary summarize_curve(const std::vector<MaterialPoint>& c, double rest_length, double bulk_modulus, bool shear) {
  CurveSummary s;
  s.initial_modulus = c.size() > 1 && c[1].strain != 0 ? c[1].stress / c[1].strain : NAN;
  double f = 0;
  const std::size_t y = crossing(c, kYieldOffset, f);
  s.yield_stress = y ? lerp(c[y - 1].equivalent_stress, c[y].equivalent_stress, f) : NAN;
  s.yield_test_stress = y ? lerp(c[y - 1].stress, c[y].stress, f) : NAN;
  s.yield_strain = y ? lerp(c[y - 1].strain, c[y].strain, f) : NAN;
  for (std::size_t k = 0; k < kFlowPlasticStrains.size(); ++k) {
    s.flow_stress[k] = stress_at_plastic_strain(c, kFlowPlasticStrains[k], true);
    s.flow_test_stress[k] = stress_at_plastic_strain(c, kFlowPlasticStrains[k], false);
  }
  s.failure_strain = NAN;
  s.contact_strain = NAN;
  s.peak_stress = 0;
  s.peak_strain = 0;
  for (const auto& p : c) {
    if (p.broken > 0 && !s.failed) {
      s.failed = true;
      s.failure_strain = p.strain;
    }
    if (p.closest_unbonded < rest_length && std::isnan(s.contact_strain)) s.contact_strain = p.strain;
    if (!s.failed && p.equivalent_stress > s.peak_stress) {
      s.peak_stress = p.equivalent_stress;
      s.peak_strain = p.strain;
    }
  }
  const MaterialPoint& e = c.back();
  s.end_strain = e.strain;
  s.end_volume_ratio = e.volume_ratio;
  s.end_plastic_volume_strain = std::log(e.volume_ratio) - e.mean_stress / bulk_modulus;
  s.collapsed = e.closest_unbonded < 0.5 * rest_length;
  s.lateral_ratio = {NAN, NAN};
  if (!shear && c.size() > 1 && c[1].strain != 0) {
    const double ax = std::log(c[1].deformation[0]);
    s.lateral_ratio = {-std::log(c[1].deformation[4]) / ax, -std::log(c[1].deformation[8]) / ax};
  }
  return s;
}

}  // namespace swarf

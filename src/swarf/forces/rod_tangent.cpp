// rod_tangent.cpp: the rods' part of the Newmark step's Jacobian (see rod_tangent.h).
#include "swarf/forces/rod_tangent.h"

#include <cmath>

namespace swarf {

void rod_tangent_setup(const RodLaw& law, double area, double kx, double kv, const RodTangentView& view,
                       Periodic periodic) {
  const std::size_t m = view.rods;
  const double A = area, E = law.youngs_modulus, eta = law.viscosity;
  const auto* ends = view.ends;
  const Vec3* x = view.x;
  const RodTangentView v = view;  // (a local copy: the compiler need not reload the pointers after each store)
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < m; ++k) {
    if (!v.intact[k] || v.trial_broken[k]) {
      v.axis[k] = Vec3::Zero();
      v.axial[k] = v.lateral[k] = 0.0;
      continue;
    }
    Vec3 dx = x[ends[k][1]] - x[ends[k][0]];
    periodic.wrap(dx);
    const double len = dx.norm();
    const Vec3 n = dx / len;
    // The branch of the trial: the law moved the shift only on the plastic branch.
    const double slope = v.trial_shift[k] != v.shift[k] ? plastic_tangent(law, v.trial_shift[k]) : E;
    const double c = v.coef[k];
    const double inv_l0 = v.inv_rest_length[k];
    v.axis[k] = n;
    v.axial[k] = kx * (slope * A * inv_l0 - c) + kv * eta * A * inv_l0;
    v.lateral[k] = kx * c;
  }
}

}  // namespace swarf

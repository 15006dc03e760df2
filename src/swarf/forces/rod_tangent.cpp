// rod_tangent.cpp: the rods' part of the Newmark step's Jacobian (see rod_tangent.h).
#include "swarf/forces/rod_tangent.h"

#include <cmath>

#include "swarf/forces/lagged_rate.h"

namespace swarf {

namespace {

// A law whose flow stresses scale with a rate factor, with the slopes at a held factor
// (johnson_cook_rod_law.h: tangent_at_scale).
template <class Law>
concept HoldsRateFactor = requires(const Law& l) {
  rate_factor(l, 0.0);
  tangent_at_scale(l, 0.0, 0.0, 1.0);
};

template <class Law>
void rod_tangent_setup_with(const Law& law, double area, double kx, double kv, const RodTangentView& view,
                            Periodic periodic) {
  const std::size_t m = view.rods;
  const double A = area;
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
    const double inv_l0 = 1.0 / v.rest_length[k];
    double strain = 0.0, rate = 0.0;
    if constexpr (Law::kTangentReadsMotion) {
      strain = len * inv_l0 - 1.0;
      rate = n.dot(v.v[ends[k][1]] - v.v[ends[k][0]]) * inv_l0;
    }
    // The branch of the trial (the law moved the shift only on the plastic branch) and its slopes.
    RodTangent t;
    bool held = false;  // (the rate factor held at the step start's rate)
    if constexpr (HoldsRateFactor<Law>) {
      if (v.rate_v != nullptr) {
        // The scale the kernel used (rod_forces.cpp): R at the step start's rate, Theta at the
        // rod's temperature where the kernel reads one.
        double S = rate_factor(law, lagged_rate(v.rate_x, v.rate_v, ends[k][0], ends[k][1], inv_l0, periodic));
        if (v.temperature != nullptr && reads_temperature(law))
          S *= thermal_factor(law, rod_temperature(law, v.temperature[ends[k][0]], v.temperature[ends[k][1]]));
        t = tangent_at_scale(law, v.shift[k], v.trial_shift[k], S);
        held = true;
      }
    }
    if (!held) {
      if constexpr (Law::kReadsTemperature) {
        // (the temperature the kernel's evaluation read: constant over the step)
        if (v.temperature != nullptr)
          t = tangent(law, strain, rate, v.shift[k], v.trial_shift[k],
                      rod_temperature(law, v.temperature[ends[k][0]], v.temperature[ends[k][1]]));
        else
          t = tangent(law, strain, rate, v.shift[k], v.trial_shift[k]);
      } else {
        t = tangent(law, strain, rate, v.shift[k], v.trial_shift[k]);
      }
    }
    const double c = v.coef[k];
    v.axis[k] = n;
    v.axial[k] = kx * (t.stiffness * A * inv_l0 - c) + kv * t.damping * A * inv_l0;
    v.lateral[k] = kx * c;
  }
}

}  // namespace

void rod_tangent_setup(const AnyRodLaw& law, double area, double kx, double kv, const RodTangentView& view,
                       Periodic periodic) {
  std::visit([&](const auto& l) { rod_tangent_setup_with(l, area, kx, kv, view, periodic); }, law);
}

}  // namespace swarf

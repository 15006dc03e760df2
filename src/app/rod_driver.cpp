// rod_driver.cpp: the single-rod driver (see rod_driver.h).
#include "app/rod_driver.h"

#include <fmt/format.h>

#include <cmath>

#include "swarf/core/errors.h"

namespace swarf {

void check_rod_options(const RodLaw& law) {
  if (!(law.youngs_modulus > 0) || !std::isfinite(law.youngs_modulus))
    throw InputError(fmt::format("--E: must be a positive modulus in Pa, got {}", law.youngs_modulus));
  if (!(law.yield_strain > 0))
    throw InputError(fmt::format("--yield-strain: must be positive, got {}", law.yield_strain));
  if (!(law.hardening >= 0 && law.hardening < law.youngs_modulus))
    throw InputError(fmt::format("--hardening: must lie in [0, E) Pa, got {}", law.hardening));
  if (!(law.tensile_strength > 0))
    throw InputError(fmt::format("--tensile-strength: must be positive (Pa), got {}", law.tensile_strength));
}

std::vector<RodSample> drive_rod(const AnyRodLaw& law, const std::vector<double>& path, int steps) {
  if (path.size() < 2 || path[0] != 0.0) throw InputError("--path: needs at least two turning points, the first 0");
  for (double p : path)
    if (!std::isfinite(p)) throw InputError(fmt::format("--path: turning point {} is not finite", p));
  if (steps < 1) throw InputError(fmt::format("--steps: must be a positive integer, got {}", steps));
  std::vector<RodSample> out;
  out.push_back({0.0, 0.0, 0.0, false});
  double shift = 0.0;
  bool broken = false;
  for (std::size_t s = 1; s < path.size(); ++s) {
    const double a = path[s - 1], b = path[s];
    for (int k = 1; k <= steps; ++k) {
      // Exact end points: the turning point itself is reached without rounding drift.
      const double eps = k == steps ? b : a + (b - a) * (double(k) / steps);
      RodSample smp{eps, 0.0, shift, true};
      if (!broken) {
        const RodResponse r = evaluate(law, eps, 0.0, shift);
        broken = r.broken;
        if (!broken) {
          shift = r.shift;
          smp = {eps, r.stress, shift, false};
        } else {
          smp = {eps, 0.0, shift, true};
        }
      }
      out.push_back(smp);
    }
  }
  return out;
}

void write_rod_csv(std::ostream& out, const std::vector<RodSample>& samples) {
  out << "strain,stress,shift,broken\n";
  for (const auto& s : samples) out << fmt::format("{},{},{},{}\n", s.strain, s.stress, s.shift, s.broken ? 1 : 0);
}

}  // namespace swarf

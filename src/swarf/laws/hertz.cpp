// hertz.cpp: restitution <-> damping coefficient for the damped Hertz law (see hertz.h).
#include "swarf/laws/hertz.h"

#include <cmath>

namespace swarf {

double alpha_to_restitution(double alpha) {
  // x'' = -x^(3/2) - alpha x^(1/4) x', x(0) = 0, x'(0) = 1; the force is clamped at zero
  // (no adhesion), so the contact ends when the force vanishes; e = |x'| then.
  auto acc = [&](double x, double v) {
    if (x <= 0.0) return 0.0;
    const double f = x * std::sqrt(x) + alpha * std::sqrt(std::sqrt(x)) * v;
    return f > 0.0 ? -f : 0.0;
  };
  double x = 0.0, v = 1.0;
  const double h = 2e-4;  // the undamped contact lasts about 3.2 time units
  for (int k = 0; k < 200000; ++k) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    x += h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (v < 0.0 && (x <= 0.0 || acc(x, v) == 0.0)) return -v;
  }
  return 0.0;  // never separated: fully damped
}

double restitution_to_alpha(double e) {
  if (e >= 1.0) return 0.0;
  double lo = 0.0, hi = 1.0;
  while (alpha_to_restitution(hi) > e && hi < 1e3) hi *= 2.0;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (alpha_to_restitution(mid) > e)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace swarf

// hysteresis.cpp: fitting the measured loop (see hysteresis.h).
#include "postprocess/hysteresis.h"

#include <cmath>

namespace swarf {

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit f;
  const std::size_t n = x.size();
  f.points = static_cast<int>(n);
  if (n < 2) return f;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  f.slope = sxx > 0 ? sxy / sxx : 0.0;
  f.intercept = my - f.slope * mx;
  return f;
}

LoopMeasurement analyze_loop(const std::vector<double>& strain, const std::vector<double>& stress,
                             const std::vector<int>& segment, double ey) {
  LoopMeasurement m;
  // Segment 0: first loading from zero strain.
  std::vector<double> xe, ye, xp, yp;
  double turn_strain = 0, turn_stress = 0;
  for (std::size_t k = 0; k < strain.size(); ++k) {
    if (segment[k] != 0) continue;
    const double a = std::abs(strain[k]);
    if (a <= 0.5 * ey) {
      xe.push_back(strain[k]);
      ye.push_back(stress[k]);
    } else if (a >= 1.5 * ey) {
      xp.push_back(strain[k]);
      yp.push_back(stress[k]);
    }
    turn_strain = strain[k];
    turn_stress = stress[k];
  }
  // Drop the last 5% of the plastic window: the grip reverses there.
  if (xp.size() > 20) {
    const std::size_t keep = xp.size() - xp.size() / 20;
    xp.resize(keep);
    yp.resize(keep);
  }
  if (xe.size() < 3 || xp.size() < 3) {
    m.note =
        "first segment too short to fit both the elastic and the hardening branch (needs strain beyond 1.5x "
        "the predicted yield strain and enough samples)";
    return m;
  }
  const LineFit el = fit_line(xe, ye), pl = fit_line(xp, yp);
  m.modulus = el.slope;
  m.hardening_tangent = pl.slope;
  m.yield_strain = (pl.intercept - el.intercept) / (el.slope - pl.slope);
  m.yield_stress = el.slope * m.yield_strain + el.intercept;
  m.turn_stress = turn_stress;
  m.ok = true;
  // Segment 1: unloading and reverse yield.
  std::vector<double> xu, yu, xr, yr;
  for (std::size_t k = 0; k < strain.size(); ++k) {
    if (segment[k] != 1) continue;
    const double a = std::abs(strain[k] - turn_strain);
    if (a <= 1.0 * ey) {
      xu.push_back(strain[k]);
      yu.push_back(stress[k]);
    } else if (a >= 3.0 * ey) {
      xr.push_back(strain[k]);
      yr.push_back(stress[k]);
    }
  }
  if (xr.size() > 20) {
    const std::size_t keep = xr.size() - xr.size() / 20;
    xr.resize(keep);
    yr.resize(keep);
  }
  if (xu.size() >= 3 && xr.size() >= 3) {
    const LineFit un = fit_line(xu, yu), rv = fit_line(xr, yr);
    const double e = (rv.intercept - un.intercept) / (un.slope - rv.slope);
    m.reverse_yield_stress = un.slope * e + un.intercept;
    m.reverse_modulus = un.slope;
    m.reverse_ok = true;
  } else {
    m.note =
        "second segment too short to fit the reverse yield (needs a reversal beyond 3x the predicted yield "
        "strain)";
  }
  return m;
}

}  // namespace swarf

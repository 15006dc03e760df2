// report.h: 'swarf report DIR': the Markdown report of a study (table, plots, the shear
// angle against Merchant's theory, forces against depth of cut, Kienzle's law and the
// extrapolation to a vanishing particle radius of fits.h), and the least-squares line.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace swarf {

/// y = slope x + intercept by least squares (fit_ols of fits.h) with its coefficient of
/// determination r2 = 1 - SS_res / SS_tot (1 when y is constant and fitted exactly).
/// ok = false with fewer than two distinct x.
struct LinearFit {
  bool ok = false;
  double slope = 0.0, intercept = 0.0, r2 = 0.0;
  std::size_t n = 0;
};
LinearFit fit_line_r2(const std::vector<double>& x, const std::vector<double>& y);

/// Writes DIR/report.md (drawing the plots first if DIR/plots has none); returns its path.
std::string write_report(const std::string& dir);

}  // namespace swarf

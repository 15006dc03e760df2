// fits.h: the fits of a study's report that carry their own uncertainty: a straight line by
// ordinary least squares with the standard errors of its coefficients, Kienzle's law of the
// cutting force as such a line in log-log, and Richardson's extrapolation of a quantity to a
// vanishing particle radius with Roache's grid convergence index. Pure functions of numbers;
// the report (report.cpp) picks the columns and groups the cases (docs/studies.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace swarf {

/// y = intercept + slope x by ordinary least squares, with the standard errors of both
/// coefficients from the covariance s^2 (X^T X)^-1, s^2 = SS_res / (n - 2). x and y in any
/// units; slope in y/x, intercept and its SE in y.
struct OlsLine {
  bool ok = false;  ///< at least two distinct x
  std::size_t n = 0;
  double slope = 0.0, intercept = 0.0;
  double r2 = 0.0;        ///< 1 - SS_res / SS_tot (1 when y is constant and fitted exactly)
  bool has_se = false;    ///< n >= 3: with two points the line passes through both, s^2 is 0/0
  double se_slope = 0.0;  ///< standard error of the slope
  double se_intercept = 0.0;
  double t95 = 0.0;  ///< 0.975 quantile of Student's t with n - 2 degrees of freedom (has_se)
};
OlsLine fit_ols(const std::vector<double>& x, const std::vector<double>& y);
/// The same with weights w > 0 (1 / variance of y, up to a common factor: the scale of the
/// scatter is estimated from the weighted residuals, s^2 = Sum w e^2 / (n - 2), and the
/// covariance is s^2 (X^T W X)^-1; r2 is the weighted one).
OlsLine fit_wls(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& w);

/// Kienzle's law Fc/b = kc1.1 h^(1 - mc), fitted as ln(F/b) = ln kc1.1 + (1 - mc) ln h.
struct KienzleFit {
  bool ok = false;                       ///< at least two distinct positive depths with a positive force
  bool weighted = false;                 ///< weighted by the forces' confidence intervals
  std::size_t n = 0;                     ///< points fitted
  std::size_t skipped = 0;               ///< points left out: a depth, force (or interval) not a positive number
  double k11 = 0.0;                      ///< kc1.1: the force per width at h = 1 mm, N/mm^2 (N/mm per mm of h)
  double m = 0.0;                        ///< mc: 1 - the slope in log-log, 1
  double r2 = 0.0;                       ///< of the log-log line, 1
  bool has_se = false;                   ///< n >= 3 (with two points the standard errors are undefined)
  double se_k11 = 0.0;                   ///< kc1.1 se(ln kc1.1), the delta method, N/mm^2
  double se_m = 0.0;                     ///< the slope's standard error, 1
  double k11_low = 0.0, k11_high = 0.0;  ///< 95 %: exp(ln kc1.1 -+ t se(ln kc1.1)), N/mm^2
  double m_low = 0.0, m_high = 0.0;      ///< 95 %: mc -+ t se(mc), 1
  double t95 = 0.0;                      ///< Student's t quantile used, n - 2 degrees of freedom
};
/// h_mm: uncut chip thickness (depth of cut), mm; f_N_per_mm: force per width, N/mm (= kN/m).
/// With ci95_N_per_mm (the 95 % half-width of each force's steady mean, N/mm) the fit is
/// weighted by (F / ci)^2, the inverse variance of ln F to first order up to a common factor;
/// a point without a positive interval is then left out (skipped).
KienzleFit fit_kienzle(const std::vector<double>& h_mm, const std::vector<double>& f_N_per_mm,
                       const std::vector<double>& ci95_N_per_mm = {});

/// The mean of y at each distinct x (x ascending), with the count: repetitions of a point
/// pooled into one value before an extrapolation. Pairs with a non-finite x or y are left out.
struct MeanAtX {
  double x = 0.0, mean = 0.0;
  std::size_t n = 0;
};
std::vector<MeanAtX> means_at_x(const std::vector<double>& x, const std::vector<double>& y);

/// How a Richardson extrapolation was made.
enum class RichardsonMethod {
  none,            ///< fewer than two radii
  observed_order,  ///< f0 from the three finest radii with their observed order p
  two_radii,       ///< two radii: p = 1 assumed, f0 through both
  line,            ///< p = 1 assumed: the least-squares line f = f0 + c R over all radii
};

/// f(R) = f0 + c R^p extrapolated to R -> 0. f0, f_finest, f_second, error in the unit of f;
/// R_finest in the unit of R.
struct Richardson {
  RichardsonMethod method = RichardsonMethod::none;
  std::string note;         ///< why p = 1 was assumed (oscillation, p out of range, ...); "" otherwise
  std::size_t radii = 0;    ///< distinct radii used
  std::size_t skipped = 0;  ///< pairs left out: a non-positive or non-finite R, a non-finite f
  double R_finest = 0.0;
  double f_finest = 0.0, f_second = 0.0;  ///< f at the finest and the second finest radius
  double f0 = 0.0;                        ///< the extrapolated f at R = 0
  double p = 0.0;                         ///< the observed order, or the assumed 1
  double r = 0.0;                         ///< refinement ratio of the two finest, R_second / R_finest
  bool has_error = false;                 ///< an error bar was computed (false only without an extrapolation)
  double error = 0.0;   ///< GCI of the finest radius (observed_order, two_radii) or the SE of f0 (line)
  double change = 0.0;  ///< |f_finest - f_second| / |f_finest|, 1 (inf when f_finest = 0 and they differ)
};
/// Radii R (any length unit) and values f; several f at one R are averaged first (means_at_x).
/// With three or more radii the order p comes from the three finest (Celik et al. 2008, J.
/// Fluids Eng. 130:078001, eqs. 3-4; Roache's ln((f3 - f2)/(f2 - f1)) / ln r for a constant
/// ratio r); an oscillating sequence, an undefined p or one outside [0.5, 4] falls back to the line.
Richardson richardson(const std::vector<double>& R, const std::vector<double>& f);
/// The order p for the three finest radii R1 < R2 < R3 with values f1, f2, f3 (Celik's
/// fixed-point iteration of eq. 3 without its absolute values, so that a diverging sequence
/// gives p < 0); NaN when the differences are zero, change sign or the iteration does not settle.
double observed_order(double R1, double R2, double R3, double f1, double f2, double f3);

}  // namespace swarf

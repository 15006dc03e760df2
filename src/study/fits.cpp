// fits.cpp: least squares with standard errors, Kienzle's law, Richardson's extrapolation (see fits.h).
#include "study/fits.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "postprocess/steady_stats.h"

namespace swarf {

OlsLine fit_ols(const std::vector<double>& x, const std::vector<double>& y) {
  return fit_wls(x, y, std::vector<double>(std::min(x.size(), y.size()), 1.0));
}

OlsLine fit_wls(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& w) {
  OlsLine f;
  f.n = std::min({x.size(), y.size(), w.size()});
  if (f.n < 2 || std::set<double>(x.begin(), x.begin() + f.n).size() < 2) return f;
  // Centred sums: the log-log fit has x far from 0 relative to its spread (ln of 0.1..0.3 mm),
  // where the raw sums Sum x^2 - n mean^2 lose digits.
  double sw = 0, mx = 0, my = 0;
  for (std::size_t k = 0; k < f.n; ++k) sw += w[k];
  for (std::size_t k = 0; k < f.n; ++k) {
    mx += w[k] * x[k] / sw;
    my += w[k] * y[k] / sw;
  }
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t k = 0; k < f.n; ++k) {
    sxx += w[k] * (x[k] - mx) * (x[k] - mx);
    sxy += w[k] * (x[k] - mx) * (y[k] - my);
    syy += w[k] * (y[k] - my) * (y[k] - my);
  }
  f.ok = true;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double ss_res = 0;
  for (std::size_t k = 0; k < f.n; ++k) {
    const double e = y[k] - (f.intercept + f.slope * x[k]);
    ss_res += w[k] * e * e;
  }
  f.r2 = syy > 0 ? 1.0 - ss_res / syy : (ss_res == 0 ? 1.0 : 0.0);
  if (f.n >= 3) {
    // s^2 (X^T W X)^-1 with s^2 = Sum w e^2 / (n - 2): the weights need only be relative.
    const double s2 = ss_res / (double(f.n) - 2.0);
    f.has_se = true;
    f.se_slope = std::sqrt(s2 / sxx);
    f.se_intercept = std::sqrt(s2 * (1.0 / sw + mx * mx / sxx));
    f.t95 = student_t_975(f.n - 2);
  }
  return f;
}

KienzleFit fit_kienzle(const std::vector<double>& h_mm, const std::vector<double>& f_N_per_mm,
                       const std::vector<double>& ci95_N_per_mm) {
  KienzleFit k;
  k.weighted = !ci95_N_per_mm.empty();
  std::vector<double> lx, ly, w;
  for (std::size_t i = 0; i < std::min(h_mm.size(), f_N_per_mm.size()); ++i) {
    const double h = h_mm[i], f = f_N_per_mm[i];
    const double ci = !k.weighted ? 1.0 : i < ci95_N_per_mm.size() ? ci95_N_per_mm[i] : NAN;
    if (!(std::isfinite(h) && std::isfinite(f) && h > 0 && f > 0 && std::isfinite(ci) && ci > 0)) {
      ++k.skipped;
      continue;
    }
    lx.push_back(std::log(h));
    ly.push_back(std::log(f));
    // The spread of ln F is about that of F over F (first order), so 1/sigma_ln^2 ~ (F / ci)^2.
    w.push_back(k.weighted ? (f / ci) * (f / ci) : 1.0);
  }
  const OlsLine line = fit_wls(lx, ly, w);
  k.n = lx.size();
  if (!line.ok) return k;
  k.ok = true;
  k.k11 = std::exp(line.intercept);
  k.m = 1.0 - line.slope;
  k.r2 = line.r2;
  if (!line.has_se) return k;
  k.has_se = true;
  k.t95 = line.t95;
  // d kc1.1 / d ln kc1.1 = kc1.1: the delta method's first-order SE. The interval is the
  // intercept's, mapped through exp (exact under the model, and never below zero).
  k.se_k11 = k.k11 * line.se_intercept;
  k.se_m = line.se_slope;
  k.k11_low = std::exp(line.intercept - line.t95 * line.se_intercept);
  k.k11_high = std::exp(line.intercept + line.t95 * line.se_intercept);
  k.m_low = k.m - line.t95 * line.se_slope;
  k.m_high = k.m + line.t95 * line.se_slope;
  return k;
}

std::vector<MeanAtX> means_at_x(const std::vector<double>& x, const std::vector<double>& y) {
  std::map<double, std::pair<double, std::size_t>> at;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (std::isfinite(x[i]) && std::isfinite(y[i])) {
      at[x[i]].first += y[i];
      ++at[x[i]].second;
    }
  std::vector<MeanAtX> out;
  for (const auto& [xv, s] : at) out.push_back({xv, s.first / double(s.second), s.second});
  return out;
}

double observed_order(double R1, double R2, double R3, double f1, double f2, double f3) {
  const double e21 = f2 - f1, e32 = f3 - f2;
  if (!(R1 > 0 && R2 > R1 && R3 > R2) || e21 == 0 || e32 == 0 || (e21 > 0) != (e32 > 0)) return NAN;
  const double r21 = R2 / R1, r32 = R3 / R2, ls = std::log(e32 / e21);
  // Celik eq. 3 with s = 1: p = (ln(e32/e21) + q(p)) / ln r21, q(p) = ln((r21^p - 1)/(r32^p - 1));
  // q = 0 for a constant ratio, so the first step is Roache's formula and the last for such a sequence.
  double p = ls / std::log(r21);
  for (int it = 0; it < 500; ++it) {
    if (!std::isfinite(p) || p == 0) return NAN;
    const double q = std::log((std::pow(r21, p) - 1.0) / (std::pow(r32, p) - 1.0));
    const double next = (ls + q) / std::log(r21);
    if (std::abs(next - p) <= 1e-14 * std::max(1.0, std::abs(p))) return next;
    p = next;
  }
  return NAN;
}

Richardson richardson(const std::vector<double>& R, const std::vector<double>& f) {
  Richardson out;
  std::vector<double> rr, ff;
  for (std::size_t i = 0; i < std::min(R.size(), f.size()); ++i) {
    if (!(std::isfinite(R[i]) && R[i] > 0 && std::isfinite(f[i]))) {
      ++out.skipped;
      continue;
    }
    rr.push_back(R[i]);
    ff.push_back(f[i]);
  }
  const std::vector<MeanAtX> pts = means_at_x(rr, ff);
  out.radii = pts.size();
  if (pts.size() < 2) return out;
  const double R1 = pts[0].x, f1 = pts[0].mean, f2 = pts[1].mean;
  out.R_finest = R1;
  out.f_finest = f1;
  out.f_second = f2;
  out.r = pts[1].x / R1;
  out.change = f1 != 0 ? std::abs(f1 - f2) / std::abs(f1) : (f1 == f2 ? 0.0 : INFINITY);
  if (pts.size() == 2) {
    // Two radii cannot give an order: p = 1, and Roache's safety factor 3 for two grids.
    out.method = RichardsonMethod::two_radii;
    out.p = 1.0;
    out.f0 = f1 + (f1 - f2) / (out.r - 1.0);
    out.has_error = true;
    out.error = 3.0 * std::abs(f1 - f2) / (out.r - 1.0);
    return out;
  }
  const double f3 = pts[2].mean, e21 = f2 - f1, e32 = f3 - f2;
  const double p = observed_order(R1, pts[1].x, pts[2].x, f1, f2, f3);
  if (e21 == 0 || e32 == 0)
    out.note = "no change between two of the three finest radii: the order is undefined";
  else if ((e21 > 0) != (e32 > 0))
    out.note = "oscillatory: the differences between the three finest radii change sign";
  else if (!std::isfinite(p))
    out.note = "the iteration for the observed order did not settle";
  else if (p < 0.5 || p > 4.0)
    out.note = fmt::format("observed order p = {:.3g} outside [0.5, 4]", p);
  if (out.note.empty()) {
    out.method = RichardsonMethod::observed_order;
    out.p = p;
    const double rp = std::pow(out.r, p);
    out.f0 = (rp * f1 - f2) / (rp - 1.0);
    out.has_error = true;
    out.error = 1.25 * std::abs(e21) / (rp - 1.0);  // Roache's GCI with Fs = 1.25 (three grids)
    return out;
  }
  std::vector<double> xs, ys;
  for (const auto& m : pts) {
    xs.push_back(m.x);
    ys.push_back(m.mean);
  }
  const OlsLine line = fit_ols(xs, ys);
  out.method = RichardsonMethod::line;
  out.p = 1.0;
  out.f0 = line.intercept;
  out.has_error = line.has_se;
  out.error = line.se_intercept;
  return out;
}

}  // namespace swarf

// study_fits_test.cpp: the report's fits with their uncertainty (src/study/fits.h): least squares
// with standard errors against the closed-form formulas, Kienzle's law on noise-free data and
// the coverage of its intervals on noisy data, Richardson's extrapolation on sequences with a
// known limit, and the report's sections (report.md) on synthetic study directories.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <random>
#include <vector>

#include "study/fits.h"
#include "study/report.h"
#include "study/study.h"
#include "study/study_record.h"
#include "test_helpers.h"

namespace swarf {
namespace {

namespace fs = std::filesystem;

// Kienzle on exact data: F/b = 1500 h^0.78 N/mm (C45, docs/cutting-data.md) at five depths.
// Tolerance 1e-10 relative: the data are the law itself, so only rounding in pow, log and the
// sums (a few 1e-16 each, amplified by the log-log conditioning to ~1e-14) separates them.
TEST(StudyFits, KienzleRecoversExactLaw) {
  const double kc = 1500.0, mc = 0.22;
  std::vector<double> h{0.05, 0.1, 0.2, 0.3, 0.5}, f;
  for (double x : h) f.push_back(kc * std::pow(x, 1.0 - mc));
  const KienzleFit k = fit_kienzle(h, f);
  ASSERT_TRUE(k.ok && k.has_se);
  EXPECT_EQ(k.n, 5u);
  EXPECT_NEAR(k.k11, kc, 1e-10 * kc);
  EXPECT_NEAR(k.m, mc, 1e-10 * mc);
  EXPECT_NEAR(k.r2, 1.0, 1e-12);
  // No scatter: the standard errors are rounding, far below the coefficients.
  EXPECT_LT(k.se_k11, 1e-10 * kc);
  EXPECT_LT(k.se_m, 1e-10);
}

// Non-positive and non-finite points have no logarithm: skipped and counted. Two points give a
// line but no standard error (has_se false), and one depth gives no fit.
TEST(StudyFits, KienzleSkipsBadPointsAndRefusesErrorsOfTwoPoints) {
  const KienzleFit k = fit_kienzle({0.1, 0.2, 0.0, -0.1, 0.3, NAN}, {100.0, 180.0, 50.0, 50.0, -5.0, 10.0});
  ASSERT_TRUE(k.ok);
  EXPECT_EQ(k.n, 2u);
  EXPECT_EQ(k.skipped, 4u);
  EXPECT_FALSE(k.has_se);
  EXPECT_NEAR(k.m, 1.0 - std::log(1.8) / std::log(2.0), 1e-12);
  EXPECT_FALSE(fit_kienzle({0.2, 0.2, 0.2}, {1.0, 2.0, 3.0}).ok);
  EXPECT_FALSE(fit_kienzle({}, {}).ok);
}

// The standard errors against the textbook formulas, computed here from the raw normal
// equations (the code uses centred sums): beta = (X^T X)^-1 X^T y, cov = s^2 (X^T X)^-1,
// s^2 = RSS / (n - 2). Four points with chosen residual-like offsets. Student's t for 2 degrees
// of freedom has the closed form t = (2p - 1) / sqrt(2 p (1 - p)) at p = 0.975. Tolerance 1e-9
// relative: two roundings of the same algebra; the raw sums lose a few digits to cancellation
// (sum ln^2 h against n mean^2, ratio ~ 10), far from 1e-9.
TEST(StudyFits, KienzleStandardErrorsMatchClosedForm) {
  const std::vector<double> h{0.1, 0.15, 0.25, 0.4}, e{0.03, -0.05, 0.04, -0.01};
  std::vector<double> f;
  for (std::size_t i = 0; i < h.size(); ++i) f.push_back(1800.0 * std::pow(h[i], 0.7) * std::exp(e[i]));
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = 4;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double x = std::log(h[i]), y = std::log(f[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double det = n * sxx - sx * sx;
  // (X^T X)^-1 = [[sxx, -sx], [-sx, n]] / det
  const double b = (n * sxy - sx * sy) / det, a = (sxx * sy - sx * sxy) / det;
  double rss = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double r = std::log(f[i]) - a - b * std::log(h[i]);
    rss += r * r;
  }
  const double s2 = rss / (n - 2), se_a = std::sqrt(s2 * sxx / det), se_b = std::sqrt(s2 * n / det);
  const double p = 0.975, t = (2 * p - 1) / std::sqrt(2 * p * (1 - p));

  const KienzleFit k = fit_kienzle(h, f);
  ASSERT_TRUE(k.ok && k.has_se);
  EXPECT_NEAR(k.k11, std::exp(a), 1e-9 * std::exp(a));
  EXPECT_NEAR(k.m, 1 - b, 1e-9);
  EXPECT_NEAR(k.se_m, se_b, 1e-9 * se_b);
  EXPECT_NEAR(k.se_k11, std::exp(a) * se_a, 1e-9 * std::exp(a) * se_a);
  EXPECT_NEAR(k.t95, t, 1e-9 * t);
  EXPECT_NEAR(k.m_low, 1 - b - t * se_b, 1e-9);
  EXPECT_NEAR(k.m_high, 1 - b + t * se_b, 1e-9);
  EXPECT_NEAR(k.k11_low, std::exp(a - t * se_a), 1e-9 * std::exp(a));
  EXPECT_NEAR(k.k11_high, std::exp(a + t * se_a), 1e-9 * std::exp(a));
  EXPECT_GT(se_b, 0.01);  // the offsets are not a line: the errors are real, not rounding
}

// Weighted least squares against the weighted normal equations, computed here from raw sums:
// det = Sw Swxx - Swx^2, cov = s^2 [[Swxx, -Swx], [-Swx, Sw]] / det, s^2 = Sum w e^2 / (n - 2).
// Weights scaled by a common factor change nothing (they are relative); Kienzle's weighted fit
// is this line in log-log with w = (F / ci)^2, and a point without a positive interval is left
// out. Tolerance 1e-9 relative: two roundings of the same algebra, as above.
TEST(StudyFits, WeightedFitMatchesClosedFormAndIgnoresWeightScale) {
  const std::vector<double> x{0.0, 1.0, 2.0, 3.0, 4.0}, y{1.1, 2.9, 5.2, 6.8, 9.3}, w{1.0, 4.0, 0.5, 2.0, 1.0};
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < 5; ++i) {
    sw += w[i];
    sx += w[i] * x[i];
    sy += w[i] * y[i];
    sxx += w[i] * x[i] * x[i];
    sxy += w[i] * x[i] * y[i];
  }
  const double det = sw * sxx - sx * sx, b = (sw * sxy - sx * sy) / det, a = (sxx * sy - sx * sxy) / det;
  double rss = 0;
  for (int i = 0; i < 5; ++i) rss += w[i] * std::pow(y[i] - a - b * x[i], 2);
  const double s2 = rss / 3;
  const OlsLine f = fit_wls(x, y, w);
  ASSERT_TRUE(f.ok && f.has_se);
  EXPECT_NEAR(f.slope, b, 1e-9 * std::abs(b));
  EXPECT_NEAR(f.intercept, a, 1e-9 * std::abs(a));
  EXPECT_NEAR(f.se_slope, std::sqrt(s2 * sw / det), 1e-9 * std::sqrt(s2 * sw / det));
  EXPECT_NEAR(f.se_intercept, std::sqrt(s2 * sxx / det), 1e-9 * std::sqrt(s2 * sxx / det));
  std::vector<double> w7;
  for (double v : w) w7.push_back(7.0 * v);
  const OlsLine g = fit_wls(x, y, w7);
  EXPECT_NEAR(g.se_slope, f.se_slope, 1e-12 * f.se_slope);
  EXPECT_NEAR(g.se_intercept, f.se_intercept, 1e-12 * f.se_intercept);
  EXPECT_NEAR(g.r2, f.r2, 1e-12);
  const OlsLine o = fit_wls(x, y, std::vector<double>(5, 1.0)), p = fit_ols(x, y);
  EXPECT_EQ(o.slope, p.slope);
  EXPECT_EQ(o.se_intercept, p.se_intercept);

  const std::vector<double> h{0.1, 0.2, 0.3, 0.4, 0.5}, F{200.0, 330.0, 470.0, 560.0, 700.0};
  const std::vector<double> ci{20.0, 10.0, 50.0, 0.0, 30.0};  // the fourth has no interval
  const KienzleFit k = fit_kienzle(h, F, ci);
  EXPECT_TRUE(k.weighted);
  EXPECT_EQ(k.n, 4u);
  EXPECT_EQ(k.skipped, 1u);
  std::vector<double> lh, lf, wk;
  for (int i : {0, 1, 2, 4}) {
    lh.push_back(std::log(h[i]));
    lf.push_back(std::log(F[i]));
    wk.push_back(std::pow(F[i] / ci[i], 2));
  }
  const OlsLine l = fit_wls(lh, lf, wk);
  EXPECT_NEAR(k.m, 1.0 - l.slope, 1e-12);
  EXPECT_NEAR(k.se_m, l.se_slope, 1e-12 * l.se_slope);
  EXPECT_NEAR(k.k11, std::exp(l.intercept), 1e-12 * k.k11);
  EXPECT_GT(std::abs(k.m - fit_kienzle(h, F).m), 1e-3);  // the weights matter for these data
}

// A standard normal deviate by Box-Muller from two 53-bit uniforms of mt19937_64 (the same on
// every standard library, unlike std::normal_distribution); the sine half is thrown away.
double box_muller(std::mt19937_64& gen) {
  const double u1 = double((gen() >> 11) + 1) * 0x1.0p-53;  // (0, 1]: log(u1) is finite
  const double u2 = double(gen() >> 11) * 0x1.0p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

// Coverage: 2000 data sets of 5 depths with lognormal scatter (sigma 0.08 in ln F) about
// kc1.1 = 1500, mc = 0.22. Under this model the t intervals are exact, so each covers the true
// value with probability 0.95 and the count of covering intervals is Binomial(2000, 0.95). The
// band is that distribution's central 99.9 % (its 0.0005 and 0.9995 quantiles, computed below:
// 1866 to 1931, i.e. 93.3 % to 96.55 %): a correct fit fails with probability 0.1 %. Intervals
// from the normal quantile 1.96 instead of t(3) = 3.18 cover 85.5 % (never pass), and those from
// s^2 = RSS / n instead of RSS / (n - 2) cover 91.0 % (pass with probability 1e-4). The seed is
// fixed, so the test is deterministic (these seeds: 1904 and 1907 of 2000 cover mc and kc1.1).
TEST(StudyFits, KienzleIntervalsCoverTheTruth) {
  const double kc = 1500.0, mc = 0.22, sigma = 0.08;
  const std::vector<double> h{0.05, 0.1, 0.15, 0.2, 0.3};
  const int sets = 2000;
  std::mt19937_64 gen(20261206);
  int cover_m = 0, cover_k = 0;
  for (int s = 0; s < sets; ++s) {
    std::vector<double> f;
    for (double x : h) f.push_back(kc * std::pow(x, 1.0 - mc) * std::exp(sigma * box_muller(gen)));
    const KienzleFit k = fit_kienzle(h, f);
    ASSERT_TRUE(k.has_se);
    cover_m += k.m_low <= mc && mc <= k.m_high;
    cover_k += k.k11_low <= kc && kc <= k.k11_high;
  }
  const boost::math::binomial_distribution<double> count(sets, 0.95);
  const double lo = boost::math::quantile(count, 0.0005), hi = boost::math::quantile(count, 0.9995);
  EXPECT_GE(cover_m, lo);
  EXPECT_LE(cover_m, hi);
  EXPECT_GE(cover_k, lo);
  EXPECT_LE(cover_k, hi);
}

// f(R) = 2 + 3 R^2 at R = 1, 0.5, 0.25 (ratio 2): Roache's order is exactly ln(0.5625 * 4 /
// 0.5625) / ln 2 = 2 and the extrapolation exact. Tolerance 1e-12: rounding in log and pow of
// numbers of order 1. The GCI is 1.25 times the true error of the finest, 3 * 0.25^2.
TEST(StudyFits, RichardsonConstantRatioRecoversLimitAndOrder) {
  const std::vector<double> R{1.0, 0.5, 0.25};
  std::vector<double> f;
  for (double r : R) f.push_back(2.0 + 3.0 * r * r);
  const Richardson e = richardson(R, f);
  ASSERT_EQ(e.method, RichardsonMethod::observed_order) << e.note;
  EXPECT_EQ(e.radii, 3u);
  EXPECT_NEAR(e.f0, 2.0, 1e-12);
  EXPECT_NEAR(e.p, 2.0, 1e-12);
  EXPECT_NEAR(e.r, 2.0, 1e-15);
  EXPECT_EQ(e.R_finest, 0.25);
  EXPECT_NEAR(e.error, 1.25 * 3.0 * 0.0625, 1e-12);
  EXPECT_NEAR(e.change, (3.0 * 0.25 - 3.0 * 0.0625) / (2.0 + 3.0 * 0.0625), 1e-14);
  EXPECT_TRUE(e.note.empty());
}

// Non-constant ratios (R = 1, 0.7, 0.5, 0.35, given out of order, with a repeated coarse radius
// whose two values average to the law): Celik's iteration recovers f0 = 1.5 and p = 1.7 from the
// three finest. Tolerance 1e-8: the iteration stops at a 1e-14 step and the extrapolation
// divides by r^p - 1 = 0.83, so rounding stays near 1e-13; 1e-8 is the brief's margin.
TEST(StudyFits, RichardsonNonConstantRatioRecoversLimitAndOrder) {
  const double f0 = 1.5, c = 0.8, p = 1.7;
  auto law = [&](double r) { return f0 + c * std::pow(r, p); };
  const std::vector<double> R{0.5, 1.0, 0.35, 0.7, 1.0};
  const std::vector<double> f{law(0.5), law(1.0) + 0.25, law(0.35), law(0.7), law(1.0) - 0.25};
  const Richardson e = richardson(R, f);
  ASSERT_EQ(e.method, RichardsonMethod::observed_order) << e.note;
  EXPECT_EQ(e.radii, 4u);
  EXPECT_NEAR(e.f0, f0, 1e-8);
  EXPECT_NEAR(e.p, p, 1e-8);
  EXPECT_NEAR(e.r, 0.5 / 0.35, 1e-15);
  EXPECT_NEAR(observed_order(0.35, 0.5, 0.7, law(0.35), law(0.5), law(0.7)), p, 1e-8);
  const auto m = means_at_x(R, f);
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[3].n, 2u);
  EXPECT_NEAR(m[3].mean, law(1.0), 1e-15);
}

// An oscillating sequence has no order: p = 1 is assumed, f0 is the intercept of the
// least-squares line over all radii, the error bar its standard error, and the note says why.
// The line is computed here by the closed form (4 points). Tolerance 1e-12: rounding only.
TEST(StudyFits, RichardsonOscillationFallsBackToLine) {
  const std::vector<double> R{0.25, 0.5, 0.75, 1.0}, f{1.0, 1.2, 0.9, 1.1};
  const Richardson e = richardson(R, f);
  EXPECT_EQ(e.method, RichardsonMethod::line);
  EXPECT_NE(e.note.find("oscillatory"), std::string::npos) << e.note;
  EXPECT_EQ(e.p, 1.0);
  double mx = 0, my = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < 4; ++i) {
    mx += R[i] / 4;
    my += f[i] / 4;
  }
  for (int i = 0; i < 4; ++i) {
    sxx += (R[i] - mx) * (R[i] - mx);
    sxy += (R[i] - mx) * (f[i] - my);
  }
  const double b = sxy / sxx, a = my - b * mx;
  double rss = 0;
  for (int i = 0; i < 4; ++i) rss += std::pow(f[i] - a - b * R[i], 2);
  EXPECT_NEAR(e.f0, a, 1e-12);
  ASSERT_TRUE(e.has_error);
  EXPECT_NEAR(e.error, std::sqrt(rss / 2 * (0.25 + mx * mx / sxx)), 1e-12);
  EXPECT_TRUE(std::isnan(observed_order(0.25, 0.5, 0.75, 1.0, 1.2, 0.9)));
}

// An order outside [0.5, 4] (f = 1 + R^0.2 converges too slowly to trust p) falls back to the
// line; two radii assume p = 1 with Roache's factor 3; one radius gives nothing.
TEST(StudyFits, RichardsonOrderOutOfRangeTwoRadiiAndOne) {
  const std::vector<double> R{0.25, 0.5, 1.0};
  std::vector<double> f;
  for (double r : R) f.push_back(1.0 + std::pow(r, 0.2));
  const Richardson e = richardson(R, f);
  EXPECT_EQ(e.method, RichardsonMethod::line);
  EXPECT_NE(e.note.find("outside [0.5, 4]"), std::string::npos) << e.note;

  const Richardson two = richardson({0.5, 1.0}, {3.0, 4.0});
  EXPECT_EQ(two.method, RichardsonMethod::two_radii);
  EXPECT_EQ(two.f0, 2.0);  // f1 + (f1 - f2) / (r - 1) with r = 2: exact in binary
  EXPECT_EQ(two.error, 3.0);
  EXPECT_EQ(two.change, 1.0 / 3.0);

  EXPECT_EQ(richardson({0.5, 0.5}, {1.0, 2.0}).method, RichardsonMethod::none);
  const Richardson bad = richardson({-1.0, 0.0, 0.5, 1.0}, {1.0, 1.0, 3.0, 4.0});
  EXPECT_EQ(bad.skipped, 2u);
  EXPECT_EQ(bad.method, RichardsonMethod::two_radii);
}

// A summary.json that case_status accepts as finished.
void write_case_summary(const std::string& out, const Study& s, const StudyCase& c, nlohmann::json j) {
  fs::create_directories(case_dir(out, c));
  j["status"] = "completed";
  j["overrides"] = case_overrides(s, c);
  test::write_file((fs::path(case_dir(out, c)) / "summary.json").string(), j.dump(1));
}

// A study (base "first_cut.toml", no plots, then the given keys) recorded in DIR/out as swarf
// sweep records it, before any case has run.
Study recorded_study(const test::TempDir& dir, const std::string& keys) {
  const Study s = parse_study("base = \"first_cut.toml\"\nplots = false\n" + keys, "study.toml", dir.str());
  write_study_json(s, dir / "out");
  return s;
}

// A depth study with two speeds and two seeds per point: Kienzle per speed (the tool's origin
// moves with the depth and does not split the cases; the seeds are pooled as points), then all
// cases pooled. Exact laws, so the printed kc1.1 and mc are the chosen ones to the 5 digits
// printed; the thrust force has its own kt1.1, mt.
TEST(Report, KienzleSectionPerGroupOfCases) {
  test::TempDir dir("fits_kienzle");
  const std::string out = dir / "out";
  const Study s = recorded_study(dir, R"(repetitions = 2
seed_key = "workpiece.disorder_seed"
[grid]
mesh.0.origin = [[0, 0, 2.4e-3], [0, 0, 2.3e-3], [0, 0, 2.1e-3]]
cut.speed = [5.0, 10.0]
)");
  ASSERT_EQ(s.cases.size(), 12u);
  for (const StudyCase& c : s.cases) {
    const double z = std::stod(c.values.at("mesh.0.origin").substr(c.values.at("mesh.0.origin").rfind(',') + 1));
    const double h_m = 2.5e-3 - z, h_mm = h_m * 1e3;
    const bool slow = c.values.at("cut.speed") == "5.0";
    const double fc = (slow ? 1500.0 : 1400.0) * std::pow(h_mm, slow ? 0.78 : 0.75);  // N/mm
    const double ft = 600.0 * std::pow(h_mm, 0.6);
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", fc * 1e3},
                    {"thrust_force_per_width_mean_N_per_m", ft * 1e3}};
    j["chip"] = {{"depth_of_cut_m", h_m}};
    write_case_summary(out, s, c, j);
  }
  const std::string md = test::read_file(write_report(out));
  ASSERT_NE(md.find("## Kienzle's law"), std::string::npos) << md;
  EXPECT_NE(md.find("| cut.speed = 5.0 | 6 | 1500 | "), std::string::npos) << md;
  EXPECT_NE(md.find("| cut.speed = 10.0 | 6 | 1400 | "), std::string::npos) << md;
  EXPECT_NE(md.find("| 0.22 | "), std::string::npos) << md;
  EXPECT_NE(md.find("| 0.25 | "), std::string::npos) << md;
  EXPECT_NE(md.find("| all cases pooled | 12 | "), std::string::npos) << md;
  EXPECT_NE(md.find("| cut.speed = 5.0 | 6 | 600 | "), std::string::npos) << md;  // kt1.1
  EXPECT_NE(md.find("| 0.4 | "), std::string::npos) << md;                        // mt
  EXPECT_EQ(md.find("undefined (2 points)"), std::string::npos) << md;
}

// Two usable depths: the law through both, its errors undefined and said so. A third case
// whose force is negative (a thrust that pulls, a broken run) has no logarithm: left out, counted;
// a fourth without a finite depth is in no group.
TEST(Report, KienzleSectionWithTwoDepthsSaysErrorsUndefined) {
  test::TempDir dir("fits_kienzle2");
  const std::string out = dir / "out";
  const Study s = recorded_study(dir, R"([grid]
mesh.0.origin = [[0, 0, 2.4e-3], [0, 0, 2.2e-3], [0, 0, 2.0e-3], [0, 0, 1.9e-3]]
)");
  for (int k = 0; k < 4; ++k) {
    const double h_mm = 0.1 + 0.2 * k;
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", k == 2 ? -5e3 : 1e3 * 1700.0 * std::pow(h_mm, 0.8)}};
    // The fourth: a depth the summary could not measure ("nan", as summary.json writes it): in no fit.
    j["chip"] = {{"depth_of_cut_m", k == 3 ? nlohmann::json("nan") : nlohmann::json(h_mm * 1e-3)}};
    write_case_summary(out, s, s.cases[k], j);
  }
  const std::string md = test::read_file(write_report(out));
  EXPECT_NE(md.find("| all cases | 2 | 1700 | undefined (2 points) | - | 0.2 | undefined (2 points) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("1 case(s) left out: a force that is missing or not positive"), std::string::npos) << md;
}

// Each steady mean with its 95 % interval: a weighted row beside the plain one, weighted by
// (F / CI)^2. The expected numbers come from fit_kienzle on the same data in N/mm (its weighting
// is checked against the closed form in StudyFits.WeightedFitMatchesClosedFormAndIgnoresWeightScale):
// this checks that the report pairs each force with its own interval column and prints both
// rows, to the 5 digits printed. (The weights are relative, so their unit cannot matter.)
TEST(Report, KienzleSectionWeightedByIntervals) {
  test::TempDir dir("fits_kienzle_ci");
  const std::string out = dir / "out";
  const Study s = recorded_study(dir, R"([grid]
mesh.0.origin = [[0, 0, 2.4e-3], [0, 0, 2.3e-3], [0, 0, 2.2e-3], [0, 0, 2.1e-3]]
)");
  const double e[4] = {0.05, -0.04, 0.02, -0.03}, ci_kN[4] = {30.0, 5.0, 40.0, 10.0};
  std::vector<double> h, F, ci;
  for (int k = 0; k < 4; ++k) {
    h.push_back(0.1 * (k + 1));
    F.push_back(1600.0 * std::pow(h.back(), 0.8) * std::exp(e[k]));
    ci.push_back(ci_kN[k]);
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", F.back() * 1e3},
                    {"cutting_force_per_width_ci95_N_per_m", ci.back() * 1e3}};
    j["chip"] = {{"depth_of_cut_m", h.back() * 1e-3}};
    write_case_summary(out, s, s.cases[k], j);
  }
  const KienzleFit plain = fit_kienzle(h, F), weighted = fit_kienzle(h, F, ci);
  ASSERT_GT(std::abs(plain.m - weighted.m), 1e-3);
  const std::string md = test::read_file(write_report(out));
  EXPECT_NE(md.find(fmt::format("| all cases | 4 | {:.5g} | {:.3g} |", plain.k11, plain.se_k11)), std::string::npos)
      << md;
  EXPECT_NE(md.find(fmt::format("| all cases, weighted | 4 | {:.5g} | {:.3g} |", weighted.k11, weighted.se_k11)),
            std::string::npos)
      << md;
  EXPECT_NE(md.find(fmt::format("| {:.5g} | {:.3g} | [{:.5g}, {:.5g}] |", weighted.m, weighted.se_m, weighted.m_low,
                                weighted.m_high)),
            std::string::npos)
      << md;
}

// A study whose cases have not run (or all failed): the report is written, without the fits.
TEST(Report, FitsLeftOutWithoutCompletedCases) {
  test::TempDir dir("fits_empty");
  const std::string out = dir / "out";
  const Study s = recorded_study(dir, R"([grid]
workpiece.radius = [1e-5, 2e-5, 4e-5]
)");
  const std::string md = test::read_file(write_report(out));
  EXPECT_NE(md.find("3 cases: 0 completed"), std::string::npos) << md;
  EXPECT_EQ(md.find("## Extrapolation"), std::string::npos) << md;
  EXPECT_EQ(md.find("## Kienzle"), std::string::npos) << md;
}

// A refinement study over workpiece.radius (ratio 2, the cells moving with the radius, a clamp
// key set by the coarsest point only, as in validation/studies/refinement.toml: neither splits):
// Fc/w = 2e5 (1 + (R / 4e-5)^2) N/m extrapolates to 2e5 N/m with p = 2; the chip thickness
// oscillates and falls back to the line, with the reason; no temperature column, no row.
TEST(Report, RichardsonSectionOverRadius) {
  test::TempDir dir("fits_richardson");
  const std::string out = dir / "out";
  const Study s = recorded_study(dir, R"([[point]]
workpiece.radius = 4e-5
workpiece.cells = [40, 2, 8]
group.1.box_min = [3.4e-3, -1.0, 0.06e-3]
[[point]]
workpiece.radius = 2e-5
workpiece.cells = [80, 2, 16]
[[point]]
workpiece.radius = 1e-5
workpiece.cells = [160, 2, 32]
)");
  const double thickness[3] = {3.0e-4, 3.2e-4, 3.1e-4};
  for (int k = 0; k < 3; ++k) {
    const double R = 4e-5 / std::pow(2.0, k);
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", 2e5 * (1.0 + std::pow(R / 4e-5, 2))},
                    {"thrust_force_per_width_mean_N_per_m", 1e5}};
    j["chip"] = {{"thickness_m", thickness[k]}};
    write_case_summary(out, s, s.cases[k], j);
  }
  const std::string md = test::read_file(write_report(out));
  ASSERT_NE(md.find("## Extrapolation to a vanishing particle radius"), std::string::npos) << md;
  // Fc: finest 2e5 * 1.0625 = 212500; f0 2e5; p 2; GCI 1.25 * 37500 / 3 = 15625; change 37500 / 212500.
  EXPECT_NE(md.find("| Fc/w (`cutting.cutting_force_per_width_mean_N_per_m`) | 3 (1, 1, 1) | 1e-05 | 2.125e+05 N/m | "
                    "2e+05 N/m | 2 (observed) | GCI 1.56e+04 N/m | 17.65 % (> 5 %) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 1e+05 N/m | 1 (assumed) |"), std::string::npos) << md;  // Ft constant: no order
  EXPECT_NE(md.find("- chip thickness h_c: oscillatory"), std::string::npos) << md;
  EXPECT_EQ(md.find("chip_temperature"), std::string::npos) << md;
  EXPECT_EQ(md.find("workpiece.cells ="), std::string::npos) << "the cells move with R: one group\n" << md;
  EXPECT_EQ(md.find("group.1.box_min ="), std::string::npos) << "one point's key: one group\n" << md;
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// A refinement in cutting terms (cut.layers = 5, 10, 20, as validation/studies/refinement_cut.toml):
// R stands as 1/layers, so f = 2e5 (1 + (5/layers)^2) extrapolates to 2e5 with p = 2 exactly as
// over the radius, the finest "R" printed as 1/20 in the unit 1/layers.
TEST(Report, RichardsonSectionOverLayers) {
  test::TempDir dir("fits_richardson_layers");
  const std::string out = dir / "out";
  const Study s = recorded_study(dir, "[grid]\ncut.layers = [5, 10, 20]\n");
  for (const StudyCase& c : s.cases) {
    const double layers = std::stod(c.values.at("cut.layers"));
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", 2e5 * (1.0 + std::pow(5.0 / layers, 2))}};
    write_case_summary(out, s, c, j);
  }
  const std::string md = test::read_file(write_report(out));
  ASSERT_NE(md.find("This study refines by `cut.layers`"), std::string::npos) << md;
  EXPECT_NE(md.find("| R finest [1/layers] |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 3 (1, 1, 1) | 0.05 | 2.125e+05 N/m | 2e+05 N/m | 2 (observed) | GCI 1.56e+04 N/m |"),
            std::string::npos)
      << md;
}

// The ensemble over seeds: three seeds of one point with Fc/w 300, 310, 320 kN/m give the mean
// 310, s = 10 and the interval t(2) s / sqrt 3 = 4.303 x 10 / 1.732 = 24.84 kN/m; each run's own
// half-width of 2.262 kN/m over 10 batches (t(9) = 2.262: a standard error of 1 kN/m) gives
// q = s / 1 = 10, the runs' own intervals far too narrow. Closed forms to the printed digits.
TEST(Report, EnsembleOverSeedsBesideTheRunsOwnIntervals) {
  test::TempDir dir("fits_ensemble");
  const std::string out = dir / "out";
  const Study s = recorded_study(
      dir, "repetitions = 3\nseed_key = \"workpiece.disorder_seed\"\n[grid]\ncut.speed = [10.0]\n");
  ASSERT_EQ(s.cases.size(), 3u);
  for (const StudyCase& c : s.cases) {
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", 300e3 + 10e3 * c.repetition},
                    {"cutting_force_per_width_ci95_N_per_m", 2.262157e3},
                    {"steady_batches", 10}};
    j["chip"] = {{"depth_of_cut_m", 2e-4}};
    write_case_summary(out, s, c, j);
  }
  const std::string md = test::read_file(write_report(out));
  ASSERT_NE(md.find("## Ensemble over seeds"), std::string::npos) << md;
  EXPECT_NE(md.find("| cut.speed = 10.0 | Fc/w | 3 | 310 kN/m | +- 24.8 kN/m | 10 kN/m | +- 2.26 kN/m | 10.00 |"),
            std::string::npos)
      << md;
  // One seed: no ensemble section (nothing to pool).
  test::TempDir one("fits_ensemble_one");
  const Study s1 = recorded_study(one, "[grid]\ncut.speed = [10.0]\n");
  write_case_summary(one / "out", s1, s1.cases[0], {{"cutting", {{"cutting_force_per_width_mean_N_per_m", 3e5}}}});
  EXPECT_EQ(test::read_file(write_report(one / "out")).find("## Ensemble over seeds"), std::string::npos);
}

// Oxley beside the cases: swarf's steady figure over Oxley's from each summary, the ratio to
// three digits; a case without Oxley's solution says where the reason is.
TEST(Report, OxleyBesideTheCases) {
  test::TempDir dir("fits_oxley");
  const std::string out = dir / "out";
  const Study s = recorded_study(dir, "[grid]\ncut.speed = [5.0, 10.0]\n");
  for (const StudyCase& c : s.cases) {
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", 310e3}};
    j["chip"] = {{"depth_of_cut_m", 2e-4}, {"thickness_m", 3.2e-4}};
    j["oxley"] = {{"speed_m_per_s", 10.0}, {"solved", c.id == "0000"}};
    if (c.id == "0000") j["oxley"].update({{"cutting_force_per_width_N_per_m", 248e3}, {"chip_thickness_m", 4e-4}});
    write_case_summary(out, s, c, j);
  }
  const std::string md = test::read_file(write_report(out));
  ASSERT_NE(md.find("## Oxley's theory beside the cases"), std::string::npos) << md;
  EXPECT_NE(md.find("| 310 / 248 = 1.250 | - | 0.32 / 0.4 = 0.800 | - |"), std::string::npos) << md;
  EXPECT_NE(md.find("no solution (the case's summary.json `oxley.reason` says why)"), std::string::npos) << md;
}

}  // namespace
}  // namespace swarf

// report.cpp: the Markdown report of a study (see report.h and docs/studies.md).
#include "study/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "io/atomic_file.h"
#include "postprocess/steady_stats.h"
#include "study/fits.h"
#include "study/study_record.h"
#include "study/study_table.h"

namespace swarf {

namespace fs = std::filesystem;

LinearFit fit_line_r2(const std::vector<double>& x, const std::vector<double>& y) {
  const OlsLine line = fit_ols(x, y);
  LinearFit f;
  f.n = line.n;
  if (!line.ok) return f;
  f.ok = true;
  f.slope = line.slope;
  f.intercept = line.intercept;
  f.r2 = line.r2;
  return f;
}

namespace {

std::string num(double v) { return fmt::format("{:.4g}", v); }

std::string header_cell(const StudyTable& t, int c) {
  const std::string& u = t.units[c];
  return u.empty() || u == "-" ? t.columns[c] : fmt::format("{} [{}]", t.columns[c], u);
}

// The table: case, varied keys, status and the given metrics (numbers to 4 digits).
std::string markdown_table(const StudyTable& t, const std::vector<std::string>& metrics) {
  std::vector<int> cols;
  for (std::size_t c = 0; c < t.first_metric; ++c) cols.push_back(int(c));
  for (const auto& m : metrics)
    if (t.column(m) >= int(t.first_metric)) cols.push_back(t.column(m));
  std::string out = "|";
  for (int c : cols) out += fmt::format(" {} |", header_cell(t, c));
  out += "\n|";
  for (std::size_t k = 0; k < cols.size(); ++k) out += "---|";
  out += "\n";
  bool any_ci = false;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    out += "|";
    for (int c : cols) {
      auto v = c >= int(t.first_metric) ? t.number(r, t.columns[c]) : std::nullopt;
      // A steady mean with its interval column: "value +- half-width".
      auto ci = v ? t.number(r, ci95_key_of(t.columns[c])) : std::nullopt;
      any_ci = any_ci || ci.has_value();
      out += fmt::format(" {}{} |", v ? num(*v) : t.rows[r][c], ci ? " +- " + num(*ci) : "");
    }
    out += "\n";
  }
  if (any_ci)
    out +=
        "\n`+-` after a value: the half-width of its 95 % confidence interval from batch means (the column "
        "`..._ci95...` "
        "of study.csv; docs/outputs.md); the `_std_` columns are the fluctuation over the steady part.\n";
  return out;
}

std::string case_label(const StudyTable& t, std::size_t r) {
  std::string out = t.rows[r][0];
  std::string keys;
  for (std::size_t c = 1; c + 1 < t.first_metric; ++c)
    keys += (keys.empty() ? "" : ", ") + t.columns[c] + " = " + t.rows[r][c];
  return keys.empty() ? out : out + " (" + keys + ")";
}

std::string fit_row(const std::string& what, const LinearFit& f, const char* slope_unit, const char* icpt_unit) {
  return fmt::format("| {} | {:.6g} {} | {:.6g} {} | {:.6f} | {} |\n", what, f.slope, slope_unit, f.intercept,
                     icpt_unit, f.r2, f.n);
}

// Shear angle measured against Merchant's 45 deg + gamma/2 - beta/2 (both from summary.json).
std::string merchant_section(const StudyTable& t) {
  std::string out = "## Shear angle against Merchant's theory\n\n";
  out +=
      "Merchant: phi_M = 45 deg + gamma/2 - beta/2, with the rake angle gamma of the tool and the friction angle "
      "beta = gamma + atan(Ft/Fc) from the mean forces (`chip.merchant_shear_angle_deg`); phi is the shear angle "
      "measured from the chip thickness (`chip.shear_angle_deg`). gamma is `chip.rake_angle_deg` where the summary has "
      "it, else recovered as 2 (phi_M - 45 deg) + beta.\n\n";
  out += "| case | gamma [deg] | beta [deg] | phi measured [deg] | phi Merchant [deg] | phi - phi_M [deg] |\n";
  out += "|---|---|---|---|---|---|\n";
  std::vector<double> ab, phi, diff;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto pm = t.number(r, "chip.merchant_shear_angle_deg");
    if (!pm) continue;
    const auto beta = t.number(r, "chip.friction_angle_deg");
    const auto p = t.number(r, "chip.shear_angle_deg");
    const double amb = 2.0 * (*pm - 45.0);
    const auto rake = t.number(r, "chip.rake_angle_deg");
    const std::string alpha = rake ? num(*rake) : beta ? num(amb + *beta) : "";
    out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", case_label(t, r), alpha, beta ? num(*beta) : "",
                       p ? num(*p) : "not measured", num(*pm), p ? num(*p - *pm) : "");
    if (p) {
      ab.push_back(amb);
      phi.push_back(*p);
      diff.push_back(*p - *pm);
    }
  }
  if (diff.empty()) return out + "\nNo case has a measured shear angle (the chip was too thin to measure).\n\n";
  double mean = 0, mabs = 0;
  for (double d : diff) {
    mean += d / double(diff.size());
    mabs += std::abs(d) / double(diff.size());
  }
  out += fmt::format(
      "\nOver {} cases with a measured shear angle: mean phi - phi_M = {} deg, mean |phi - phi_M| = {} deg.\n",
      diff.size(), num(mean), num(mabs));
  const LinearFit f = fit_line_r2(ab, phi);
  if (f.ok)
    out += fmt::format(
        "Least-squares line phi = a (gamma - beta) + b: a = {:.4g} (Merchant: 0.5), b = {:.4g} deg "
        "(Merchant: 45 deg), R^2 = {:.4f}, {} cases.\n",
        f.slope, f.intercept, f.r2, f.n);
  return out + "\n";
}

// Forces per width against the depth of cut, when it varies.
std::string depth_section(const StudyTable& t) {
  std::vector<std::pair<std::string, std::string>> forces{
      {"cutting force Fc/w", "cutting.cutting_force_per_width_mean_N_per_m"},
      {"thrust force Ft/w", "cutting.thrust_force_per_width_mean_N_per_m"}};
  std::set<double> depths;
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (auto d = t.number(r, "chip.depth_of_cut_m")) depths.insert(*d);
  if (depths.size() < 2) return "";
  std::string out = "## Forces against depth of cut\n\n";
  out +=
      "Least-squares lines F/w = slope h + intercept of the steady mean forces per width of the workpiece against "
      "the depth of cut h (`chip.depth_of_cut_m`). The slope is the specific cutting energy (N/m^2 = J/m^3); the "
      "intercept is the force per width that does not scale with h (edge and ploughing).\n\n";
  out += "| force | slope | intercept | R^2 | cases |\n|---|---|---|---|---|\n";
  for (const auto& [what, col] : forces) {
    std::vector<double> x, y;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      auto d = t.number(r, "chip.depth_of_cut_m");
      auto f = t.number(r, col);
      if (d && f) {
        x.push_back(*d);
        y.push_back(*f);
      }
    }
    const LinearFit f = fit_line_r2(x, y);
    if (f.ok) out += fit_row(what + " (`" + col + "`)", f, "N/m^2", "N/m");
  }
  return out + "\n";
}

// Cases that share every varied key that varies apart from x: the fits are made per group.
struct CaseGroup {
  std::string label;              ///< "key = value, ..." or "all cases"
  std::vector<std::size_t> rows;  ///< completed rows with an x
};

// Two x of one point: equal to 1 %, so that a measured x (the depth of cut, which a jittered
// surface moves by a fraction of a radius) still counts as one value.
bool same_x(double a, double b) { return std::abs(a - b) <= 0.01 * std::max(std::abs(a), std::abs(b)); }

// Groups the completed rows with an x by the varied keys other than x's own key and the seed
// key (repetitions are pooled). Only a key that takes two values at one x splits the cases; one
// that goes with x (the tool's origin of a depth study, the cells of a refinement, a key that
// only one point sets) does not.
std::vector<CaseGroup> groups_apart_from(const Study& study, const StudyTable& t,
                                         const std::vector<std::optional<double>>& x, const std::string& x_key) {
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (x[r] && t.status[r].state == CaseState::completed) rows.push_back(r);
  // The rows by x, and where each run of equal x (same_x of neighbours) starts.
  std::vector<std::size_t> by_x = rows;
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return *x[a] < *x[b]; });
  std::vector<int> keys;
  for (const auto& p : study.parameters) {
    if (p == study.seed_key || p == x_key || t.column(p) < 0) continue;
    const int c = t.column(p);
    bool splits = false;
    for (std::size_t k = 1, first = 0; k < by_x.size() && !splits; ++k) {
      if (!same_x(*x[by_x[k]], *x[by_x[k - 1]])) first = k;
      splits = t.rows[by_x[first]][c] != t.rows[by_x[k]][c];
    }
    if (splits) keys.push_back(c);
  }
  std::map<std::vector<std::string>, CaseGroup> by;
  for (std::size_t r : rows) {
    std::vector<std::string> values;
    std::string label;
    for (int c : keys) {
      values.push_back(t.rows[r][c]);
      label += (label.empty() ? "" : ", ") + t.columns[c] + " = " + t.rows[r][c];
    }
    CaseGroup& g = by[values];
    g.label = label.empty() ? "all cases" : label;
    g.rows.push_back(r);
  }
  std::vector<CaseGroup> out;
  for (auto& [v, g] : by) out.push_back(std::move(g));
  // Groups in the order of their first case.
  std::sort(out.begin(), out.end(), [](const CaseGroup& a, const CaseGroup& b) { return a.rows[0] < b.rows[0]; });
  return out;
}

// A column's finite numbers (a summary's "nan" or "inf" is no x to fit against).
std::vector<std::optional<double>> column_values(const StudyTable& t, const std::string& name) {
  std::vector<std::optional<double>> v(t.rows.size());
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (const auto x = t.number(r, name); x && std::isfinite(*x)) v[r] = x;
  return v;
}

std::string kienzle_row(const std::string& group, const KienzleFit& k) {
  if (!k.ok)
    return fmt::format("| {} | {} | fewer than two depths with a positive force: no fit | | | | | | |\n", group, k.n);
  if (!k.has_se)
    return fmt::format("| {} | {} | {:.5g} | undefined (2 points) | - | {:.5g} | undefined (2 points) | - | {:.6f} |\n",
                       group, k.n, k.k11, k.m, k.r2);
  return fmt::format("| {} | {} | {:.5g} | {:.3g} | [{:.5g}, {:.5g}] | {:.5g} | {:.3g} | [{:.5g}, {:.5g}] | {:.6f} |\n",
                     group, k.n, k.k11, k.se_k11, k.k11_low, k.k11_high, k.m, k.se_m, k.m_low, k.m_high, k.r2);
}

// Kienzle's law Fc/b = kc1.1 h^(1 - mc) per group of cases, with standard errors.
std::string kienzle_section(const Study& study, const StudyTable& t) {
  const std::string depth_col = "chip.depth_of_cut_m";
  const auto h = column_values(t, depth_col);
  std::vector<double> distinct;
  for (const auto& v : h)
    if (v && std::none_of(distinct.begin(), distinct.end(), [&](double d) { return same_x(d, *v); }))
      distinct.push_back(*v);
  if (distinct.size() < 2) return "";
  const std::vector<std::array<std::string, 3>> forces{
      {"cutting force Fc/b: kc1.1, mc", "cutting.cutting_force_per_width_mean_N_per_m", "kc1.1"},
      {"thrust force Ft/b: kt1.1, mt", "cutting.thrust_force_per_width_mean_N_per_m", "kt1.1"}};
  if (std::none_of(forces.begin(), forces.end(), [&](const auto& f) { return t.column(f[1]) >= 0; })) return "";
  const std::vector<CaseGroup> groups = groups_apart_from(study, t, h, depth_col);
  std::string out = "## Kienzle's law\n\n";
  out +=
      "Kienzle's law F/b = k1.1 h^(1 - m), fitted by least squares in log-log to the steady mean force per width "
      "(N/mm = kN/m, from the N/m of study.csv) against the depth of cut h (mm, `chip.depth_of_cut_m`): "
      "ln(F/b) = ln k1.1 + (1 - m) ln h. k1.1 [N/mm^2] is the force per width at h = 1 mm, m [1] the exponent. SE: "
      "standard errors from the fit's covariance (of k1.1 by the delta method, k1.1 SE(ln k1.1)); 95 % CI from "
      "Student's t with n - 2 degrees of freedom (for k1.1 the interval of ln k1.1, mapped through exp). With two "
      "points the line passes through both and the errors are undefined. Rows marked weighted: the same fit with "
      "weights (F / CI)^2 from each steady mean's 95 % interval (the `_ci95_` column), its scatter scale from the "
      "weighted residuals; given where every case of the group has an interval.";
  out += groups.size() > 1 ? " One fit per group of the other varied keys (repetitions pooled as points), then all "
                             "cases pooled.\n\n"
                           : " Repetitions of a point are pooled as points.\n\n";
  for (const auto& [what, col, name] : forces) {
    if (t.column(col) < 0) continue;
    out += fmt::format("{} (`{}`)\n\n", what, col);
    out += fmt::format("| cases | points | {0} [N/mm^2] | SE | 95 % CI | {1} | SE | 95 % CI | R^2 (log-log) |\n", name,
                       name == "kc1.1" ? "mc" : "mt");
    out += "|---|---|---|---|---|---|---|---|---|\n";
    std::size_t skipped = 0;
    const std::string ci_col = ci95_key_of(col);
    // weighted: by each mean's 95 % interval (fits.h); a case without one is left out there.
    auto fit_rows = [&](const std::vector<std::size_t>& rows, bool weighted) {
      std::vector<double> hx, fy, ci;
      for (std::size_t r : rows) {
        hx.push_back(*h[r] * 1e3);                           // m -> mm
        fy.push_back(t.number(r, col).value_or(NAN) / 1e3);  // N/m -> N/mm; none: left out, counted
        if (weighted) ci.push_back(t.number(r, ci_col).value_or(NAN) / 1e3);
      }
      return fit_kienzle(hx, fy, ci);
    };
    // The weighted row, only where every case of the plain fit has its interval.
    auto weighted_row = [&](const std::string& label, const std::vector<std::size_t>& rows, const KienzleFit& plain) {
      if (ci_col.empty() || t.column(ci_col) < 0) return std::string();
      const KienzleFit w = fit_rows(rows, true);
      return w.ok && w.n == plain.n ? kienzle_row(label + ", weighted", w) : std::string();
    };
    std::vector<std::size_t> all;
    for (const auto& g : groups) {
      const KienzleFit k = fit_rows(g.rows, false);
      skipped += k.skipped;
      out += kienzle_row(g.label, k) + weighted_row(g.label, g.rows, k);
      all.insert(all.end(), g.rows.begin(), g.rows.end());
    }
    if (groups.size() > 1) {
      const KienzleFit k = fit_rows(all, false);
      out += kienzle_row("all cases pooled", k) + weighted_row("all cases pooled", all, k);
    }
    if (skipped)
      out += fmt::format(
          "\n{} case(s) left out: a force that is missing or not positive, or a depth that is not "
          "positive, has no logarithm.\n",
          skipped);
    out += "\n";
  }
  return out;
}

// Richardson's extrapolation of the cut's numbers to a vanishing particle radius.
std::string richardson_section(const Study& study, const StudyTable& t) {
  const auto varied = [&](const char* key) {
    return std::find(study.parameters.begin(), study.parameters.end(), key) != study.parameters.end();
  };
  // A study in cutting terms refines by cut.layers: at a fixed depth of cut h the radius is
  // R = h / (layers sqrt 2), proportional to 1/layers, and Richardson needs only its ratios.
  const bool by_layers = !varied("workpiece.radius") && varied("cut.layers");
  if (!varied("workpiece.radius") && !by_layers) return "";
  const std::string radius_key = by_layers ? "cut.layers" : "workpiece.radius";
  auto R = column_values(t, radius_key);
  if (by_layers)
    for (auto& v : R) v = v && *v > 0 ? std::optional<double>(1.0 / *v) : std::nullopt;
  const std::string r_unit = by_layers ? "1/layers" : "m";
  const std::vector<CaseGroup> groups = groups_apart_from(study, t, R, radius_key);
  std::set<double> radii;
  for (const auto& g : groups)
    for (std::size_t r : g.rows) radii.insert(*R[r]);
  if (radii.size() < 2) return "";
  const std::vector<std::array<std::string, 3>> quantities{
      {"Fc/w", "cutting.cutting_force_per_width_mean_N_per_m", "N/m"},
      {"Ft/w", "cutting.thrust_force_per_width_mean_N_per_m", "N/m"},
      {"chip thickness h_c", "chip.thickness_m", "m"},
      {"chip temperature", "chip.chip_temperature_K", "K"}};
  std::string out = "## Extrapolation to a vanishing particle radius\n\n";
  out +=
      "Richardson's extrapolation of f(R) = f0 + c R^p to R -> 0 over the particle radius R (`workpiece.radius`, m); "
      "repetitions of a radius are averaged first. With three or more radii the order p is observed on the three "
      "finest (Celik et al. 2008, J. Fluids Eng. 130:078001) and the error bar is Roache's grid convergence index "
      "GCI = 1.25 |f1 - f2| / (r^p - 1) of the finest radius (r = R2/R1); when the differences change sign, or p "
      "is undefined or outside [0.5, 4], p = 1 is assumed, f0 is the intercept of the least-squares line f = f0 + "
      "c R over all radii and the error bar its standard error. With two radii p = 1 is assumed and GCI = "
      "3 |f1 - f2| / (r - 1). Change: |f1 - f2| / |f1| between the two finest radii (converged: at most 5 %).\n\n";
  if (by_layers)
    out +=
        "This study refines by `cut.layers`: R stands as 1/layers (at the fixed depth of cut h the radius is h / "
        "(layers sqrt 2), proportional to it; the extrapolation needs only the ratios).\n\n";
  for (const auto& g : groups) {
    if (groups.size() > 1) out += fmt::format("{}\n\n", g.label);
    out += "| quantity | radii (cases per radius, finest first) | R finest [" + r_unit +
           "] | f at R finest | f0 (R -> 0) | p | "
           "error bar | change |\n|---|---|---|---|---|---|---|---|\n";
    std::string notes;
    for (const auto& [what, col, unit] : quantities) {
      if (t.column(col) < 0) continue;
      std::vector<double> rx, fy;
      for (std::size_t r : g.rows)
        if (const auto f = t.number(r, col)) {
          rx.push_back(*R[r]);
          fy.push_back(*f);
        }
      const Richardson e = richardson(rx, fy);
      const std::string name = fmt::format("{} (`{}`)", what, col);
      if (e.method == RichardsonMethod::none) {
        out += fmt::format("| {} | {} | fewer than two radii: no extrapolation | | | | | |\n", name, e.radii);
        continue;
      }
      std::string counts;
      for (const auto& m : means_at_x(rx, fy)) counts += (counts.empty() ? "" : ", ") + std::to_string(m.n);
      const std::string p = e.method == RichardsonMethod::observed_order ? fmt::format("{:.3g} (observed)", e.p)
                                                                         : std::string("1 (assumed)");
      const std::string err = !e.has_error                         ? "undefined"
                              : e.method == RichardsonMethod::line ? fmt::format("SE {:.3g} {}", e.error, unit)
                                                                   : fmt::format("GCI {:.3g} {}", e.error, unit);
      out += fmt::format("| {} | {} ({}) | {:.4g} | {:.5g} {} | {:.5g} {} | {} | {} | {:.2f} % ({}) |\n", name, e.radii,
                         counts, e.R_finest, e.f_finest, unit, e.f0, unit, p, err, 100.0 * e.change,
                         e.change <= 0.05 ? "<= 5 %" : "> 5 %");
      if (!e.note.empty())
        notes += fmt::format("- {}: {}; p = 1 assumed (least-squares line over {} radii).\n", what, e.note, e.radii);
      if (e.skipped) notes += fmt::format("- {}: {} case(s) left out (a value that is not finite).\n", what, e.skipped);
    }
    out += notes.empty() ? "\n" : "\n" + notes + "\n";
  }
  return out;
}

// The cut's steady figures that the ensemble and Oxley sections read: label, study column, unit
// to print, the factor from the column's unit to it.
struct Figure {
  const char* what;
  const char* column;
  const char* unit;
  double scale;
};
const std::vector<Figure>& cut_figures() {
  static const std::vector<Figure> f{{"Fc/w", "cutting.cutting_force_per_width_mean_N_per_m", "kN/m", 1e-3},
                                     {"Ft/w", "cutting.thrust_force_per_width_mean_N_per_m", "kN/m", 1e-3},
                                     {"chip thickness h_c", "chip.thickness_m", "mm", 1e3},
                                     {"contact length", "chip.contact_length_m", "mm", 1e3},
                                     {"chip temperature", "chip.chip_temperature_K", "K", 1.0},
                                     {"rake-face temperature", "chip.rake_face_temperature_K", "K", 1.0}};
  return f;
}

// The ensemble over the seeds of each point: the mean over its repetitions with the 95 %
// interval t(n-1) s / sqrt(n) of the repetitions' scatter s, beside the runs' own intervals
// (batch means within one run). The spread between seeds is the honest error of a chaotic cut;
// a run's own interval that is narrower than s / sqrt(n) would make it (s over the runs' own
// standard error well above 1) is too narrow (docs/studies.md).
std::string ensemble_section(const Study& study, const StudyTable& t) {
  if (study.seed_key.empty() || study.repetitions < 2) return "";
  // The points: completed rows that share every varied key but the seed.
  std::map<std::vector<std::string>, std::vector<std::size_t>> points;
  std::vector<std::vector<std::string>> order;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.status[r].state != CaseState::completed) continue;
    std::vector<std::string> key;
    for (const auto& p : study.parameters)
      if (p != study.seed_key && t.column(p) >= 0) key.push_back(p + " = " + t.rows[r][t.column(p)]);
    if (!points.count(key)) order.push_back(key);
    points[key].push_back(r);
  }
  std::string out = "## Ensemble over seeds\n\n";
  out += fmt::format(
      "Each point's repetitions over `{}` as an ensemble: the mean over its n seeds with the 95 % interval "
      "t(n-1) s / sqrt(n), s the standard deviation between the seeds' steady means; beside it the mean of the "
      "runs' "
      "own 95 % half-widths (batch means within one run) and q = s / (the runs' own standard error, their "
      "half-width "
      "over t of their batches' degrees of freedom). q near 1: the runs' own intervals are honest; q well above 1 "
      "(beyond about 2 with 3 seeds): they are too narrow, and the ensemble's interval is the one to quote.\n\n",
      study.seed_key);
  out += "| point | quantity | n | ensemble mean | 95 % interval | s between seeds | runs' own 95 % (mean) | q |\n";
  out += "|---|---|---|---|---|---|---|---|\n";
  for (const auto& key : order) {
    std::string label;
    for (const auto& k : key) label += (label.empty() ? "" : ", ") + k;
    if (label.empty()) label = "all cases";
    const auto& rows = points[key];
    for (const Figure& f : cut_figures()) {
      if (t.column(f.column) < 0) continue;
      std::vector<double> v, own_se, own_ci;
      for (std::size_t r : rows) {
        const auto x = t.number(r, f.column);
        if (!x || !std::isfinite(*x)) continue;
        v.push_back(*x);
        const auto ci = t.number(r, ci95_key_of(f.column));
        const auto batches = t.number(r, "cutting.steady_batches");
        if (ci && std::isfinite(*ci)) {
          own_ci.push_back(*ci);
          if (batches && *batches >= 2) own_se.push_back(*ci / student_t_975(std::size_t(*batches) - 1));
        }
      }
      if (v.size() < 2) {
        out += fmt::format("| {} | {} | {} | fewer than two seeds with a value: no ensemble | | | | |\n", label, f.what,
                           v.size());
        continue;
      }
      const double n = double(v.size());
      double mean = 0, ss = 0;
      for (double x : v) mean += x / n;
      for (double x : v) ss += (x - mean) * (x - mean);
      const double sd = std::sqrt(ss / (n - 1));
      const double half = student_t_975(v.size() - 1) * sd / std::sqrt(n);
      double own = 0, se = 0;
      for (double c : own_ci) own += c / double(own_ci.size());
      for (double e : own_se) se += e / double(own_se.size());
      out += fmt::format("| {} | {} | {} | {:.4g} {} | +- {:.3g} {} | {:.3g} {} | {} | {} |\n", label, f.what, v.size(),
                         f.scale * mean, f.unit, f.scale * half, f.unit, f.scale * sd, f.unit,
                         own_ci.empty() ? std::string("-") : fmt::format("+- {:.3g} {}", f.scale * own, f.unit),
                         own_se.empty() || !(se > 0) ? std::string("-") : fmt::format("{:.2f}", sd / se));
    }
  }
  return out + "\n";
}

// Oxley's theory beside each case (summary.json "oxley", postprocess/cut_oxley.h): swarf's
// steady figure over Oxley's for the same material, speed, depth, rake and width (the pairs:
// the result key table's "oxley" field).
std::string oxley_section(const StudyTable& t) {
  std::vector<std::pair<Figure, std::string>> pairs;
  for (const Figure& f : cut_figures())
    if (auto o = oxley_key_of(f.column); !o.empty()) pairs.emplace_back(f, o);
  if (t.column("oxley.speed_m_per_s") < 0) return "";
  std::string out = "## Oxley's theory beside the cases\n\n";
  out +=
      "Oxley's predictive machining theory solved for each case's material, cutting speed, depth of cut, rake angle "
      "and width (summary.json `oxley`; docs/outputs.md): a physics cross-check for a sharp tool and a continuous "
      "chip, not a measurement. Each cell: swarf / Oxley = ratio.\n\n| case |";
  for (const auto& [p, o] : pairs) out += fmt::format(" {} [{}] |", p.what, p.unit);
  out += "\n|---|";
  for (std::size_t k = 0; k < pairs.size(); ++k) out += "---|";
  out += "\n";
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.status[r].state != CaseState::completed) continue;
    out += fmt::format("| {} |", case_label(t, r));
    if (!t.number(r, "oxley.cutting_force_per_width_N_per_m")) {
      out += " no solution (the case's summary.json `oxley.reason` says why) |";
      for (std::size_t k = 1; k < pairs.size(); ++k) out += " |";
      out += "\n";
      continue;
    }
    for (const auto& [p, o] : pairs) {
      const auto a = t.number(r, p.column), b = t.number(r, o);
      const double scale = p.scale;
      if (!b) {
        out += " - |";
      } else if (!a || !std::isfinite(*a)) {
        out += fmt::format(" none / {:.4g} |", scale * *b);
      } else {
        out += fmt::format(" {:.4g} / {:.4g} = {:.3f} |", scale * *a, scale * *b, *a / *b);
      }
    }
    out += "\n";
  }
  return out + "\n";
}

}  // namespace

std::string write_report(const std::string& dir) {
  const Study study = read_study_json(dir);
  const StudyTable t = collect_table(study, dir);
  const fs::path plots = fs::path(dir) / "plots";
  auto pngs = [&]() {
    std::vector<std::string> out;
    if (fs::exists(plots))
      for (const auto& e : fs::directory_iterator(plots))
        if (e.path().extension() == ".png") out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  };
  std::string plot_note;
  if (study.plots && pngs().empty()) plot_note = draw_plots(study, t, dir);

  std::size_t completed = 0, failed = 0;
  for (const auto& s : t.status) {
    completed += s.state == CaseState::completed;
    failed += s.state == CaseState::failed;
  }
  std::string md = fmt::format("# Study report: {}\n\n", study.title.empty() ? study.file : study.title);
  md += fmt::format("- study file: `{}`; base case: `{}`\n", study.file, study.base_path);
  if (!study.fixed.empty()) {
    md += "- set in every case:";
    for (const auto& [k, v] : study.fixed) md += fmt::format(" `{}={}`", k, v);
    md += "\n";
  }
  md += fmt::format("- {} cases: {} completed, {} failed, {} not finished\n", t.rows.size(), completed, failed,
                    t.rows.size() - completed - failed);
  md +=
      "- all metrics: [study.csv](study.csv); wall times: [timing.csv](timing.csv); the columns' units and "
      "meanings: [study_columns.csv](study_columns.csv)\n\n";

  const std::vector<std::string> metrics = study.plot_metrics.empty() ? default_plot_metrics(t) : study.plot_metrics;
  md += "## Cases\n\n" + markdown_table(t, metrics) + "\n";

  if (failed) {
    md += "## Failed cases\n\n";
    for (std::size_t r = 0; r < t.rows.size(); ++r)
      if (t.status[r].state == CaseState::failed)
        md += fmt::format("- {}: {}, log `cases/{}/log.txt`, last lines:\n\n```\n{}```\n\n", case_label(t, r),
                          t.status[r].text(), t.rows[r][0], t.status[r].log_tail);
  }

  md += "## Plots\n\n";
  const auto files = pngs();
  if (files.empty())
    md += plot_note.empty() ? "No plots (plots = false in the study file).\n\n" : "No plots: " + plot_note + "\n\n";
  for (const auto& f : files) md += fmt::format("![{}](plots/{})\n\n", f.substr(0, f.size() - 4), f);

  if (t.column("chip.merchant_shear_angle_deg") >= 0 && t.column("cutting.cutting_force_per_width_mean_N_per_m") >= 0) {
    md += merchant_section(t);
    md += depth_section(t);
  }
  md += kienzle_section(study, t);
  md += richardson_section(study, t);
  md += ensemble_section(study, t);
  md += oxley_section(t);
  const std::string path = (fs::path(dir) / "report.md").string();
  write_text_atomic(path, md);
  return path;
}

}  // namespace swarf

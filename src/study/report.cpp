// report.cpp: the Markdown report of a study (see report.h and docs/studies.md).
#include "study/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "io/atomic_file.h"
#include "postprocess/hysteresis.h"
#include "study/study_record.h"
#include "study/study_table.h"

namespace swarf {

namespace fs = std::filesystem;

LinearFit fit_line_r2(const std::vector<double>& x, const std::vector<double>& y) {
  LinearFit f;
  f.n = std::min(x.size(), y.size());
  if (f.n < 2 || std::set<double>(x.begin(), x.begin() + f.n).size() < 2) return f;
  const LineFit line = fit_line(std::vector<double>(x.begin(), x.begin() + f.n),
                                std::vector<double>(y.begin(), y.begin() + f.n));
  f.ok = true;
  f.slope = line.slope;
  f.intercept = line.intercept;
  double my = 0, ss_res = 0, ss_tot = 0;
  for (std::size_t k = 0; k < f.n; ++k) my += y[k] / double(f.n);
  for (std::size_t k = 0; k < f.n; ++k) {
    const double e = y[k] - (f.slope * x[k] + f.intercept);
    ss_res += e * e;
    ss_tot += (y[k] - my) * (y[k] - my);
  }
  f.r2 = ss_tot > 0 ? 1.0 - ss_res / ss_tot : (ss_res == 0 ? 1.0 : 0.0);
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
  const std::string path = (fs::path(dir) / "report.md").string();
  write_text_atomic(path, md);
  return path;
}

}  // namespace swarf

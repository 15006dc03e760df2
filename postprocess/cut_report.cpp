// cut_report.cpp: the end-of-cut analysis and table (see cut_report.h).
#include "postprocess/cut_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/h5file.h"
#include "io/results_format.h"
#include "postprocess/json_number.h"
#include "postprocess/steady_stats.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"

namespace swarf {

// What to quote instead of one run's interval when its batches are too short (docs/studies.md,
// "Ensemble over seeds"): the spread over seeds of a position jitter.
constexpr const char* kEnsembleHint =
    "for an honest interval run an ensemble over seeds (a study with seed_key = \"workpiece.disorder_seed\", "
    "as validation/studies/disorder_seeds.toml) and quote swarf report's ensemble interval";
namespace {

constexpr std::size_t kMinThicknessRows = 5;
constexpr double kDeg = M_PI / 180.0;

// summary.json has no NaN: an unavailable number (an interval of too short a series) is null.
nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// A cut with free sides (an oblique cut): the passive force's steady mean, and the chip's flow
// angle and width as the steady medians of the rows that measured them (as h_c), beside
// Stabler's flow rule eta_c = lambda and the width the chip would have without side flow.
void free_side_figures(const CutSetup& s, const CutData& d, CutResult& out) {
  if (d.passive_force.empty()) return;
  std::vector<double> fp, eta, width;
  for (std::size_t k = 0; k < d.time.size(); ++k) {
    if (d.time[k] < s.steady_from) continue;
    if (k < d.passive_force.size()) fp.push_back(d.passive_force[k]);
    if (k < d.chip_width.size() && k < d.chip_flow_angle.size() && d.chip_width[k] > 0) {
      eta.push_back(d.chip_flow_angle[k]);
      width.push_back(d.chip_width[k]);
    }
  }
  const SteadyStats fps = steady_stats(fp);
  out.cutting["passive_force_per_width_mean_N_per_m"] = fp.empty() ? nlohmann::json(nullptr) : nlohmann::json(fps.mean);
  out.cutting["passive_force_per_width_ci95_N_per_m"] = finite_or_null(fps.ci95);
  // The force away from the sides, for the comparison with plane strain.
  for (const auto& [rows, name] : {std::pair{&d.fc_middle, "cutting"}, std::pair{&d.ft_middle, "thrust"}}) {
    if (rows->empty()) continue;
    std::vector<double> v;
    for (std::size_t k = 0; k < d.time.size() && k < rows->size(); ++k)
      if (d.time[k] >= s.steady_from) v.push_back((*rows)[k]);
    const SteadyStats st = steady_stats(v);
    out.cutting[fmt::format("{}_force_per_width_middle_mean_N_per_m", name)] = v.empty() ? nlohmann::json(nullptr)
                                                                                         : nlohmann::json(st.mean);
    out.cutting[fmt::format("{}_force_per_width_middle_ci95_N_per_m", name)] = finite_or_null(st.ci95);
  }
  out.chip["inclination_deg"] = s.inclination_deg;
  out.chip["flow_angle_stabler_deg"] = s.inclination_deg;
  out.chip["flow_rows"] = eta.size();
  if (eta.size() < kMinThicknessRows) {
    out.chip["flow_note"] = fmt::format(
        "chip flow angle and width not measured: {} steady rows measured them (at least {} needed)", eta.size(),
        kMinThicknessRows);
    return;
  }
  out.chip["flow_angle_deg"] = quantile(eta, 0.5);
  out.chip["flow_angle_ci95_deg"] = finite_or_null(eta.size() >= kSteadyMinSamples ? batch_ci95(batch_medians(eta))
                                                                                   : NAN);
  out.chip["width_m"] = quantile(width, 0.5);
  out.chip["width_ci95_m"] = finite_or_null(width.size() >= kSteadyMinSamples ? batch_ci95(batch_medians(width)) : NAN);
  out.chip["width_to_cut_width"] = quantile(width, 0.5) / s.edge_width();
}

}  // namespace

ChipInput chip_input(const CutSetup& setup, std::vector<Vec3> position, const Vec3& tool_tip) {
  ChipInput ci;
  if (setup.inclination_deg != 0.0)
    for (Vec3& x : position) x = tool_tip + to_tool_frame(x - tool_tip, setup.inclination_deg);
  ci.position = std::move(position);
  ci.radius = setup.radius;
  ci.uncut_surface_z = setup.uncut_surface_z;
  ci.tool_tip = tool_tip;
  ci.rake_angle_deg = setup.rake_angle_deg;
  ci.depth_of_cut = setup.uncut_surface_z - tool_tip[2];
  ci.face_length = setup.face_length;
  return ci;
}

double broken_rod_fraction(std::span<const std::uint8_t> intact, std::span<const std::uint8_t> formed) {
  if (!formed.empty() && formed.size() != intact.size())
    throw InputError(
        fmt::format("broken-rod fraction: {} intact flags but {} formed flags", intact.size(), formed.size()));
  std::size_t own = 0, broken = 0;
  for (std::size_t k = 0; k < intact.size(); ++k) {
    if (!formed.empty() && formed[k]) continue;
    ++own;
    broken += intact[k] ? 0 : 1;
  }
  return double(broken) / std::max<double>(1.0, double(own));  // (no rods: 0, not NaN)
}

CutResult analyze_cut(const CutSetup& s, const CutData& d) {
  CutResult out;
  // The steady part's rows.
  std::vector<double> time, fc_rows, ft_rows;
  for (std::size_t k = 0; k < d.time.size(); ++k)
    if (d.time[k] >= s.steady_from) {
      time.push_back(d.time[k]);
      fc_rows.push_back(k < d.fc.size() ? d.fc[k] : NAN);
      ft_rows.push_back(k < d.ft.size() ? d.ft[k] : NAN);
    }
  const std::size_t samples = time.size();
  // No steady rows (a run that ended before its steady window): no force to report, which is
  // not a force of 0 N/m. The means and deviations are null, and the note says why.
  // Mean, sample deviation and the batch-means interval of the forces per width (steady_stats.h).
  const SteadyStats fcs = steady_stats(fc_rows), fts = steady_stats(ft_rows);
  const double fc = samples > 0 ? fcs.mean : 0.0, ft = samples > 0 ? fts.mean : 0.0;
  const double row_interval = samples >= 2 ? (time.back() - time.front()) / double(samples - 1) : NAN;  // s
  // Ft/Fc from the means; its interval by the delta method over the batch means of both forces
  // (the same rows): dR = (dFt - R dFc) / Fc.
  const std::vector<double> bfc = batch_means(fc_rows), bft = batch_means(ft_rows);
  const double ratio = fc != 0 ? ft / fc : NAN;
  out.cutting = {
      {"tool_mesh", s.tool_mesh},
      {"width_m", s.width},
      {"steady_from_s", s.steady_from},
      {"steady_samples", samples},
      {"cutting_force_per_width_mean_N_per_m", samples > 0 ? nlohmann::json(fc) : nlohmann::json(nullptr)},
      {"cutting_force_per_width_std_N_per_m", samples > 1 ? nlohmann::json(fcs.std) : nlohmann::json(nullptr)},
      {"cutting_force_per_width_ci95_N_per_m", finite_or_null(fcs.ci95)},
      {"cutting_force_per_width_autocorrelation_time_s", finite_or_null(fcs.autocorrelation_time * row_interval)},
      {"cutting_force_per_width_effective_samples", finite_or_null(fcs.effective_samples)},
      {"thrust_force_per_width_mean_N_per_m", samples > 0 ? nlohmann::json(ft) : nlohmann::json(nullptr)},
      {"thrust_force_per_width_std_N_per_m", samples > 1 ? nlohmann::json(fts.std) : nlohmann::json(nullptr)},
      {"thrust_force_per_width_ci95_N_per_m", finite_or_null(fts.ci95)},
      {"thrust_force_per_width_autocorrelation_time_s", finite_or_null(fts.autocorrelation_time * row_interval)},
      {"thrust_force_per_width_effective_samples", finite_or_null(fts.effective_samples)},
      {"thrust_to_cutting_force_ratio", finite_or_null(ratio)},
      // (no steady rows: Fc = 0 and no ratio; 1 / Fc would divide by zero)
      {"thrust_to_cutting_force_ratio_ci95",
       finite_or_null(fc != 0 ? batch_ci95_linear(bfc, bft, -ratio / fc, 1 / fc) : NAN)},
      {"steady_batches", fcs.batches},
      {"steady_batch_samples", fcs.batches > 0 ? fcs.batch_size : 0},
      {"broken_fraction", d.broken_rod_fraction}};
  // Shop-floor units beside SI: kc = Fc / (b h) in N/mm^2 (Kienzle's, handbooks'), and the
  // forces in N on the width the run simulated (a plane-strain slice's, or a finite cut's).
  // h is the geometric depth of cut, exact, so kc's interval is Fc/w's over h.
  const double h = s.uncut_surface_z - s.tool_tip[2];  // m
  const bool has_kc = samples > 0 && h > 0;
  out.cutting["specific_cutting_force_N_per_mm2"] = has_kc ? nlohmann::json(fc / h * 1e-6) : nlohmann::json(nullptr);
  out.cutting["specific_cutting_force_ci95_N_per_mm2"] = finite_or_null(has_kc ? fcs.ci95 / h * 1e-6 : NAN);
  out.cutting["cutting_force_N"] = samples > 0 ? nlohmann::json(fc * s.width) : nlohmann::json(nullptr);
  out.cutting["thrust_force_N"] = samples > 0 ? nlohmann::json(ft * s.width) : nlohmann::json(nullptr);
  if (samples == 0)
    out.cutting
        ["steady_note"] = d.time.empty()
                              ? std::string("the series has no rows: no steady forces")
                              : fmt::format(
                                    "the steady window starts at {:.4g} s, after the end of the run at {:.4g} s: no "
                                    "steady rows, so no steady forces (lower output.steady_from, or run longer)",
                                    s.steady_from, d.time.back());
  if (fcs.batches_short() || fts.batches_short()) {
    const char* which = fcs.batches_short() && fts.batches_short()
                            ? "cutting_force_per_width and thrust_force_per_width"
                        : fcs.batches_short() ? "cutting_force_per_width"
                                              : "thrust_force_per_width";
    out.cutting["ci95_note"] = fmt::format(
        "batches of {} rows are shorter than {} autocorrelation times of {}: the 95 % intervals may be too narrow; "
        "{}",
        fcs.batch_size, kSteadyBatchesPerTau, which, kEnsembleHint);
  }

  const ChipInput ci = chip_input(s, d.position, s.tool_tip);
  out.metrics = measure_chip(ci);
  const ChipMetrics& cm = out.metrics;
  // h_c over the steady part: the median of the rows' measurements.
  std::vector<double> steady_hc;
  for (std::size_t k = 0; k < d.chip_thickness.size() && k < d.time.size(); ++k)
    if (d.time[k] >= s.steady_from && d.chip_thickness[k] > 0) steady_hc.push_back(d.chip_thickness[k]);
  // beta - gamma = atan2(Ft, Fc) of the means; linearised: d(beta) = (Fc dFt - Ft dFc) / (Fc^2 + Ft^2) rad.
  // No force (no steady rows, or the tool never touched): no direction, so no angle.
  const double f2 = fc * fc + ft * ft;
  const double beta = f2 > 0 ? friction_angle_deg(fc, ft, s.rake_angle_deg) : NAN;
  const double beta_ci = f2 > 0 ? batch_ci95_linear(bfc, bft, -ft / f2, fc / f2) / kDeg : NAN;
  double chip_broken = 0.0;
  for (auto i : cm.members) chip_broken += i < d.broken_fraction.size() ? d.broken_fraction[i] : 0.0;
  std::size_t damaged = 0;
  for (double b : d.broken_fraction) damaged += b > 0 ? 1 : 0;
  out.chip = {{"depth_of_cut_m", ci.depth_of_cut},
              {"rake_angle_deg", s.rake_angle_deg},
              {"chip_particles", cm.chip_particles},
              {"measured_particles", cm.measured_particles},
              {"friction_angle_deg", finite_or_null(beta)},
              {"friction_angle_ci95_deg", finite_or_null(beta_ci)},
              {"merchant_shear_angle_deg", finite_or_null(merchant_shear_angle_deg(s.rake_angle_deg, beta))},
              {"merchant_shear_angle_ci95_deg", finite_or_null(0.5 * beta_ci)},
              {"chip_broken_fraction_mean", cm.members.empty() ? 0.0 : chip_broken / double(cm.members.size())},
              {"damaged_particle_fraction",
               d.broken_fraction.empty() ? 0.0 : double(damaged) / double(d.broken_fraction.size())}};
  if (cm.thickness > 0) out.chip["thickness_final_m"] = cm.thickness;
  // The chip's up-curl radius in the end state (chip.h); null with a note when it is not measured.
  const ChipCurl curl = measure_chip_curl(ci, cm);
  out.chip["curl_points"] = curl.points;
  out.chip["curl_radius_m"] = curl.measured ? nlohmann::json(curl.radius) : nlohmann::json(nullptr);
  out.chip["curl_fit_rms_m"] = curl.measured ? nlohmann::json(curl.fit_rms) : nlohmann::json(nullptr);
  out.chip["curl_arc_deg"] = curl.measured ? nlohmann::json(curl.arc_deg) : nlohmann::json(nullptr);
  if (!curl.measured) out.chip["curl_note"] = "chip curl radius not measured: " + curl.note;
  double hc = 0.0, hc_ci = NAN;
  if (steady_hc.size() >= kMinThicknessRows) {
    hc = quantile(steady_hc, 0.5);
    out.chip["thickness_p10_m"] = quantile(steady_hc, 0.1);
    out.chip["thickness_p90_m"] = quantile(steady_hc, 0.9);
    out.chip["thickness_rows"] = steady_hc.size();
    // The median's interval from batch medians: the sample median is asymptotically a mean (of
    // sign(x - median) / (2 f(median)), Bahadur's representation), so the medians of long batches
    // behave as batch means do. From kSteadyMinSamples measured rows on.
    if (steady_hc.size() >= kSteadyMinSamples) {
      hc_ci = batch_ci95(batch_medians(steady_hc));
      const double tau = integrated_autocorrelation_time(steady_hc);
      out.chip["thickness_effective_rows"] = finite_or_null(double(steady_hc.size()) / tau);
      if (std::isfinite(tau) && double(steady_hc.size() / kSteadyBatches) < kSteadyBatchesPerTau * tau)
        out.chip["ci95_note"] = fmt::format(
            "batches of {} rows are shorter than {} autocorrelation times ({:.3g} rows) of the chip thickness: its "
            "95 % interval (and those of the ratio and shear angle) may be too narrow; {}",
            steady_hc.size() / kSteadyBatches, kSteadyBatchesPerTau, tau, kEnsembleHint);
    }
    out.chip["thickness_ci95_m"] = finite_or_null(hc_ci);
  } else if (d.chip_thickness.empty() && cm.thickness > 0) {
    hc = cm.thickness;  // a run of an earlier version: no per-row thickness, the last state's
    out.chip["thickness_note"] = "series.csv has no chip_thickness column: h_c is the last state's";
    out.chip["thickness_ci95_m"] = nullptr;  // one state: no interval
  }
  if (hc > 0) {
    out.chip["thickness_m"] = hc;
    const double r = ci.depth_of_cut / hc, a = s.rake_angle_deg * kDeg;
    out.chip["compression_ratio"] = r;
    out.chip["shear_angle_deg"] = shear_angle_deg(r, s.rake_angle_deg);
    // Propagated from h_c's interval: dr = -h / h_c^2 dh_c, and from tan(phi) = r cos(a) / (1 - r sin(a)),
    // dphi/dr = cos(a) / (1 - 2 r sin(a) + r^2).
    const double r_ci = ci.depth_of_cut / (hc * hc) * hc_ci;
    out.chip["compression_ratio_ci95"] = finite_or_null(r_ci);
    out.chip["shear_angle_ci95_deg"] = finite_or_null(std::cos(a) / (1 - 2 * r * std::sin(a) + r * r) * r_ci / kDeg);
  } else {
    out.chip["note"] = fmt::format(
        "chip thickness not measured: {} steady rows measured it (at least {} needed; "
        "a row needs 10 chip particles 2 to 3 depths of cut up the rake face and the chip's head half a depth "
        "of cut past them: a cut too short for the chip to pass there measures none)",
        steady_hc.size(), kMinThicknessRows);
  }
  free_side_figures(s, d, out);
  if (s.free_sides && std::isfinite(s.side_y_lo))
    out.chip["side_burr_m"] = side_burr(d.position, ci, s.inclination_deg, s.side_y_lo, s.side_y_hi);
  return out;
}

std::string cut_table(const nlohmann::json& cutting, const nlohmann::json& chip, double broken) {
  // (nan when the summary lacks it, printed through nan_safe: a NaN with a precision would trap)
  const auto num = json_number;
  const std::size_t rows = cutting.value("steady_samples", std::size_t(0));
  // The 95 % interval after a value: its half-width, or why there is none (null in summary.json).
  auto ci = [&](const nlohmann::json& j, const char* key, double scale, const char* unit, const char* of,
                std::size_t samples) -> std::string {
    if (!j.contains(key)) return "";
    if (!j[key].is_number())
      return samples < kSteadyMinSamples
                 ? fmt::format(" (95 % CI{}: unavailable, {} steady rows, {} needed)", of, samples, kSteadyMinSamples)
                 : fmt::format(" (95 % CI{}: unavailable)", of);
    return fmt::format(" (95 % CI{} +- {:.3g}{})", of, nan_safe(j[key].get<double>() * scale), unit);
  };
  // A steady force: its mean, its deviation (when there are two rows) and its interval; none
  // without steady rows (null in summary.json), said so instead of a force of 0.
  auto force = [&](const char* what, const char* mean, const char* std_key, const char* ci_key) {
    if (!cutting.contains(mean) || !cutting[mean].is_number())
      return fmt::format("  {}    {:>10} (no steady rows: see the note below)\n", what, "none");
    const double sd = num(cutting, std_key);
    return fmt::format("  {}    {:>10.4g}{} kN/m{}\n", what, nan_safe(num(cutting, mean) / 1e3),
                       std::isnan(sd) ? std::string() : fmt::format(" +- {:.3g}", nan_safe(sd / 1e3)),
                       ci(cutting, ci_key, 1e-3, " kN/m", " of the mean", rows));
  };
  // A figure that summary.json gives as null (no steady rows, no force direction): "none", not
  // "nan" (and not 0).
  auto figure = [](const nlohmann::json& j, const char* key, const char* spec, const char* unit) {
    if (!j.contains(key) || !j[key].is_number()) return fmt::format("{:>10}", "none");
    return fmt::format(fmt::runtime(spec), nan_safe(j[key].get<double>())) + unit;
  };
  std::string t;
  t += "\n  result (steady part of the cut)          value\n";
  t += force("cutting force per width Fc/w", "cutting_force_per_width_mean_N_per_m",
             "cutting_force_per_width_std_N_per_m", "cutting_force_per_width_ci95_N_per_m");
  t += force("thrust force per width Ft/w ", "thrust_force_per_width_mean_N_per_m",
             "thrust_force_per_width_std_N_per_m", "thrust_force_per_width_ci95_N_per_m");
  if (cutting.contains("specific_cutting_force_N_per_mm2") && cutting["specific_cutting_force_N_per_mm2"].is_number())
    t += fmt::format("  specific cutting force kc=Fc/bh {:>10.4g} N/mm^2{}\n",
                     nan_safe(num(cutting, "specific_cutting_force_N_per_mm2")),
                     ci(cutting, "specific_cutting_force_ci95_N_per_mm2", 1.0, " N/mm^2", " of the mean", rows));
  if (cutting.contains("cutting_force_N") && cutting["cutting_force_N"].is_number())
    t += fmt::format("  Fc, Ft on the width b = {:.4g} mm {:>8.4g}, {:.4g} N\n",
                     nan_safe(num(cutting, "width_m") * 1e3), nan_safe(num(cutting, "cutting_force_N")),
                     nan_safe(num(cutting, "thrust_force_N")));
  if (cutting.contains("thrust_to_cutting_force_ratio"))
    t += fmt::format("  force ratio Ft/Fc               {}{}\n",
                     figure(cutting, "thrust_to_cutting_force_ratio", "{:>10.3g}", ""),
                     ci(cutting, "thrust_to_cutting_force_ratio_ci95", 1.0, "", "", rows));
  t += fmt::format("  depth of cut h                  {:>10.4g} mm\n", nan_safe(num(chip, "depth_of_cut_m") * 1e3));
  if (chip.contains("thickness_m")) {
    const std::size_t hc_rows = chip.value("thickness_rows", std::size_t(0));
    t += fmt::format("  chip thickness h_c              {:>10.4g} mm", nan_safe(num(chip, "thickness_m") * 1e3));
    if (chip.contains("thickness_p10_m"))
      t += fmt::format(" (median of {} rows; 10-90 %: {:.3g} to {:.3g})", hc_rows,
                       nan_safe(num(chip, "thickness_p10_m") * 1e3), nan_safe(num(chip, "thickness_p90_m") * 1e3));
    t += ci(chip, "thickness_ci95_m", 1e3, " mm", " of the median", hc_rows) + "\n";
    t += fmt::format("  compression ratio r = h/h_c     {:>10.3f}{}\n", nan_safe(num(chip, "compression_ratio")),
                     ci(chip, "compression_ratio_ci95", 1.0, "", "", hc_rows));
    t += fmt::format("  shear angle phi (from r)        {:>10.1f} deg{}\n", nan_safe(num(chip, "shear_angle_deg")),
                     ci(chip, "shear_angle_ci95_deg", 1.0, " deg", "", hc_rows));
  } else {
    t += fmt::format("  chip thickness                  not measured ({} chip particles)\n",
                     chip.value("chip_particles", 0));
  }
  if (chip.contains("curl_points")) {
    if (chip.contains("curl_radius_m") && chip["curl_radius_m"].is_number())
      t += fmt::format("  chip curl radius R_u (end)      {:>10.4g} mm (over {:.0f} deg, {} points, rms {:.2g} mm)\n",
                       nan_safe(num(chip, "curl_radius_m") * 1e3), nan_safe(num(chip, "curl_arc_deg")),
                       chip.value("curl_points", 0), nan_safe(num(chip, "curl_fit_rms_m") * 1e3));
    else
      t += fmt::format("  chip curl radius R_u (end)      not measured\n  note: {}\n", chip.value("curl_note", ""));
  }
  t += fmt::format("  friction angle beta (Fc, Ft)    {}{}\n", figure(chip, "friction_angle_deg", "{:>10.1f}", " deg"),
                   ci(chip, "friction_angle_ci95_deg", 1.0, " deg", "", rows));
  t += fmt::format("  Merchant 45 + gamma/2 - beta/2  {}{}\n",
                   figure(chip, "merchant_shear_angle_deg", "{:>10.1f}", " deg"),
                   ci(chip, "merchant_shear_angle_ci95_deg", 1.0, " deg", "", rows));
  t += fmt::format("  broken-rod fraction             {:>10.2f} %\n", nan_safe(100.0 * broken));
  if (chip.contains("packing_volume_m3"))
    t += fmt::format("  chip volume (particles x a^3/4) {:>10.4g} mm^3\n",
                     nan_safe(num(chip, "packing_volume_m3") * 1e9));
  // What the two spreads mean, and the cross-check of the batches' length.
  if (cutting.contains("steady_note")) t += "  note: " + cutting["steady_note"].get<std::string>() + "\n";
  if (cutting.contains("cutting_force_per_width_ci95_N_per_m") && rows > 0) {
    t += "  (+- after a force: its standard deviation over the steady part; 95 % CI: the confidence interval of the\n"
         "  mean";
    if (cutting.value("steady_batches", 0) > 0) {
      t += fmt::format(
          " from {} batch means of {} rows (Student t, {} dof); effective rows n/tau of {}: Fc {:.3g}, "
          "Ft {:.3g}",
          cutting.value("steady_batches", 0), cutting.value("steady_batch_samples", 0),
          cutting.value("steady_batches", 0) - 1, rows,
          nan_safe(num(cutting, "cutting_force_per_width_effective_samples")),
          nan_safe(num(cutting, "thrust_force_per_width_effective_samples")));
      if (chip.contains("thickness_effective_rows"))
        t += fmt::format(", h_c {:.3g} of {}", nan_safe(num(chip, "thickness_effective_rows")),
                         chip.value("thickness_rows", 0));
    } else {
      t += fmt::format(" from batch means, which need {} steady rows", kSteadyMinSamples);
    }
    t += ")\n";
    for (const auto* j : {&cutting, &chip})
      if (j->contains("ci95_note")) t += "  note: " + (*j)["ci95_note"].get<std::string>() + "\n";
  }
  return t;
}

namespace {

// The work material's values under /cutting/material/ (with its name as the attribute
// cutting_material; none when the material is unknown).
struct MaterialField {
  const char* name;
  const char* unit;
  const char* what;
  double CutMaterial::*top = nullptr;
  double OxleyMaterial::*field = nullptr;
  double get(const CutMaterial& m) const { return top ? m.*top : m.oxley.*field; }
  void set(CutMaterial& m, double v) const { (top ? m.*top : m.oxley.*field) = v; }
};

const std::vector<MaterialField>& material_fields() {
  static const std::vector<MaterialField> fields{
      {"material/johnson_cook_a", "Pa", "Johnson-Cook A", nullptr, &OxleyMaterial::jc_a},
      {"material/johnson_cook_b", "Pa", "Johnson-Cook B", nullptr, &OxleyMaterial::jc_b},
      {"material/johnson_cook_n", "1", "Johnson-Cook n", nullptr, &OxleyMaterial::jc_n},
      {"material/johnson_cook_c", "1", "Johnson-Cook C", nullptr, &OxleyMaterial::jc_c},
      {"material/johnson_cook_m", "1", "Johnson-Cook m", nullptr, &OxleyMaterial::jc_m},
      {"material/reference_rate", "1/s", "Johnson-Cook reference strain rate", nullptr,
       &OxleyMaterial::reference_strain_rate},
      {"material/reference_temperature", "K", "Johnson-Cook T_ref", nullptr, &OxleyMaterial::t_ref},
      {"material/melt_temperature", "K", "Johnson-Cook T_melt", nullptr, &OxleyMaterial::t_melt},
      {"material/density", "kg/m^3", "density", nullptr, &OxleyMaterial::density},
      {"material/heat_capacity", "J/(kg K)", "specific heat capacity", nullptr, &OxleyMaterial::heat_capacity},
      {"material/conductivity", "W/(m K)", "thermal conductivity", nullptr, &OxleyMaterial::conductivity},
      {"material/initial_temperature", "K", "the workpiece's temperature at the start",
       &CutMaterial::initial_temperature, nullptr},
  };
  return fields;
}

}  // namespace

// Layout 3: one named dataset per value under /cutting, each with its unit.
void write_cut_setup(H5File& f, const CutSetup& s) {
  auto put = [&f](const char* name, const double* v, std::size_t n, const char* unit, const char* what) {
    f.write(std::string("/cutting/") + name, v, n);
    f.describe(std::string("/cutting/") + name, unit, what);
  };
  const double tip[3] = {s.tool_tip[0], s.tool_tip[1], s.tool_tip[2]};
  put("width", &s.width, 1, "m", "workpiece width: the lattice's extent along y plus half a cell edge");
  put("steady_from", &s.steady_from, 1, "s", "the force statistics use the series rows from this time on");
  put("tool_tip", tip, 3, "m", "the tool's sharp tip (x, y, z) at the end of the run");
  put("rake_angle", &s.rake_angle_deg, 1, "deg", "the tool's rake angle (ISO 3002 gamma; normal rake if inclined)");
  put("inclination_angle", &s.inclination_deg, 1, "deg", "the edge's inclination lambda_s (ISO 3002): 0 orthogonal");
  const double sides = s.free_sides ? 1.0 : 0.0;
  put("free_sides", &sides, 1, "1", "1: a block of finite width with free sides; 0: plane strain (periodic)");
  const double side_y[2] = {s.side_y_lo, s.side_y_hi};
  put("side_faces_y", side_y, 2, "m", "the side faces' initial centres (lowest and highest y of the ordered lattice)");
  put("uncut_surface_z", &s.uncut_surface_z, 1, "m", "highest initial centre of the ordered workpiece lattice");
  put("radius", &s.radius, 1, "m", "particle radius R");
  const std::int64_t count = static_cast<std::int64_t>(s.lattice_particles);
  f.write("/cutting/workpiece_particles", &count, 1);
  f.describe("/cutting/workpiece_particles", "1", "the workpiece is particles 0 to this - 1");
  put("face_length", &s.face_length, 1, "m", "the tool's rake face length from the tip");
  f.write_attribute("cutting_tool_mesh", s.tool_mesh);
  put("cutting_speed", &s.cutting_speed, 1, "m/s", "the tool's constant speed along x (0: its path has none)");
  f.write_attribute("cutting_material", s.material.known ? s.material.name : std::string());
  if (!s.material.known) f.write_attribute("cutting_material_note", s.material.note);
  if (s.material.known)
    for (const auto& m : material_fields()) {
      const double v = m.get(s.material);
      put(m.name, &v, 1, m.unit, m.what);
    }
  if (s.compliant()) {
    const double m[4] = {s.mount.stiffness_x, s.mount.stiffness_z, s.mount.mass, s.mount.damping};
    put("tool_mount", m, 4, "N/m/m, N/m/m, kg/m, N s/m/m",
        "a compliant tool's mount per metre of width: stiffness along x and z, mass, damping");
  }
}

bool read_cut_setup(const H5File& f, CutSetup& s) {
  if (results_format(f) >= 3) {
    if (!f.has("/cutting/width")) return false;
    auto one = [&f](const char* name, std::size_t want) {
      std::size_t r = 0, c = 0;
      auto v = f.read_doubles(std::string("/cutting/") + name, r, c);
      if (v.size() != want)
        throw InputError(fmt::format("'{}': /cutting/{} has {} values, not {}", f.path(), name, v.size(), want));
      return v;
    };
    s.width = one("width", 1)[0];
    s.steady_from = one("steady_from", 1)[0];
    const auto tip = one("tool_tip", 3);
    s.tool_tip = Vec3(tip[0], tip[1], tip[2]);
    s.rake_angle_deg = one("rake_angle", 1)[0];
    s.uncut_surface_z = one("uncut_surface_z", 1)[0];
    s.radius = one("radius", 1)[0];
    std::size_t r = 0, c = 0;
    const auto n = f.read_ints("/cutting/workpiece_particles", r, c);
    if (n.size() != 1 || n[0] < 0)
      throw InputError(fmt::format("'{}': /cutting/workpiece_particles must be one count >= 0", f.path()));
    s.lattice_particles = static_cast<std::size_t>(n[0]);
    s.face_length = one("face_length", 1)[0];
    s.tool_mesh = f.has_attribute("cutting_tool_mesh") ? f.read_string_attribute("cutting_tool_mesh") : "";
    // Runs before 2026-12-06 stored neither the speed nor the material: Oxley's reference is then unknown.
    if (f.has("/cutting/cutting_speed")) s.cutting_speed = one("cutting_speed", 1)[0];
    if (f.has("/cutting/inclination_angle")) s.inclination_deg = one("inclination_angle", 1)[0];
    if (f.has("/cutting/free_sides")) s.free_sides = one("free_sides", 1)[0] != 0.0;
    if (f.has("/cutting/side_faces_y")) {
      const auto y = one("side_faces_y", 2);
      s.side_y_lo = y[0], s.side_y_hi = y[1];
    } else {
      s.side_y_lo = s.side_y_hi = NAN;  // not recorded: no side burr
    }
    const std::string material = f.has_attribute("cutting_material") ? f.read_string_attribute("cutting_material") : "";
    s.material = CutMaterial{};
    if (!material.empty()) {
      s.material.known = true;
      s.material.name = material;
      for (const auto& m : material_fields()) m.set(s.material, one(m.name, 1)[0]);
    } else {
      s.material.note = f.has_attribute("cutting_material_note")
                            ? f.read_string_attribute("cutting_material_note")
                            : "the run's results.h5 does not record the work material (a run before 2026-12-06)";
    }
    if (f.has("/cutting/tool_mount")) {
      const auto m = one("tool_mount", 4);
      s.mount = ToolMount{m[0], m[1], m[2], m[3]};
      if (!(s.mount.stiffness_x > 0 && s.mount.stiffness_z > 0 && s.mount.mass > 0 && s.mount.damping >= 0))
        throw InputError(
            fmt::format("'{}': /cutting/tool_mount [{}, {}, {}, {}] is not a mount (stiffnesses and mass "
                        "> 0, damping >= 0)",
                        f.path(), m[0], m[1], m[2], m[3]));
    }
    return true;
  }
  if (!f.has("/cutting/setup")) return false;
  std::size_t r = 0, c = 0;
  const auto v = f.read_doubles("/cutting/setup", r, c);
  const int format = results_format(f);  // (1: runs before the face length was stored, 9 values)
  if (v.size() != (format >= 2 ? 10u : 9u))
    throw InputError(fmt::format("'{}': /cutting/setup has {} values; layout {} has {}", f.path(), v.size(), format,
                                 format >= 2 ? 10 : 9));
  s.width = v[0];
  s.steady_from = v[1];
  s.tool_tip = Vec3(v[2], v[3], v[4]);
  s.rake_angle_deg = v[5];
  s.uncut_surface_z = v[6];
  s.radius = v[7];
  s.lattice_particles = static_cast<std::size_t>(v[8]);
  s.face_length = format >= 2 ? v[9] : HUGE_VAL;
  s.tool_mesh = f.has_attribute("cutting_tool_mesh") ? f.read_string_attribute("cutting_tool_mesh") : "";
  return true;
}

}  // namespace swarf

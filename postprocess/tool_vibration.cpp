// tool_vibration.cpp: a compliant tool's deflection and spectra (see tool_vibration.h).
#include "postprocess/tool_vibration.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "postprocess/steady_stats.h"

namespace swarf {
namespace {

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// The rows [from, end) of x.
std::vector<double> rows_from(const std::vector<double>& x, std::size_t from) {
  return {x.begin() + static_cast<std::ptrdiff_t>(std::min(from, x.size())), x.end()};
}

}  // namespace

std::vector<double> amplitude_spectrum(const std::vector<double>& t, const std::vector<double>& x,
                                       const std::vector<double>& f) {
  const std::size_t n = std::min(t.size(), x.size());
  std::vector<double> out(f.size(), 0.0);
  if (n < 3) return out;
  const double t0 = t[0], span = t[n - 1] - t[0];
  // Each row's share of the time (trapezoid weights) and the Hann window over the record.
  std::vector<double> w(n);
  double sum_w = 0, mean = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dt = 0.5 * ((i + 1 < n ? t[i + 1] : t[i]) - (i > 0 ? t[i - 1] : t[i]));
    const double hann = 0.5 - 0.5 * std::cos(2.0 * M_PI * (t[i] - t0) / span);
    w[i] = dt * hann;
    sum_w += w[i];
  }
  double sum_dt = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dt = 0.5 * ((i + 1 < n ? t[i + 1] : t[i]) - (i > 0 ? t[i - 1] : t[i]));
    mean += dt * x[i];
    sum_dt += dt;
  }
  mean /= sum_dt;
  for (std::size_t k = 0; k < f.size(); ++k) {
    double re = 0, im = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double phase = 2.0 * M_PI * f[k] * (t[i] - t0);
      re += w[i] * (x[i] - mean) * std::cos(phase);
      im -= w[i] * (x[i] - mean) * std::sin(phase);
    }
    out[k] = 2.0 * std::hypot(re, im) / sum_w;
  }
  return out;
}

ToolVibration analyze_tool(const ToolMount& mount, const ToolSeries& s, double steady_from) {
  ToolVibration out;
  nlohmann::json& j = out.summary;
  const double fn_x = std::sqrt(mount.stiffness_x / mount.mass) / (2.0 * M_PI);
  const double fn_z = std::sqrt(mount.stiffness_z / mount.mass) / (2.0 * M_PI);
  const double zeta_x = mount.damping / (2.0 * std::sqrt(mount.stiffness_x * mount.mass));
  const double zeta_z = mount.damping / (2.0 * std::sqrt(mount.stiffness_z * mount.mass));
  j = {{"stiffness_x_N_per_m_per_m", mount.stiffness_x},
       {"stiffness_z_N_per_m_per_m", mount.stiffness_z},
       {"mass_kg_per_m", mount.mass},
       {"damping_ratio_x", finite_or_null(zeta_x)},
       {"damping_ratio_z", finite_or_null(zeta_z)},
       {"natural_frequency_x_Hz", finite_or_null(fn_x)},
       {"natural_frequency_z_Hz", finite_or_null(fn_z)}};

  // The steady part: the deflection's mean against the static closed form F / k.
  const std::size_t n = s.time.size();
  std::size_t first = 0;
  while (first < n && s.time[first] < steady_from) ++first;
  const SteadyStats dx = steady_stats(rows_from(s.deflection_x, first));
  const SteadyStats dz = steady_stats(rows_from(s.deflection_z, first));
  const SteadyStats fc = steady_stats(rows_from(s.fc, first));
  const SteadyStats ft = steady_stats(rows_from(s.ft, first));
  // The particles push the tool back (-x) by Fc and up (+z) by Ft.
  j["deflection_x_mean_m"] = finite_or_null(dx.mean);
  j["deflection_x_ci95_m"] = finite_or_null(dx.ci95);
  j["deflection_x_std_m"] = finite_or_null(dx.std);
  j["static_deflection_x_m"] = finite_or_null(-fc.mean / mount.stiffness_x);
  j["static_deflection_x_ci95_m"] = finite_or_null(fc.ci95 / mount.stiffness_x);
  j["deflection_z_mean_m"] = finite_or_null(dz.mean);
  j["deflection_z_ci95_m"] = finite_or_null(dz.ci95);
  j["deflection_z_std_m"] = finite_or_null(dz.std);
  j["static_deflection_z_m"] = finite_or_null(ft.mean / mount.stiffness_z);
  j["static_deflection_z_ci95_m"] = finite_or_null(ft.ci95 / mount.stiffness_z);
  j["static_note"] =
      "static_deflection = the steady mean force per width over the stiffness per width (-Fc/k along x, Ft/k along "
      "z), with the force mean's 95 % interval; deflection_*_mean is the measured one over the same rows";

  // The spectra over the engaged part: from the first row with a force on the tool.
  std::size_t engaged = 0;
  while (engaged < n && s.fc[engaged] == 0.0 && s.ft[engaged] == 0.0) ++engaged;
  std::vector<double> t = rows_from(s.time, engaged);
  if (t.size() < 8) {
    j["spectrum_note"] = "fewer than 8 engaged rows: no spectrum";
    return out;
  }
  const double T = t.back() - t.front();
  const double nyquist = 0.5 * double(t.size() - 1) / T;
  const double df = 0.25 / T;
  ToolSpectra& sp = out.spectra;
  for (double f = 0; f <= nyquist; f += df) sp.frequency.push_back(f);
  sp.deflection_x = amplitude_spectrum(t, rows_from(s.deflection_x, engaged), sp.frequency);
  sp.deflection_z = amplitude_spectrum(t, rows_from(s.deflection_z, engaged), sp.frequency);
  sp.fc = amplitude_spectrum(t, rows_from(s.fc, engaged), sp.frequency);
  sp.ft = amplitude_spectrum(t, rows_from(s.ft, engaged), sp.frequency);
  // The peak where the mount's mode shows: between half and twice its natural frequency (and
  // above the window's main lobe around 0 Hz, 2/T wide). Below lie the entry's slow build-up of
  // the deflection and the chip's segmentation, whose amplitudes outweigh the mode's in one run.
  auto peak = [&](const std::vector<double>& a, double fn) {
    std::size_t best = a.size();
    for (std::size_t k = 0; k < a.size(); ++k) {
      const double f = sp.frequency[k];
      if (f > 2.0 / T && f >= 0.5 * fn && f <= 2.0 * fn && (best == a.size() || a[k] > a[best])) best = k;
    }
    return best == a.size() ? NAN : sp.frequency[best];
  };
  j["spectrum_from_s"] = t.front();
  j["spectrum_resolution_Hz"] = 1.0 / T;
  j["spectrum_nyquist_Hz"] = nyquist;
  j["deflection_x_peak_frequency_Hz"] = finite_or_null(peak(sp.deflection_x, fn_x));
  j["deflection_z_peak_frequency_Hz"] = finite_or_null(peak(sp.deflection_z, fn_z));
  j["spectrum_file"] = "tool_spectrum.csv";
  return out;
}

std::string tool_spectrum_csv(const ToolSpectra& sp) {
  std::string
      s = "frequency_Hz,deflection_x_m,deflection_z_m,cutting_force_per_width_N_per_m,thrust_force_per_width_N_per_m\n";
  for (std::size_t k = 0; k < sp.frequency.size(); ++k)
    s += fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", sp.frequency[k], sp.deflection_x[k], sp.deflection_z[k],
                     sp.fc[k], sp.ft[k]);
  return s;
}

}  // namespace swarf

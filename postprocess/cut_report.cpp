// cut_report.cpp: the end-of-cut analysis and table (see cut_report.h).
#include "postprocess/cut_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/h5file.h"
#include "io/results_format.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

constexpr std::size_t kMinThicknessRows = 5;

}  // namespace

ChipInput chip_input(const CutSetup& setup, std::vector<Vec3> position, const Vec3& tool_tip) {
  ChipInput ci;
  ci.position = std::move(position);
  ci.radius = setup.radius;
  ci.uncut_surface_z = setup.uncut_surface_z;
  ci.tool_tip = tool_tip;
  ci.rake_angle_deg = setup.rake_angle_deg;
  ci.depth_of_cut = setup.uncut_surface_z - tool_tip[2];
  ci.face_length = setup.face_length;
  return ci;
}

CutResult analyze_cut(const CutSetup& s, const CutData& d) {
  CutResult out;
  // Mean and sample standard deviation of the forces per width over the steady part.
  auto stats = [&](const std::vector<double>& v) {
    double n = 0, sum = 0;
    for (std::size_t k = 0; k < v.size(); ++k)
      if (d.time[k] >= s.steady_from) {
        n += 1;
        sum += v[k];
      }
    const double mean = n > 0 ? sum / n : 0.0;
    double var = 0;
    for (std::size_t k = 0; k < v.size(); ++k)
      if (d.time[k] >= s.steady_from) var += (v[k] - mean) * (v[k] - mean);
    var = n > 1 ? var / (n - 1) : 0.0;
    return std::make_pair(mean, std::sqrt(var));
  };
  std::size_t samples = 0;
  for (double t : d.time) samples += t >= s.steady_from ? 1 : 0;
  const auto [fc, fc_sd] = stats(d.fc);
  const auto [ft, ft_sd] = stats(d.ft);
  out.cutting = {{"tool_mesh", s.tool_mesh},
                 {"width_m", s.width},
                 {"steady_from_s", s.steady_from},
                 {"steady_samples", samples},
                 {"cutting_force_per_width_mean_N_per_m", fc},
                 {"cutting_force_per_width_std_N_per_m", fc_sd},
                 {"thrust_force_per_width_mean_N_per_m", ft},
                 {"thrust_force_per_width_std_N_per_m", ft_sd},
                 {"broken_fraction", d.broken_rod_fraction}};

  const ChipInput ci = chip_input(s, d.position, s.tool_tip);
  out.metrics = measure_chip(ci);
  const ChipMetrics& cm = out.metrics;
  // h_c over the steady part: the median of the rows' measurements.
  std::vector<double> steady_hc;
  for (std::size_t k = 0; k < d.chip_thickness.size() && k < d.time.size(); ++k)
    if (d.time[k] >= s.steady_from && d.chip_thickness[k] > 0) steady_hc.push_back(d.chip_thickness[k]);
  const double beta = friction_angle_deg(fc, ft, s.rake_angle_deg);
  double chip_broken = 0.0;
  for (auto i : cm.members) chip_broken += i < d.broken_fraction.size() ? d.broken_fraction[i] : 0.0;
  std::size_t damaged = 0;
  for (double b : d.broken_fraction) damaged += b > 0 ? 1 : 0;
  out.chip = {{"depth_of_cut_m", ci.depth_of_cut},
              {"rake_angle_deg", s.rake_angle_deg},
              {"chip_particles", cm.chip_particles},
              {"measured_particles", cm.measured_particles},
              {"friction_angle_deg", beta},
              {"merchant_shear_angle_deg", merchant_shear_angle_deg(s.rake_angle_deg, beta)},
              {"chip_broken_fraction_mean", cm.members.empty() ? 0.0 : chip_broken / double(cm.members.size())},
              {"damaged_particle_fraction",
               d.broken_fraction.empty() ? 0.0 : double(damaged) / double(d.broken_fraction.size())}};
  if (cm.thickness > 0) out.chip["thickness_final_m"] = cm.thickness;
  double hc = 0.0;
  if (steady_hc.size() >= kMinThicknessRows) {
    hc = quantile(steady_hc, 0.5);
    out.chip["thickness_p10_m"] = quantile(steady_hc, 0.1);
    out.chip["thickness_p90_m"] = quantile(steady_hc, 0.9);
    out.chip["thickness_rows"] = steady_hc.size();
  } else if (d.chip_thickness.empty() && cm.thickness > 0) {
    hc = cm.thickness;  // a run of an earlier version: no per-row thickness, the last state's
    out.chip["thickness_note"] = "series.csv has no chip_thickness column: h_c is the last state's";
  }
  if (hc > 0) {
    out.chip["thickness_m"] = hc;
    out.chip["compression_ratio"] = ci.depth_of_cut / hc;
    out.chip["shear_angle_deg"] = shear_angle_deg(ci.depth_of_cut / hc, s.rake_angle_deg);
  } else {
    out.chip["note"] = fmt::format(
        "chip thickness not measured: {} steady rows measured it (at least {} needed; "
        "a row needs 10 chip particles beyond the edge region)",
        steady_hc.size(), kMinThicknessRows);
  }
  return out;
}

std::string cut_table(const nlohmann::json& cutting, const nlohmann::json& chip, double broken) {
  auto num = [](const nlohmann::json& j, const char* k) { return j.contains(k) ? j[k].get<double>() : NAN; };
  std::string t;
  t += "\n  result (steady part of the cut)          value\n";
  t += fmt::format("  cutting force per width Fc/w    {:>10.4g} +- {:.3g} kN/m\n",
                   num(cutting, "cutting_force_per_width_mean_N_per_m") / 1e3,
                   num(cutting, "cutting_force_per_width_std_N_per_m") / 1e3);
  t += fmt::format("  thrust force per width Ft/w     {:>10.4g} +- {:.3g} kN/m\n",
                   num(cutting, "thrust_force_per_width_mean_N_per_m") / 1e3,
                   num(cutting, "thrust_force_per_width_std_N_per_m") / 1e3);
  t += fmt::format("  depth of cut h                  {:>10.4g} mm\n", num(chip, "depth_of_cut_m") * 1e3);
  if (chip.contains("thickness_m")) {
    t += fmt::format("  chip thickness h_c              {:>10.4g} mm", num(chip, "thickness_m") * 1e3);
    if (chip.contains("thickness_p10_m"))
      t += fmt::format(" (median of {} rows; 10-90 %: {:.3g} to {:.3g})", chip.value("thickness_rows", 0),
                       num(chip, "thickness_p10_m") * 1e3, num(chip, "thickness_p90_m") * 1e3);
    t += "\n";
    t += fmt::format("  compression ratio r = h/h_c     {:>10.3f}\n", num(chip, "compression_ratio"));
    t += fmt::format("  shear angle phi (from r)        {:>10.1f} deg\n", num(chip, "shear_angle_deg"));
  } else {
    t += fmt::format("  chip thickness                  not measured ({} chip particles)\n",
                     chip.value("chip_particles", 0));
  }
  t += fmt::format("  friction angle beta (Fc, Ft)    {:>10.1f} deg\n", num(chip, "friction_angle_deg"));
  t += fmt::format("  Merchant 45 + alpha/2 - beta/2  {:>10.1f} deg\n", num(chip, "merchant_shear_angle_deg"));
  t += fmt::format("  broken-rod fraction             {:>10.2f} %\n", 100.0 * broken);
  if (chip.contains("packing_volume_m3"))
    t += fmt::format("  chip volume (particles x a^3/4) {:>10.4g} mm^3\n", num(chip, "packing_volume_m3") * 1e9);
  return t;
}

void write_cut_setup(H5File& f, const CutSetup& s) {
  const std::vector<double> v{s.width,           s.steady_from, s.tool_tip[0],
                              s.tool_tip[1],     s.tool_tip[2], s.rake_angle_deg,
                              s.uncut_surface_z, s.radius,      double(s.lattice_particles),
                              s.face_length};
  f.write("/cutting/setup", v.data(), v.size());
  f.write_attribute("cutting_tool_mesh", s.tool_mesh);
}

bool read_cut_setup(const H5File& f, CutSetup& s) {
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

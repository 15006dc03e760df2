// cut_oxley.cpp: Oxley's theory beside a cut's result (see cut_oxley.h).
#include "postprocess/cut_oxley.h"

#include <fmt/format.h>

#include <cmath>
#include <exception>
#include <numbers>

#include "postprocess/json_number.h"

namespace swarf {

nlohmann::json oxley_beside(const CutMaterial& material, const CutConditions& cut) {
  nlohmann::json j;
  j["material"] = material.name;
  j["speed_m_per_s"] = cut.speed;
  j["depth_of_cut_m"] = cut.depth_of_cut;
  j["rake_angle_deg"] = cut.rake_angle_deg;
  j["width_m"] = cut.width;
  j["initial_temperature_K"] = material.initial_temperature;
  j["solved"] = false;
  if (!material.known) {
    j["reason"] = material.note;
    return j;
  }
  if (!(cut.speed > 0)) {
    j["reason"] = "the tool's path has no constant cutting speed (motion other than \"velocity\" or \"ramp\" along x)";
    return j;
  }
  if (!(cut.depth_of_cut > 0) || !(cut.width > 0)) {
    j["reason"] = fmt::format("no depth of cut ({} m) or width ({} m) to take", cut.depth_of_cut, cut.width);
    return j;
  }
  OxleyResult r;
  try {
    r = oxley(OxleyCut{.speed = cut.speed,
                       .uncut_thickness = cut.depth_of_cut,
                       .width = cut.width,
                       .rake = cut.rake_angle_deg * std::numbers::pi / 180.0,
                       .initial_temperature = material.initial_temperature},
              material.oxley);
  } catch (const std::exception& e) {  // a material Oxley's model refuses (e.g. a constant it needs positive)
    j["reason"] = e.what();
    return j;
  }
  if (!r.solved) {
    j["reason"] = r.reason;
    return j;
  }
  j["solved"] = true;
  j["cutting_force_per_width_N_per_m"] = r.cutting_force_per_width;
  j["thrust_force_per_width_N_per_m"] = r.thrust_force / cut.width;
  j["thrust_to_cutting_force_ratio"] = r.thrust_force / r.cutting_force;
  j["shear_angle_deg"] = r.shear_angle * 180.0 / std::numbers::pi;
  j["chip_thickness_m"] = r.chip_thickness;
  j["compression_ratio"] = r.chip_ratio;
  j["contact_length_m"] = r.contact_length;
  j["primary_zone_temperature_K"] = r.primary_temperature;
  j["rake_face_temperature_K"] = r.rake_temperature;
  return j;
}

std::string oxley_table(const nlohmann::json& ox, const nlohmann::json& cutting, const nlohmann::json& chip) {
  if (ox.is_null() || !ox.contains("solved")) return "";
  if (!ox["solved"].get<bool>())
    return fmt::format("  Oxley's theory at this cut: no figures ({})\n", ox.value("reason", std::string("?")));
  std::string t = fmt::format(
      "\n  Oxley's theory at this cut ({}, {:.4g} m/s, h {:.4g} mm, rake {:.3g} deg, T0 {:.0f} K; "
      "postprocess/oxley.h)\n"
      "  figure                                    swarf       Oxley  swarf/Oxley\n",
      ox.value("material", std::string()), json_number(ox, "speed_m_per_s"), 1e3 * json_number(ox, "depth_of_cut_m"),
      json_number(ox, "rake_angle_deg"), json_number(ox, "initial_temperature_K"));
  // One row: swarf's value and Oxley's, scaled to the printed unit; "none" where swarf has none.
  const auto row = [&](const char* what, double mine, double theirs, double scale, const char* unit, bool ratio) {
    const std::string a = std::isfinite(mine) ? fmt::format("{:>10.4g}", scale * mine) : fmt::format("{:>10}", "none");
    const std::string q = ratio && std::isfinite(mine) && theirs != 0 ? fmt::format("{:>10.3f}", mine / theirs)
                                                                      : fmt::format("{:>10}", "-");
    std::string line = fmt::format("  {:<37} {}  {:>10.4g}  {}   {}", what, a, scale * theirs, q, unit);
    while (line.back() == ' ') line.pop_back();
    t += line + "\n";
  };
  row("cutting force per width Fc/w", json_number(cutting, "cutting_force_per_width_mean_N_per_m"),
      json_number(ox, "cutting_force_per_width_N_per_m"), 1e-3, "kN/m", true);
  row("thrust force per width Ft/w", json_number(cutting, "thrust_force_per_width_mean_N_per_m"),
      json_number(ox, "thrust_force_per_width_N_per_m"), 1e-3, "kN/m", true);
  row("force ratio Ft/Fc", json_number(cutting, "thrust_to_cutting_force_ratio"),
      json_number(ox, "thrust_to_cutting_force_ratio"), 1.0, "", true);
  row("chip thickness h_c", json_number(chip, "thickness_m"), json_number(ox, "chip_thickness_m"), 1e3, "mm", true);
  row("compression ratio r = h/h_c", json_number(chip, "compression_ratio"), json_number(ox, "compression_ratio"), 1.0,
      "", true);
  row("shear angle phi", json_number(chip, "shear_angle_deg"), json_number(ox, "shear_angle_deg"), 1.0, "deg", true);
  row("tool-chip contact length", json_number(chip, "contact_length_m"), json_number(ox, "contact_length_m"), 1e3, "mm",
      true);
  // Temperatures differ in what they average: swarf's rake-face figure is the hottest particle
  // in the layer on the face, Oxley's the mean over the interface; no ratio is printed.
  if (chip.contains("rake_face_temperature_K"))
    row("rake face T (swarf max, Oxley mean)", json_number(chip, "rake_face_temperature_K"),
        json_number(ox, "rake_face_temperature_K"), 1.0, "K", false);
  row("primary shear zone T (Oxley's T_AB)", NAN, json_number(ox, "primary_zone_temperature_K"), 1.0, "K", false);
  return t;
}

}  // namespace swarf

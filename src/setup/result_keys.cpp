// result_keys.cpp: the units of summary.json's results (see result_keys.h). Each section's
// keys are written where the section is: results by the observers (src/app/observers/),
// cutting and chip by postprocess/cut_report.cpp and app/post.cpp, uniaxial by the uniaxial
// probe, run by the step counters.
#include "setup/result_keys.h"

#include <algorithm>

namespace swarf {
namespace {

// Whether 'text' matches 'pattern', where '*' stands for any run of characters but a dot.
bool matches(std::string_view pattern, std::string_view text) {
  if (pattern.empty()) return text.empty();
  if (pattern.front() == '*') {
    for (std::size_t n = 0; n <= text.size(); ++n) {
      if (matches(pattern.substr(1), text.substr(n))) return true;
      if (n < text.size() && text[n] == '.') break;
    }
    return false;
  }
  return !text.empty() && pattern.front() == text.front() && matches(pattern.substr(1), text.substr(1));
}

// ".x", ".y", ".z" or ".0", ".1", ...: a vector's component.
bool is_component(std::string_view part) {
  return part == "x" || part == "y" || part == "z" ||
         (!part.empty() && std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; }));
}

}  // namespace

const std::vector<ResultKey>& result_keys() {
  static const std::vector<ResultKey> keys{
      // results: the energy balance, the groups' reactions, the rods
      {"results.kinetic_energy_J", "J"},
      {"results.elastic_energy_J", "J"},
      {"results.external_work_J", "J"},
      {"results.plastic_work_J", "J"},
      {"results.viscous_work_J", "J"},
      {"results.fracture_energy_J", "J"},
      {"results.potential_energy_J", "J"},
      {"results.contact_energy_J", "J"},
      {"results.contact_work_J", "J"},
      {"results.energy_error_J", "J"},
      {"results.reaction_*_N", "N"},
      {"results.broken_rods", "1"},
      {"results.broken_fraction", "1"},
      {"results.formed_rods", "1"},
      // cutting: the steady forces per width
      {"cutting.width_m", "m"},
      {"cutting.steady_from_s", "s"},
      {"cutting.steady_samples", "1"},
      {"cutting.cutting_force_per_width_mean_N_per_m", "N/m", "cutting.cutting_force_per_width_ci95_N_per_m",
       "oxley.cutting_force_per_width_N_per_m"},
      {"cutting.cutting_force_per_width_std_N_per_m", "N/m"},
      {"cutting.cutting_force_per_width_ci95_N_per_m", "N/m"},
      {"cutting.cutting_force_per_width_autocorrelation_time_s", "s"},
      {"cutting.cutting_force_per_width_effective_samples", "1"},
      {"cutting.thrust_force_per_width_mean_N_per_m", "N/m", "cutting.thrust_force_per_width_ci95_N_per_m",
       "oxley.thrust_force_per_width_N_per_m"},
      {"cutting.thrust_force_per_width_std_N_per_m", "N/m"},
      {"cutting.thrust_force_per_width_ci95_N_per_m", "N/m"},
      {"cutting.thrust_force_per_width_autocorrelation_time_s", "s"},
      {"cutting.thrust_force_per_width_effective_samples", "1"},
      {"cutting.thrust_to_cutting_force_ratio", "1", "cutting.thrust_to_cutting_force_ratio_ci95",
       "oxley.thrust_to_cutting_force_ratio"},
      {"cutting.thrust_to_cutting_force_ratio_ci95", "1"},
      {"cutting.specific_cutting_force_N_per_mm2", "N/mm^2", "cutting.specific_cutting_force_ci95_N_per_mm2"},
      {"cutting.specific_cutting_force_ci95_N_per_mm2", "N/mm^2"},
      {"cutting.cutting_force_N", "N"},
      {"cutting.thrust_force_N", "N"},
      {"cutting.passive_force_per_width_mean_N_per_m", "N/m", "cutting.passive_force_per_width_ci95_N_per_m"},
      {"cutting.passive_force_per_width_ci95_N_per_m", "N/m"},
      {"cutting.cutting_force_per_width_middle_mean_N_per_m", "N/m",
       "cutting.cutting_force_per_width_middle_ci95_N_per_m"},
      {"cutting.cutting_force_per_width_middle_ci95_N_per_m", "N/m"},
      {"cutting.thrust_force_per_width_middle_mean_N_per_m", "N/m",
       "cutting.thrust_force_per_width_middle_ci95_N_per_m"},
      {"cutting.thrust_force_per_width_middle_ci95_N_per_m", "N/m"},
      {"cutting.steady_batches", "1"},
      {"cutting.steady_batch_samples", "1"},
      {"cutting.broken_fraction", "1"},
      // chip: its geometry, angles and surface
      {"chip.depth_of_cut_m", "m"},
      {"chip.rake_angle_deg", "deg"},
      {"chip.chip_particles", "1"},
      {"chip.measured_particles", "1"},
      {"chip.friction_angle_deg", "deg", "chip.friction_angle_ci95_deg"},
      {"chip.friction_angle_ci95_deg", "deg"},
      {"chip.merchant_shear_angle_deg", "deg", "chip.merchant_shear_angle_ci95_deg"},
      {"chip.merchant_shear_angle_ci95_deg", "deg"},
      {"chip.chip_broken_fraction_mean", "1"},
      {"chip.damaged_particle_fraction", "1"},
      {"chip.thickness_m", "m", "chip.thickness_ci95_m", "oxley.chip_thickness_m"},
      {"chip.thickness_ci95_m", "m"},
      {"chip.thickness_final_m", "m"},
      {"chip.thickness_p10_m", "m"},
      {"chip.thickness_p90_m", "m"},
      {"chip.thickness_rows", "1"},
      {"chip.thickness_effective_rows", "1"},
      {"chip.compression_ratio", "1", "chip.compression_ratio_ci95", "oxley.compression_ratio"},
      {"chip.compression_ratio_ci95", "1"},
      {"chip.shear_angle_deg", "deg", "chip.shear_angle_ci95_deg", "oxley.shear_angle_deg"},
      {"chip.shear_angle_ci95_deg", "deg"},
      {"chip.surface_particles", "1"},
      {"chip.surface_volume_m3", "m^3"},
      {"chip.packing_volume_m3", "m^3"},
      {"chip.surface_voxel_m", "m"},
      {"chip.surface_dilation_m", "m"},
      {"chip.surface_triangles", "1"},
      {"chip.curl_radius_m", "m"},
      {"chip.curl_fit_rms_m", "m"},
      {"chip.curl_arc_deg", "deg"},
      {"chip.curl_points", "1"},
      {"chip.contact_length_m", "m", "chip.contact_length_ci95_m", "oxley.contact_length_m"},
      {"chip.contact_length_ci95_m", "m"},
      {"chip.chip_temperature_K", "K", "chip.chip_temperature_ci95_K"},
      {"chip.chip_temperature_ci95_K", "K"},
      {"chip.rake_face_temperature_K", "K", "chip.rake_face_temperature_ci95_K", "oxley.rake_face_temperature_K"},
      {"chip.rake_face_temperature_ci95_K", "K"},
      // a cut with free sides (an oblique cut): the chip's flow and width
      {"chip.inclination_deg", "deg"},
      {"chip.flow_angle_deg", "deg", "chip.flow_angle_ci95_deg"},
      {"chip.flow_angle_ci95_deg", "deg"},
      {"chip.flow_angle_stabler_deg", "deg"},
      {"chip.flow_rows", "1"},
      {"chip.width_m", "m", "chip.width_ci95_m"},
      {"chip.width_ci95_m", "m"},
      {"chip.width_to_cut_width", "1"},
      {"chip.side_burr_m", "m"},
      // oxley: Oxley's theory at the cut's conditions (postprocess/cut_oxley.h)
      {"oxley.speed_m_per_s", "m/s"},
      {"oxley.depth_of_cut_m", "m"},
      {"oxley.rake_angle_deg", "deg"},
      {"oxley.width_m", "m"},
      {"oxley.initial_temperature_K", "K"},
      {"oxley.cutting_force_per_width_N_per_m", "N/m"},
      {"oxley.thrust_force_per_width_N_per_m", "N/m"},
      {"oxley.thrust_to_cutting_force_ratio", "1"},
      {"oxley.shear_angle_deg", "deg"},
      {"oxley.chip_thickness_m", "m"},
      {"oxley.compression_ratio", "1"},
      {"oxley.contact_length_m", "m"},
      {"oxley.primary_zone_temperature_K", "K"},
      {"oxley.rake_face_temperature_K", "K"},
      // heat ([heat]): the ledger at the end, temperatures, the conduction's clock
      {"heat.heat_plastic_J", "J"},
      {"heat.heat_friction_J", "J"},
      {"heat.heat_stored_J", "J"},
      {"heat.heat_to_tools_J", "J"},
      {"heat.heat_outflow_J", "J"},
      {"heat.heat_to_clamps_J", "J"},
      {"heat.heat_error_J", "J"},
      {"heat.temperature_max_K", "K"},
      {"heat.conductions", "1"},
      {"heat.conduction_step_s", "s"},
      {"heat.conduction_limit_s", "s"},
      {"heat.tool_temperature_K.*", "K"},
      // uniaxial: the bar, the prediction, the measured loop
      {"uniaxial.gauge_length_m", "m"},
      {"uniaxial.cross_section_m2", "m^2"},
      {"uniaxial.predicted.youngs_modulus_Pa", "Pa"},
      {"uniaxial.predicted.yield_stress_Pa", "Pa"},
      {"uniaxial.predicted.yield_strain", "1"},
      {"uniaxial.predicted.hardening_tangent_Pa", "Pa"},
      {"uniaxial.predicted.reverse_elastic_range_Pa", "Pa"},
      {"uniaxial.quasi_static.max_midplane_mismatch", "1"},
      {"uniaxial.measured.youngs_modulus_Pa", "Pa"},
      {"uniaxial.measured.yield_stress_Pa", "Pa"},
      {"uniaxial.measured.yield_strain", "1"},
      {"uniaxial.measured.hardening_tangent_Pa", "Pa"},
      {"uniaxial.measured.turn_stress_Pa", "Pa"},
      {"uniaxial.measured.reverse_yield_stress_Pa", "Pa"},
      {"uniaxial.measured.reverse_elastic_range_Pa", "Pa"},
      {"uniaxial.deviation_percent.*", "%"},
      // run: steps and solver counts, the machine's times
      {"run.threads", "1"},
      {"run.steps", "1"},
      {"run.steps_rejected", "1"},
      {"run.iterations_per_step_mean", "1"},
      {"run.iterations_per_step_max", "1"},
      {"run.force_evaluations", "1"},
      {"run.force_evaluations_per_us", "1/us"},
      {"run.dt_last_s", "s"},
      {"run.simulated_time_s", "s"},
      {"run.end_time_s", "s"},
      {"run.wall_time_s", "s"},
      {"run.step_wall_time_s", "s"},
      {"run.ns_per_particle_step", "ns"},
      {"run.newton_solves", "1"},
      {"run.tangent_products", "1"},
      {"run.krylov_iterations", "1"},
      {"run.krylov_capped", "1"},
      {"run.steps_rejected_indefinite", "1"},
  };
  return keys;
}

const ResultKey* find_result_key(std::string_view flat_key) {
  for (const ResultKey& k : result_keys())
    if (matches(k.name, flat_key)) return &k;
  const auto dot = flat_key.rfind('.');
  if (dot != std::string_view::npos && is_component(flat_key.substr(dot + 1)))
    return find_result_key(flat_key.substr(0, dot));
  return nullptr;
}

}  // namespace swarf

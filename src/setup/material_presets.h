// material_presets.h: named workpiece materials (material.preset), with their sources.
//
// Each preset is a macroscopic description: density, Young's modulus, a Johnson-Cook flow
// curve at room temperature and a reference strain rate (A + B eps_p^n), a strain at failure,
// Johnson-Cook's rate and temperature factors (C, m, T_melt, T_ref, used by rod.law =
// "johnson_cook": laws/johnson_cook_rod_law.h) and the heat's c and k ([heat]). The sources are
// in docs/materials.md; the rod parameters follow from calibration.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace swarf {

struct MaterialPreset {
  std::string_view name;
  std::string_view description;
  double density = 0;         ///< kg/m^3
  double youngs_modulus = 0;  ///< Pa
  double jc_a = 0;            ///< Johnson-Cook A (yield stress), Pa
  double jc_b = 0;            ///< Johnson-Cook B, Pa
  double jc_n = 0;            ///< Johnson-Cook n, 1
  double failure_strain = 0;  ///< equivalent strain at failure in shear (material.failure_strain), 1
  // Rate and temperature (Johnson-Cook's second and third factors) and the heat ([heat]).
  double jc_c = 0;                   ///< Johnson-Cook C (rate sensitivity), 1
  double jc_m = 0;                   ///< Johnson-Cook m (thermal softening exponent), 1
  double reference_rate = 0;         ///< Johnson-Cook reference equivalent plastic strain rate, 1/s
  double melt_temperature = 0;       ///< Johnson-Cook T_melt, K
  double reference_temperature = 0;  ///< Johnson-Cook T_ref (room: the flow curve's), K
  double heat_capacity = 0;          ///< specific heat capacity c, J/(kg K)
  double conductivity = 0;           ///< thermal conductivity k, W/(m K)
  std::string_view source;           ///< one line: where the numbers come from
};

/// The library, in the order the docs list it.
const std::vector<MaterialPreset>& material_presets();

/// The preset of that name, or nullptr.
const MaterialPreset* find_material_preset(std::string_view name);

/// "C45, Al2024-T351, Ti6Al4V" for error messages.
std::string material_preset_names();

}  // namespace swarf

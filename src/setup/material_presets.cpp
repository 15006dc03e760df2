// material_presets.cpp: the material library (see material_presets.h; docs/materials.md).
#include "setup/material_presets.h"

namespace swarf {

const std::vector<MaterialPreset>& material_presets() {
  // The failure strains are the Johnson-Cook damage model's strain to fracture at zero
  // triaxiality (shear), D1 + D2, where the chip is formed; see docs/materials.md for why
  // shear and for what the lattice does with it.
  static const std::vector<MaterialPreset> presets{
      {.name = "C45",
       .description = "non-alloy steel 0.45 % C (AISI 1045), normalised",
       .density = 7870.0,
       .youngs_modulus = 205e9,
       .jc_a = 553.1e6,
       .jc_b = 600.8e6,
       .jc_n = 0.234,
       .failure_strain = 2.0,
       .jc_c = 0.0134,
       .jc_m = 1.0,
       .reference_rate = 1.0,
       .melt_temperature = 1733.0,
       .reference_temperature = 293.15,
       .heat_capacity = 486.0,
       .conductivity = 50.7,
       .source = "Jaspers 1999 (PhD thesis TU Eindhoven, table 5.3) flow curve, C, m, T_melt; E, rho, k, c: "
                 "Rodriguez Prieto et al., Materials 16 (2023) 3702, appendix A"},
      {.name = "Al2024-T351",
       .description = "aluminium alloy 2024-T351",
       .density = 2770.0,
       .youngs_modulus = 73.1e9,
       .jc_a = 265e6,
       .jc_b = 426e6,
       .jc_n = 0.34,
       .failure_strain = 1.5,
       .jc_c = 0.015,
       .jc_m = 1.0,
       .reference_rate = 1.0,
       .melt_temperature = 775.0,
       .reference_temperature = 293.15,
       .heat_capacity = 875.0,
       .conductivity = 121.0,
       .source = "Johnson and Cook 1983 (7th Int. Symp. Ballistics) flow curve, C, m, T_melt, c; k: ASM handbook "
                 "(2024-T3/T351, 121 W/(m K))"},
      {.name = "Ti6Al4V",
       .description = "titanium alloy Ti-6Al-4V",
       .density = 4430.0,
       .youngs_modulus = 110e9,
       .jc_a = 862e6,
       .jc_b = 331e6,
       .jc_n = 0.34,
       .failure_strain = 1.0,
       .jc_c = 0.012,
       .jc_m = 0.8,
       .reference_rate = 1.0,
       .melt_temperature = 1878.0,
       .reference_temperature = 293.15,
       .heat_capacity = 526.0,
       .conductivity = 6.7,
       .source = "Johnson 1985 set as used in SPH cutting codes (A, B, n, C, m, T_melt); E, rho, k, c: Rodriguez "
                 "Prieto "
                 "et al. 2023, appendix A"},
  };
  return presets;
}

const MaterialPreset* find_material_preset(std::string_view name) {
  for (const auto& p : material_presets())
    if (p.name == name) return &p;
  return nullptr;
}

std::string material_preset_names() {
  std::string s;
  for (const auto& p : material_presets()) s += (s.empty() ? "" : ", ") + std::string(p.name);
  return s;
}

}  // namespace swarf

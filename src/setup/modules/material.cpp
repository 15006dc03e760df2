// material.cpp: the material's module of setup (see material.h).
#include "setup/modules/material.h"

#include <fmt/format.h>

#include "setup/calibration.h"
#include "setup/case_tables.h"
#include "setup/material_presets.h"
#include "setup/model.h"

namespace swarf {

const std::vector<Key<MaterialSettings>>& material_keys() {
  using S = MaterialSettings;
  static const std::vector<Key<S>> keys{
      {.name = "density", .field = &S::density, .unit = "kg/m^3", .range = kDensity, .doc = "Material density rho."},
      {.name = "mass_basis",
       .field = &S::mass_basis,
       .choices = {"cell", "sphere"},
       .doc = "How particle mass m is computed. See below."},
      {.name = "youngs_modulus",
       .field = &S::youngs_modulus,
       .unit = "Pa",
       .no_default = true,
       .range = kModulus,
       .doc = "Macroscopic Young's modulus along a cube axis [100]. Giving it makes swarf derive the rod law from "
              "the keys of this table (below); `[rod]` may then give only `area` and `damping_ratio`."},
      {.name = "yield_stress",
       .field = &S::yield_stress,
       .unit = "Pa",
       .range = or_inf(kStress),
       .rule = "needs `youngs_modulus`",
       .doc = "Uniaxial yield stress along [100]. inf = elastic."},
      {.name = "hardening_modulus",
       .field = &S::hardening_modulus,
       .unit = "Pa",
       .range = kModulusOrZero,
       .rule = "below `youngs_modulus`; needs `youngs_modulus`",
       .doc = "Tangent modulus after yield along [100]."},
      {.name = "tensile_strength",
       .field = &S::tensile_strength,
       .unit = "Pa",
       .range = or_inf(kStress),
       .rule = "needs `youngs_modulus`",
       .doc = "Uniaxial stress along [100] at which the rods break. inf = unbreakable."},
      {.name = "poisson_ratio",
       .field = &S::poisson_ratio,
       .unit = "1",
       .no_default = true,
       .range = in(-1, 0.5, "()"),
       .rule = "needs `youngs_modulus`",
       .doc = "Only checked: a lattice of central rods has 1/3 along [100] (1/4 as an isotropic average) and "
              "cannot represent another value; any other value prints a warning and the run continues with the "
              "lattice's."},
      {.name = "preset",
       .field = &S::preset,
       .default_note = "none",
       .choices = {"C45", "Al2024-T351", "Ti6Al4V"},
       .doc = "A named material of the library ([materials.md](materials.md)): its density, Young's modulus, "
              "Johnson-Cook flow curve and failure strain, each replaced by the key of this table when given."},
      {.name = "reference",
       .field = &S::reference,
       .default_note = "none",
       .choices = {"C45", "Al2024-T351", "Ti6Al4V"},
       .rule = "not with `preset` or the other macroscopic keys (such a case is its own reference)",
       .doc = "The named material a case with hand-written rods (`[rod]`) stands for. It builds nothing: "
              "Oxley's theory beside the cut's result (summary.json `oxley`, "
              "[outputs.md](outputs.md#summaryjson-oxley)) "
              "takes its Johnson-Cook curve and factors, and its heat capacity and conductivity where `[heat]` does "
              "not give them; the density stays this table's."},
      {.name = "flow_plastic_strain",
       .field = &S::flow_plastic_strain,
       .unit = "1",
       .no_default = true,
       .default_note = "none",
       .range = in(0.0, 100.0, "[]", "a plastic strain, 0 to 100"),
       .rule = "2 to 8 increasing values, the first 0; with `flow_stress`; needs `youngs_modulus` or `preset`; not "
               "with `yield_stress`, `hardening_modulus` or `johnson_cook_*`",
       .doc = "The material's flow curve as a table: equivalent plastic strains of its points. Matched by the rods "
              "in the mode `calibration` names (see [materials.md](materials.md#calibration))."},
      {.name = "flow_stress",
       .field = &S::flow_stress,
       .unit = "Pa",
       .no_default = true,
       .default_note = "none",
       .range = kStress,
       .rule = "as many as `flow_plastic_strain`, not decreasing; each below E, and rising by at most E times its "
               "plastic strain range",
       .doc = "True (equivalent) flow stress at the points of `flow_plastic_strain`; the first is the yield stress."},
      {.name = "johnson_cook_a",
       .field = &S::johnson_cook_a,
       .unit = "Pa",
       .no_default = true,
       .default_note = "none",
       .range = kStress,
       .rule = "with `johnson_cook_b` and `johnson_cook_n`; not with a table or `yield_stress`",
       .doc = "Johnson-Cook's A: the flow curve A + B eps_p^n at the reference rate and room temperature, "
              "tabulated at eps_p = 0, 0.01, 0.03, 0.08, 0.2, 0.5, 1, 2 (the rate and temperature factors: "
              "`rod.law` = `\"johnson_cook\"` with `johnson_cook_c` and `johnson_cook_m`)."},
      {.name = "johnson_cook_b",
       .field = &S::johnson_cook_b,
       .unit = "Pa",
       .no_default = true,
       .default_note = "none",
       .range = in(0.0, 1e13, "[]", "a stress, 0 to 1e13 Pa"),
       .doc = "Johnson-Cook's B."},
      {.name = "johnson_cook_n",
       .field = &S::johnson_cook_n,
       .unit = "1",
       .no_default = true,
       .default_note = "none",
       .range = in(0, 1, "(]"),
       .doc = "Johnson-Cook's n."},
      {.name = "failure_strain",
       .field = &S::failure_strain,
       .unit = "1",
       .range = or_inf(kStrain),
       .rule = "needs a flow curve (a table, `johnson_cook_*` or `preset`)",
       .doc = "Equivalent (von Mises) strain at which the lattice fails in simple shear on a cube plane: the rods "
              "break at the strain the stretched rod of that shear reaches (the `calibration` = \"tension\" "
              "mode takes it along [100] instead). inf = never."},
      {.name = "calibration",
       .field = &S::calibration,
       .choices = {"shear", "tension"},
       .rule = "with a flow curve",
       .doc = "The mode in which the rods reproduce the flow curve: `\"shear\"`, simple shear on a cube plane "
              "(von Mises equivalent; the mode that forms a chip), or `\"tension\"`, uniaxial along [100]."},
      {.name = "johnson_cook_c",
       .field = &S::johnson_cook_c,
       .unit = "1",
       .default_note = "the preset's; 0 without one",
       .range = in(0.0, 10.0, "[]", "a judgement: measured C are below 0.1"),
       .rule = "with `rod.law` = `\"johnson_cook\"`",
       .doc = "Johnson-Cook's C: the flow curve scaled by 1 + C ln(max(rate / `reference_rate`, 1)), rate the "
              "equivalent plastic strain rate (a rod's strain rate times 2/sqrt3 with `calibration` = "
              "`\"shear\"`, times 3 with `\"tension\"`: docs/physics.md section 2)."},
      {.name = "johnson_cook_m",
       .field = &S::johnson_cook_m,
       .unit = "1",
       .default_note = "the preset's; 1 without one",
       .range = in(0, 10, "(]"),
       .rule = "with `rod.law` = `\"johnson_cook\"`",
       .doc = "Johnson-Cook's m: the flow curve scaled by max(1 - T*^m, 1e-3), T* = (T - T_ref)/(T_melt - T_ref) "
              "in [0, 1], T a rod's temperature (the mean of its ends')."},
      {.name = "reference_rate",
       .field = &S::reference_rate,
       .unit = "1/s",
       .default_note = "the preset's; 1 without one",
       .range = kStrainRate,
       .rule = "with `rod.law` = `\"johnson_cook\"`",
       .doc = "Johnson-Cook's reference equivalent plastic strain rate (that of the flow curve)."},
      {.name = "melt_temperature",
       .field = &S::melt_temperature,
       .unit = "K",
       .default_note = "the preset's; inf (no softening) without one",
       .range = or_inf(kTemperature),
       .rule = "with `rod.law` = `\"johnson_cook\"`; above `reference_temperature`",
       .doc = "Johnson-Cook's T_melt."},
      {.name = "reference_temperature",
       .field = &S::reference_temperature,
       .unit = "K",
       .default_note = "the preset's; 293.15 without one",
       .range = kTemperature,
       .rule = "with `rod.law` = `\"johnson_cook\"`",
       .doc = "Johnson-Cook's T_ref, the temperature of the flow curve."},
  };
  return keys;
}

void read_material(const CaseInput& in, CaseSettings& cs) {
  TableReader r = in.reader(in.table("material"), "material");
  auto& mt = cs.material;
  r.read(material_keys(), mt);
  r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
  const MaterialPreset* preset = mt.preset.empty() ? nullptr : find_material_preset(mt.preset);
  mt.macroscopic = r.has("youngs_modulus") || preset;
  if (!mt.macroscopic)
    for (const char* key :
         {"yield_stress", "hardening_modulus", "tensile_strength", "poisson_ratio", "flow_plastic_strain",
          "flow_stress", "johnson_cook_a", "johnson_cook_b", "johnson_cook_n", "failure_strain", "calibration",
          "johnson_cook_c", "johnson_cook_m", "reference_rate", "melt_temperature", "reference_temperature"})
      if (r.has(key))
        r.fail(key, r.get(key), "macroscopic properties need material.youngs_modulus (Pa) or material.preset too");
  if (r.has("reference") && mt.macroscopic)
    r.fail("reference", r.get("reference"),
           preset ? "the preset is the case's reference material: give one of material.preset and material.reference"
                  : "a case whose rods come from [material]'s properties is its own reference: drop "
                    "material.reference");
  const bool table = r.has("flow_plastic_strain") || r.has("flow_stress");
  const bool jc = r.has("johnson_cook_a") || r.has("johnson_cook_b") || r.has("johnson_cook_n");
  if (table && jc)
    r.fail("johnson_cook_a", r.get("johnson_cook_a"), "give the flow curve as a table or as Johnson-Cook, not both");
  for (const char* key : {"yield_stress", "hardening_modulus"})
    if (r.has(key) && (table || jc))
      r.fail(key, r.get(key), "the flow curve (a table or Johnson-Cook) gives the yield and the hardening");
  if (jc)
    for (const char* key : {"johnson_cook_a", "johnson_cook_b", "johnson_cook_n"})
      if (!r.has(key)) r.fail(key, nullptr, "a Johnson-Cook flow curve needs johnson_cook_a (Pa), _b (Pa) and _n (1)");
  if (table)
    check_flow_curve(r, "flow_plastic_strain", "flow_stress", mt.flow_plastic_strain, mt.flow_stress,
                     !r.has("youngs_modulus") && preset ? preset->youngs_modulus : mt.youngs_modulus,
                     !r.has("youngs_modulus") && preset ? "the preset's E" : "material.youngs_modulus");
  if (preset) {
    // The preset fills what the table does not give.
    if (!r.has("density")) mt.density = preset->density;
    if (!r.has("youngs_modulus")) mt.youngs_modulus = preset->youngs_modulus;
    if (!r.has("failure_strain")) mt.failure_strain = preset->failure_strain;
    if (!table && !jc && !r.has("yield_stress")) {
      mt.johnson_cook_a = preset->jc_a;
      mt.johnson_cook_b = preset->jc_b;
      mt.johnson_cook_n = preset->jc_n;
    }
    // Johnson-Cook's rate and temperature factors (used by rod.law = "johnson_cook").
    if (!r.has("johnson_cook_c")) mt.johnson_cook_c = preset->jc_c;
    if (!r.has("johnson_cook_m")) mt.johnson_cook_m = preset->jc_m;
    if (!r.has("reference_rate")) mt.reference_rate = preset->reference_rate;
    if (!r.has("melt_temperature")) mt.melt_temperature = preset->melt_temperature;
    if (!r.has("reference_temperature")) mt.reference_temperature = preset->reference_temperature;
  }
  mt.johnson_cook_keys_given.clear();
  for (const char* key :
       {"johnson_cook_c", "johnson_cook_m", "reference_rate", "melt_temperature", "reference_temperature"})
    if (r.has(key)) mt.johnson_cook_keys_given.push_back(key);
  if (!(mt.melt_temperature > mt.reference_temperature))
    r.fail(r.has("melt_temperature") ? "melt_temperature" : "reference_temperature",
           r.get(r.has("melt_temperature") ? "melt_temperature" : "reference_temperature"),
           fmt::format("T_melt = {} K must lie above T_ref = {} K", mt.melt_temperature, mt.reference_temperature));
  if (mt.johnson_cook_a > 0) {
    mt.flow_plastic_strain = johnson_cook_points();
    mt.flow_stress = johnson_cook_stress(mt.johnson_cook_a, mt.johnson_cook_b, mt.johnson_cook_n,
                                         mt.flow_plastic_strain);
  }
  mt.flow_curve = !mt.flow_plastic_strain.empty();
  for (const char* key : {"failure_strain", "calibration"})
    if (r.has(key) && !mt.flow_curve)
      r.fail(key, r.get(key), "needs a flow curve: material.flow_plastic_strain/flow_stress, johnson_cook_* or preset");
  if (mt.macroscopic && !(mt.hardening_modulus < mt.youngs_modulus))
    r.fail("hardening_modulus", r.get("hardening_modulus"),
           fmt::format("must be below material.youngs_modulus = {} Pa", mt.youngs_modulus));
}

std::string material_echo(const Model& m) {
  const Derived& d = m.derived;
  const MaterialSettings& mt = m.settings.material;
  std::string out;
  if (d.converted && mt.flow_curve) {
    std::string pts;
    for (std::size_t i = 0; i < mt.flow_plastic_strain.size(); ++i)
      pts += fmt::format("{}({:.4g}, {:.4g} MPa)", i ? " " : "", mt.flow_plastic_strain[i], mt.flow_stress[i] * 1e-6);
    out += fmt::format("  material{}: E = {:.4g} Pa, flow curve (equivalent plastic strain, true stress): {}\n",
                       mt.preset.empty() ? std::string() : " " + mt.preset, mt.youngs_modulus, pts);
    out += fmt::format("  rod law calibrated in {} ({}), failure at equivalent strain {:.4g}:\n",
                       mt.calibration == "shear" ? "simple shear on a cube plane" : "uniaxial tension along [100]",
                       "calibration.h", mt.failure_strain);
    if (mt.calibration == "shear")
      out += fmt::format("  finite-strain shear correction: {} of {} points reached, largest mismatch left {:.1f} %\n",
                         d.calibration_points, mt.flow_plastic_strain.size() - 1, 100.0 * d.calibration_mismatch);
  } else if (d.converted) {
    out += fmt::format(
        "  rod law from [material] (along [100]: E = {:.4g} Pa, yield {:.4g} Pa, hardening {:.4g} Pa, "
        "strength {:.4g} Pa):\n",
        mt.youngs_modulus, mt.yield_stress, mt.hardening_modulus, mt.tensile_strength);
  }
  return out;
}
}  // namespace swarf

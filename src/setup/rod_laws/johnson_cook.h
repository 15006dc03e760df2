// johnson_cook.h: the Johnson-Cook rod law in setup (rod.law = "johnson_cook", formerly
// "johnson_cook_rate"; the law: swarf/laws/johnson_cook_rod_law.h): its [rod] keys, its rules,
// its build from [rod] or from the [material]'s factors, and the material lab's fixed
// conditions. Included by rod_laws.cpp only.
#pragma once

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string_view>
#include <variant>

#include "setup/case_reader.h"
#include "setup/rod_laws/rod_laws.h"

namespace swarf::johnson_cook_setup {

inline const std::vector<Key<RodSettings>>& keys() {
  using S = RodSettings;
  static const std::vector<Key<S>> keys{
      {.name = "rate_sensitivity",
       .field = &S::rate_sensitivity,
       .unit = "1",
       .range = in(0.0, 10.0, "[]", "a judgement: measured C are below 0.1"),
       .rule = "only with `law` = `\"johnson_cook\"`; not with [material] properties",
       .doc = "C of the rate factor (Johnson-Cook's C; about 0.01 to 0.03 for steels). 0: no rate term."},
      {.name = "reference_rate",
       .field = &S::reference_rate,
       .unit = "1/s",
       .range = kStrainRate,
       .rule = "only with `law` = `\"johnson_cook\"`; not with [material] properties",
       .doc = "rate_ref, a rod strain rate: at rod strain rates up to this the rate factor is 1."},
      {.name = "thermal_softening_exponent",
       .field = &S::thermal_softening_exponent,
       .unit = "1",
       .range = in(0, 10, "(]"),
       .rule = "only with `law` = `\"johnson_cook\"`; not with [material] properties",
       .doc = "m of the thermal factor Theta = max(1 - T*^m, 1e-3), T* = (T - T_ref)/(T_melt - T_ref) "
              "clamped to [0, 1]."},
      {.name = "melt_temperature",
       .field = &S::melt_temperature,
       .unit = "K",
       .range = or_inf(kTemperature),
       .rule = "only with `law` = `\"johnson_cook\"`; above `reference_temperature`; not with [material] "
               "properties",
       .doc = "T_melt, where the rod keeps 1e-3 of its flow stress. inf: no thermal softening (the rate law)."},
      {.name = "reference_temperature",
       .field = &S::reference_temperature,
       .unit = "K",
       .range = kTemperature,
       .rule = "only with `law` = `\"johnson_cook\"`; not with [material] properties",
       .doc = "T_ref, the temperature of the flow curve; a particle without a temperature (no [heat]) is at it."},
  };
  return keys;
}

// Its keys only with the law, and not beside [material] properties (whose factors are
// material.johnson_cook_c and its neighbours); the material's factors only with the law.
inline void rules(TableReader& r, const CaseSettings& cs, bool chosen) {
  const RodSettings& d = cs.rod;
  for (const auto& k : keys()) {
    const std::string_view key = k.name;
    if (r.has(key) && !chosen)
      r.fail(key, r.get(key), "belongs to the Johnson-Cook law: set rod.law = \"johnson_cook\"");
    if (r.has(key) && cs.material.macroscopic)
      r.fail(key, r.get(key),
             fmt::format("with [material] properties the law's factors are material.{} (and its neighbours)",
                         key == "rate_sensitivity"             ? "johnson_cook_c"
                         : key == "thermal_softening_exponent" ? "johnson_cook_m"
                                                               : key));
  }
  if (!chosen && !cs.material.johnson_cook_keys_given.empty())
    r.fail("law", r.get("law"),
           fmt::format("material.{} belongs to the Johnson-Cook law: set rod.law = \"johnson_cook\"",
                       cs.material.johnson_cook_keys_given.front()));
  if (chosen && !(d.melt_temperature > d.reference_temperature))
    r.fail(r.has("melt_temperature") ? "melt_temperature" : "reference_temperature",
           r.get(r.has("melt_temperature") ? "melt_temperature" : "reference_temperature"),
           fmt::format("T_melt = {} K must lie above T_ref = {} K", d.melt_temperature, d.reference_temperature));
}

inline AnyRodLaw build(const BilinearRodLaw& base, const CaseSettings& cs, const RodSettings& rod) {
  JohnsonCookRodLaw jc{.base = base,
                       .rate_sensitivity = rod.rate_sensitivity,
                       .reference_rate = rod.reference_rate,
                       .rate_to_equivalent = 1.0,
                       .softening_exponent = rod.thermal_softening_exponent,
                       .melt_temperature = rod.melt_temperature,
                       .reference_temperature = rod.reference_temperature};
  if (cs.material.macroscopic) {
    // The material's factors, its rate an equivalent plastic strain rate: a rod's rate times the
    // factor by which the calibration relates the rod's plastic strain to the equivalent one
    // (calibration.h; laws/johnson_cook_rod_law.h): 2/sqrt3 in cube-plane shear, 3 along [100]
    // (also for the bilinear [material] route, which is matched along [100]).
    const auto& mt = cs.material;
    jc.rate_sensitivity = mt.johnson_cook_c;
    jc.reference_rate = mt.reference_rate;
    jc.rate_to_equivalent = mt.flow_curve && mt.calibration == "shear" ? 2.0 / std::sqrt(3.0) : 3.0;
    jc.softening_exponent = mt.johnson_cook_m;
    jc.melt_temperature = mt.melt_temperature;
    jc.reference_temperature = mt.reference_temperature;
  }
  return jc;
}

// At a fixed temperature and rate the law is its base law with the flow stresses times
// S = R Theta (scaled_base, exact for the law's construction): the lab's crystal runs with that.
inline RodLawAtConditions at_conditions(const AnyRodLaw& any, double temperature, double strain_rate) {
  const JohnsonCookRodLaw& jc = std::get<JohnsonCookRodLaw>(any);
  const double T = temperature > 0 ? temperature : jc.reference_temperature;
  // (the rod rate whose equivalent rate is the one asked: rate_eq = kappa rate_rod)
  const double rate_f = rate_factor(jc, strain_rate / jc.rate_to_equivalent);
  const double thermal_f = thermal_factor(jc, T);
  // The closed form: every flow stress S times the law's at T_ref and rate_ref.
  return {.law = scaled_base(jc, rate_f * thermal_f),
          .record = {{"temperature_K", T},
                     {"rate_factor", rate_f},
                     {"thermal_factor", thermal_f},
                     {"flow_scale", rate_f * thermal_f}},
          .echo = fmt::format(
              "Johnson-Cook: T = {:.6g} K, equivalent plastic strain rate {:.6g} 1/s: R = {:.6g}, Theta = {:.6g}, "
              "every flow stress x S = {:.6g}\n",
              T, strain_rate, rate_f, thermal_f, rate_f * thermal_f)};
}

inline RodLawSetup setup() {
  return {.names = {"johnson_cook", "johnson_cook_rate"},
          .title = "Johnson-Cook",
          .doc =
              "`\"johnson_cook\"`: the same with all its flow stresses (yield and back stress) scaled by "
              "Johnson-Cook's S = R Theta, the rate factor R = 1 + C ln(max(rate / rate_ref, 1)) of the rod's "
              "strain rate and the thermal factor Theta = max(1 - T*^m, 1e-3) of the mean of its ends' "
              "temperatures (with [heat]); failure is not scaled (docs/physics.md section 2). "
              "`\"johnson_cook_rate\"` is the same law (its former name). With [material], C, m, the rates and "
              "temperatures are `material.johnson_cook_c` and its neighbours.",
          .holds = [](const AnyRodLaw& law) { return std::holds_alternative<JohnsonCookRodLaw>(law); },
          .keys = keys,
          .rules = rules,
          .build = build,
          .at_conditions = at_conditions};
}

}  // namespace swarf::johnson_cook_setup

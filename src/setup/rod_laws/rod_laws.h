// rod_laws.h: the rod laws setup knows, one list (a new law is its file here and one line in
// rod_laws.cpp, beside its engine file in swarf/laws/ and its line in any_rod_law.h).
//
// Each law's setup part sits in one header of this folder (bilinear.h, johnson_cook.h): the
// [rod] keys only it reads, its rules between keys, the engine law it builds from the settings
// and the derived quantities, and what the material lab does with it at fixed conditions.
// Everything else reaches a law through this list: the key table's choices for rod.law and the
// place of the law's keys in [rod] (case_keys.cpp), the rules (case_config.cpp), the build
// (derived.cpp) and the material lab (app/material_lab.cpp). Nothing outside this folder spells
// a law's name; the engine's law functions (laws/rod_law.h) do the rest.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "setup/case_config.h"
#include "setup/case_keys.h"
#include "swarf/laws/any_rod_law.h"

namespace swarf {

class TableReader;

/// A law held at fixed conditions (the material lab's --temperature, --strain-rate).
struct RodLawAtConditions {
  AnyRodLaw law;                                       ///< the law the lab's crystal runs with
  std::vector<std::pair<std::string, double>> record;  ///< material.json's entries for the conditions
  std::string echo;                                    ///< the lab's line on them (ends in a newline)
};

/// One rod law's setup part.
struct RodLawSetup {
  std::vector<std::string_view> names;  ///< rod.law's values for it: its name, then former names
  std::string_view title;               ///< in messages: "a Johnson-Cook rod law"
  std::string_view doc;                 ///< its part of rod.law's doc line (docs/case-reference.md)
  /// Whether a built law is this one.
  bool (*holds)(const AnyRodLaw& law);
  /// Its own [rod] keys (listed after rod.law, in the docs' order); empty when it has none.
  const std::vector<Key<RodSettings>>& (*keys)();
  /// Its rules on [rod] and [material] keys, read or not ('chosen': rod.law names it).
  void (*rules)(TableReader& r, const CaseSettings& cs, bool chosen);
  /// The law from the paper's law 'base' (built from [rod] or [material], viscosity filled in)
  /// and the settings ('rod': [rod] as the [material] route converted it).
  AnyRodLaw (*build)(const BilinearRodLaw& base, const CaseSettings& cs, const RodSettings& rod);
  /// The law at a temperature (K; 0 = its reference) and an equivalent plastic strain rate
  /// (1/s; 0 = quasi-static); null when the law reads neither.
  RodLawAtConditions (*at_conditions)(const AnyRodLaw& law, double temperature, double strain_rate) = nullptr;
};

/// Every law, in the order of rod.law's choices.
const std::vector<RodLawSetup>& rod_law_setups();
/// The law rod.law names (one of rod_law_names(): the key table checked it).
const RodLawSetup& rod_law_setup(std::string_view name);
/// The law a built law is.
const RodLawSetup& rod_law_setup_of(const AnyRodLaw& law);
/// rod.law's choices: each law's names in order.
std::vector<std::string_view> rod_law_names();
/// The laws with conditions, for a message: "a Johnson-Cook rod law (--set rod.law=\"johnson_cook\")".
std::string rod_laws_with_conditions();

}  // namespace swarf

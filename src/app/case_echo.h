// case_echo.h: the case as summary.json echoes it, from the settings through the key table
// (setup/case_keys.h), so that no key can be left out, named differently from the case file
// or read a second time from TOML. "case" holds the keys the case gave (the file, the
// overrides, what [cut] derived); "case_effective" every key of every table in use, the
// defaults filled in, which is what a reader needs to rerun the case when a default changes.
#pragma once

#include <nlohmann/json.hpp>

#include "setup/case_config.h"

namespace swarf {

/// summary.json "case": each table the case gave, with the keys it gave (CaseSettings::given)
/// and their values in the settings, in SI units (case_units gives them). Non-finite numbers
/// become "inf"/"-inf"/"nan".
nlohmann::json case_json(const CaseSettings& cs);

/// summary.json "case_effective": each table the case uses (and [integrator] and [output],
/// which every run uses) with all its keys from the key table, in SI units. A key whose
/// default only means "not given" (a lattice file, a mesh file) appears only if given.
nlohmann::json case_effective_json(const CaseSettings& cs);

}  // namespace swarf

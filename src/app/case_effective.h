// case_effective.h: the case as it ran, every key of every table in use with its value, the
// defaults filled in (summary.json "case_effective"). The "case" echo holds what the file and
// the overrides said; this one is what a reader needs to rerun the case when a default changes.
#pragma once

#include <nlohmann/json.hpp>

#include "setup/case_config.h"

namespace swarf {

/// Each table the case uses (and [integrator] and [output], which every run uses) with all its
/// keys from the key table (setup/case_keys.h), in SI units (case_units gives them). A key
/// whose default only means "not given" (a lattice file, a mesh file) appears only if given.
nlohmann::json case_effective_json(const CaseSettings& cs);

}  // namespace swarf

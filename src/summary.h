// summary.h: pieces of DIR/summary.json and the final-state HDF5 file DIR/results.h5.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "derived.h"
#include "simulation.h"

namespace swarf {

/// The effective case (after overrides) as JSON; non-finite numbers become "inf"/"-inf".
nlohmann::json case_to_json(const CaseSettings& cs);
/// Derived quantities with their units in the key names.
nlohmann::json derived_to_json(const Derived& d);
/// A finite number, or the string "inf"/"-inf"/"nan" (JSON has no such numbers).
nlohmann::json number(double v);

/// Writes the final state (particles, rods with plastic state) atomically.
void write_results_h5(const std::string& path, const Simulation& sim);

}  // namespace swarf

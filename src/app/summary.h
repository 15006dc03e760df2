// summary.h: pieces of DIR/summary.json and the final-state HDF5 file DIR/results.h5. The
// observers (app/observers/) write the parts they measure; these are the rest.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "setup/derived.h"
#include "swarf/simulation.h"

namespace swarf {

class H5File;
struct Model;

/// Derived quantities with their units in the key names.
nlohmann::json derived_to_json(const Derived& d);
/// A finite number, or the string "inf"/"-inf"/"nan" (JSON has no such numbers).
nlohmann::json number(double v);
/// The rod law as its describe() gives it: "<prefix>law" its name, then "<prefix><parameter>"
/// with the unit as the summary's key suffix (_Pa, _Pa_s, _per_s; none for 1), a number or,
/// for a table, an array (empty: no table).
nlohmann::json rod_law_to_json(const AnyRodLaw& law, const std::string& prefix);

/// The summary's head: version, status "completed", the final state's hash, the case (file,
/// overrides, effective settings), the derived quantities and the counts; 'restarted_from'
/// names the checkpoint of a restart (empty: none).
nlohmann::json summary_head(const Model& model, const Simulation& sim, const std::string& restarted_from);

/// The workpiece's disorder as root attributes of results.h5: 'disorder_seed' and
/// 'position_jitter' (radii; 0 when the disorder is off), both float64.
void write_disorder_attributes(H5File& f, const Derived& d);

/// Writes the final state (particles with their broken-rod fraction, rods with plastic state)
/// atomically; 'fields' are the per-particle fields chosen (output.fields; broken_fraction is
/// written always); 'extra' may add datasets (the cut's setup) before the file is closed.
void write_results_h5(const std::string& path, const Simulation& sim, const std::vector<std::string>& fields,
                      const std::function<void(H5File&)>& extra = {});

}  // namespace swarf

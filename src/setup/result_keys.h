// result_keys.h: the numbers of summary.json that a study tabulates (the sections results,
// cutting, chip, uniaxial and run), each with its unit, declared once.
//
// The key names keep their unit suffixes (_N_per_m, _deg: users and scripts rely on the
// names), but the unit is read from here, not parsed back from the name: a name whose tail
// happened to look like a unit would be given a wrong one, and a unit the suffix cannot
// spell (ns) none. A test runs short cases and checks that every number their summaries hold
// is declared here (tests/test_result_keys.cpp).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace swarf {

struct ResultKey {
  /// The flattened name: "cutting.cutting_force_per_width_mean_N_per_m"; '*' stands for any
  /// text within one part of it ("results.reaction_*_N": a group's name; "uniaxial.
  /// deviation_percent.*": each deviation).
  std::string_view name;
  std::string_view unit;       ///< SI unit; "1" for counts and ratios
  std::string_view ci95 = {};  ///< the key of its 95 % confidence half-width, when the summary gives one
  /// The key of Oxley's figure of the same quantity (summary.json "oxley", postprocess/cut_oxley.h),
  /// when his theory gives one: the report's and the plots' reference.
  std::string_view oxley = {};
};

/// Every declared result key, by section in the order of the study table.
const std::vector<ResultKey>& result_keys();

/// The declaration of a flattened key; a component of a vector (".x", ".0") takes its
/// vector's. Null when the key is not declared.
const ResultKey* find_result_key(std::string_view flat_key);

}  // namespace swarf

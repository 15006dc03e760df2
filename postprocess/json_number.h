// json_number.h: a number of a summary.json section, NaN where the key is missing or null (an
// unavailable figure), for the tables that print them through nan_safe.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>

namespace swarf {

inline double json_number(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : NAN;
}

}  // namespace swarf

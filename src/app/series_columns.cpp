// series_columns.cpp: series rows by column name (see series_columns.h).
#include "app/series_columns.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace swarf {

bool SeriesColumns::has(std::string_view name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

std::vector<double> SeriesColumns::operator[](std::string_view name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) throw std::logic_error(fmt::format("series.csv has no column '{}'", name));
  const std::size_t c = static_cast<std::size_t>(it - names_.begin()), n = names_.size();
  std::vector<double> out;
  out.reserve(rows());
  for (std::size_t r = 0; r < rows(); ++r) out.push_back(rows_[r * n + c]);
  return out;
}

}  // namespace swarf

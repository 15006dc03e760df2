// series_columns.h: the rows of series.csv read back by column name.
//
// The run keeps every row it wrote (the checkpoint carries them, so a restart rewrites the
// file whole). Whoever needs a column at the end (the chip analysis, the uniaxial loop) asks
// for it by its name: the layout of a row is the observers' business, and a column that moves
// or is added must not shift what another part reads.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace swarf {

class SeriesColumns {
 public:
  /// 'rows' is row-major with names.size() values a row; both are held by reference.
  SeriesColumns(const std::vector<std::string>& names, const std::vector<double>& rows) : names_(names), rows_(rows) {}
  bool has(std::string_view name) const;
  /// The column's values, one a row; throws std::logic_error naming a column the series lacks
  /// (a probe asked for a column no observer writes: a bug, not an input error).
  std::vector<double> operator[](std::string_view name) const;
  std::size_t rows() const { return names_.empty() ? 0 : rows_.size() / names_.size(); }

 private:
  const std::vector<std::string>& names_;
  const std::vector<double>& rows_;
};

}  // namespace swarf

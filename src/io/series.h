// series.h: DIR/series.csv, one row per output interval, written as series.csv.part while
// the run goes on and renamed at the end.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace swarf {

class SeriesWriter {
 public:
  SeriesWriter(const std::string& path, const std::vector<std::string>& columns);
  ~SeriesWriter();
  SeriesWriter(const SeriesWriter&) = delete;
  SeriesWriter& operator=(const SeriesWriter&) = delete;

  /// Appends a row; values are written with the shortest representation that reads back exactly.
  void row(const std::vector<double>& values);
  /// Flushes, closes and renames to the final name.
  void finish();

 private:
  std::string path_;
  std::FILE* f_ = nullptr;
  std::size_t columns_ = 0;
};

}  // namespace swarf

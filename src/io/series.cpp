// series.cpp: the CSV time series writer (see series.h).
#include "io/series.h"

#include <fmt/format.h>

#include <filesystem>

#include "io/atomic_file.h"
#include "swarf/core/errors.h"

namespace swarf {

SeriesWriter::SeriesWriter(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), columns_(columns.size()) {
  f_ = std::fopen((path + ".part").c_str(), "w");
  if (!f_) throw InputError("cannot write '" + path + ".part'");
  std::string header;
  for (std::size_t c = 0; c < columns.size(); ++c) header += (c ? "," : "") + columns[c];
  fmt::print(f_, "{}\n", header);
}

SeriesWriter::~SeriesWriter() {
  if (f_) std::fclose(f_);  // left as .part: the run did not finish
}

void SeriesWriter::row(const std::vector<double>& values) {
  std::string line;
  line.reserve(24 * values.size());
  for (std::size_t c = 0; c < values.size(); ++c) {
    if (c) line += ',';
    line += fmt::format("{}", values[c]);
  }
  line += '\n';
  std::fputs(line.c_str(), f_);
}

void SeriesWriter::finish() {
  if (!f_) return;
  const bool failed = std::ferror(f_) != 0;  // (a row that could not be written, even if the close succeeds)
  if (std::fclose(f_) != 0 || failed) {
    f_ = nullptr;
    throw OutputError("writing '" + path_ + ".part' failed (disk full?)");
  }
  f_ = nullptr;
  commit_file(path_ + ".part", path_);
}

}  // namespace swarf

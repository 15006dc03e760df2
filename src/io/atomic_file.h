// atomic_file.h: results are written to NAME.part and renamed when complete, so an
// interrupted run never leaves a file that looks complete.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "swarf/core/errors.h"

namespace swarf {

/// Writes 'text' to 'path' atomically (temporary file, then rename).
inline void write_text_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".part";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError("cannot write '" + tmp + "'");
    out << text;
    out.close();  // (the last buffer is written here: a full disk shows now)
    if (!out) throw OutputError("write to '" + tmp + "' failed (disk full?)");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace swarf

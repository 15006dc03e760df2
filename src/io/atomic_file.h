// atomic_file.h: results are written to NAME.part and renamed when complete, so an
// interrupted run never leaves a file that looks complete.
//
// The rename comes after an fsync of the finished file, and the directory is synced after it:
// without the first, a crash of the machine (power loss) soon after the rename can leave the
// new name on an empty or partly written file, since the file system may commit the rename
// before the data (ext4 with delalloc, xfs). After commit_file() the name holds the whole new
// file, or the old one if the crash came first.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "swarf/core/errors.h"

namespace swarf {

/// Flushes the file's data to the disk (fsync). Throws OutputError naming the file.
inline void sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw OutputError("cannot open '" + path + "' to sync it to the disk");
  const int rc = ::fsync(fd);
  ::close(fd);
  if (rc != 0) throw OutputError("fsync of '" + path + "' failed (disk full or failing?)");
}

/// Puts the finished temporary file 'tmp' in place as 'path': fsync, rename, then an fsync of
/// the directory (best effort: some file systems refuse it) so the rename itself is durable.
inline void commit_file(const std::string& tmp, const std::string& path) {
  sync_file(tmp);
  std::filesystem::rename(tmp, path);
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const int fd = ::open(parent.empty() ? "." : parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

/// Writes 'text' to 'path' atomically (temporary file, fsync, then rename).
inline void write_text_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".part";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError("cannot write '" + tmp + "'");
    out << text;
    out.close();  // (the last buffer is written here: a full disk shows now)
    if (!out) throw OutputError("write to '" + tmp + "' failed (disk full?)");
  }
  commit_file(tmp, path);
}

}  // namespace swarf

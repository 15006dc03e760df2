// path_kind.h: what a path the user gave names, asked without the exceptions of
// std::filesystem's throwing calls. is_directory(p) and exists(p) throw filesystem_error on a
// name too long, a component that is a file, or a folder that cannot be searched; through a
// reader that escaped as an unexplained exception (the study-file fuzzer: a case path of 300
// characters). The callers turn the answer into a message naming their file, key and value.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>

namespace swarf {

struct PathKind {
  enum Kind { Missing, File, Directory, Unusable } kind = Missing;
  std::string error;  ///< Unusable: why, from the system ("File name too long")
};

inline PathKind path_kind(const std::string& path) {
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (st.type() == std::filesystem::file_type::not_found) return {PathKind::Missing, ""};
  if (ec) return {PathKind::Unusable, ec.message()};
  if (st.type() == std::filesystem::file_type::directory) return {PathKind::Directory, ""};
  return {PathKind::File, ""};
}

/// What is wrong with 'path' as the name of a file of the kind 'what' ("a mesh file"), for
/// a key's message: "" if it names a file.
inline std::string file_problem(const std::string& path, const std::string& what) {
  const PathKind k = path_kind(path);
  switch (k.kind) {
    case PathKind::File:
      return "";
    case PathKind::Missing:
      return "file not found: " + path;
    case PathKind::Directory:
      return "is a directory, not " + what + ": " + path;
    default:
      return k.error + ": " + path;
  }
}

}  // namespace swarf

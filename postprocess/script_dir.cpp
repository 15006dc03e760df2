// script_dir.cpp: see script_dir.h.
#include "postprocess/script_dir.h"

#include <cstdlib>
#include <filesystem>

namespace swarf {

std::string postprocess_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("SWARF_POSTPROCESS_DIR")) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / SWARF_POSTPROCESS_INSTALL_DIR;
    if (fs::is_directory(installed, ec)) return installed.lexically_normal().string();
  }
  return SWARF_POSTPROCESS_DIR;
}

std::string postprocess_path(const std::string& name) { return postprocess_dir() + "/" + name; }

}  // namespace swarf

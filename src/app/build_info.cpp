// build_info.cpp: provenance (see build_info.h). The commit comes from a header that the build
// rewrites whenever HEAD or the tree's state changes (cmake/git_info.cmake), so only this file
// recompiles.
#include "app/build_info.h"

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <ctime>

#include "app/build_config.h"
#include "app/git_info.h"
#include "io/h5file.h"
#include "postprocess/script_dir.h"
#include "swarf/version.h"

namespace swarf {

const BuildInfo& build_info() {
  static const BuildInfo info{SWARF_VERSION,    SWARF_GIT_COMMIT, SWARF_GIT_DIRTY,
                              SWARF_BUILD_TYPE, SWARF_COMPILER,   SWARF_COMPILE_FLAGS};
  return info;
}

static std::string dirty_word(int dirty) {
  return dirty == 1 ? "with uncommitted changes" : dirty == 0 ? "clean" : "tree state unknown";
}

std::string version_text() {
  const BuildInfo& b = build_info();
  return fmt::format("swarf {}\ncommit {} ({})\nbuild {}, {}\nflags {}\nscripts {}", b.version, b.git_commit,
                     dirty_word(b.git_dirty), b.build_type, b.compiler, b.compile_flags, postprocess_dir());
}

RunProvenance run_provenance(int threads) {
  RunProvenance r;
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::array<char, 32> date{};
  std::strftime(date.data(), date.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  r.started_utc = date.data();
  std::array<char, 256> host{};
  r.host = gethostname(host.data(), host.size() - 1) == 0 ? host.data() : "unknown";
  r.threads = threads;
  return r;
}

nlohmann::json provenance_json(const RunProvenance& run) {
  const BuildInfo& b = build_info();
  return {{"version", b.version},
          {"git_commit", b.git_commit},
          {"git_dirty", b.git_dirty == 1   ? nlohmann::json(true)
                        : b.git_dirty == 0 ? nlohmann::json(false)
                                           : nullptr},
          {"build_type", b.build_type},
          {"compiler", b.compiler},
          {"compile_flags", b.compile_flags},
          {"started_utc", run.started_utc},
          {"host", run.host},
          {"threads", run.threads},
          {"ranks", run.ranks}};
}

void write_provenance_attributes(H5File& f, const RunProvenance& run) {
  const BuildInfo& b = build_info();
  f.write_attribute("swarf_version", b.version);
  f.write_attribute("git_commit", b.git_commit);
  f.write_attribute("git_dirty", static_cast<double>(b.git_dirty));
  f.write_attribute("build_type", b.build_type);
  f.write_attribute("compiler", b.compiler);
  f.write_attribute("compile_flags", b.compile_flags);
  f.write_attribute("started_utc", run.started_utc);
  f.write_attribute("host", run.host);
  f.write_attribute("threads", static_cast<double>(run.threads));
  f.write_attribute("ranks", static_cast<double>(run.ranks));
}

}  // namespace swarf

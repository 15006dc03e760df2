// build_info.h: provenance. Which build made a result (version, git commit and whether the tree
// had uncommitted changes, build type, compiler, flags) and where and when it ran, recorded in
// summary.json ("provenance") and as root attributes of results.h5, and printed by
// `swarf --version`. A result that cannot name its build cannot be reproduced.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace swarf {

class H5File;

struct BuildInfo {
  std::string version;        ///< SWARF_VERSION
  std::string git_commit;     ///< full hash of HEAD at build time, "unknown" outside a git tree
  int git_dirty = -1;         ///< 1: tracked files differed from the commit; 0: clean; -1: unknown
  std::string build_type;     ///< CMAKE_BUILD_TYPE
  std::string compiler;       ///< "GNU 12.2.0"
  std::string compile_flags;  ///< the C++ flags of the build type and the project's options
};

const BuildInfo& build_info();

/// The text of `swarf --version`: one line with version and commit, then build and compiler,
/// flags, and the folder of the post-processing scripts it runs (postprocess/script_dir.h).
std::string version_text();

/// Where and when a run ran: the build, its start (UTC, ISO 8601), the host and the threads.
struct RunProvenance {
  std::string started_utc;  ///< "2026-12-02T17:05:09Z"
  std::string host;
  int threads = 1;  ///< OpenMP threads (per rank)
  int ranks = 1;    ///< MPI ranks of the run (domain decomposition)
};

/// The run's provenance now (its start time: call it when the run starts).
RunProvenance run_provenance(int threads);

/// summary.json's "provenance": the build and the run's start, host and threads.
nlohmann::json provenance_json(const RunProvenance& run);

/// The same as root attributes of results.h5 (strings; 'threads' and 'git_dirty' as float64).
void write_provenance_attributes(H5File& f, const RunProvenance& run);

}  // namespace swarf

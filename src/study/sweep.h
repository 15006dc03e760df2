// sweep.h: the runner of parameter studies ('swarf sweep'): each case of a study (study.h) as
// a subprocess of swarf itself (several at once, and across MPI ranks), resuming an
// interrupted study from its record (study_record.h). Described in docs/studies.md.
#pragma once

#include <string>
#include <vector>

namespace swarf {

/// Runs argv[0] with the arguments, stdin from /dev/null, stdout and stderr to log_path.
/// Returns the exit code, or 128 + signal number when the process was killed.
/// With time_limit > 0 (s of wall time), a process still running then gets SIGTERM (a swarf
/// run writes its checkpoint and ends with 143), and SIGKILL 10 s later; 'timed_out' says so.
int run_logged(const std::vector<std::string>& argv, const std::string& log_path, double time_limit = 0,
               bool* timed_out = nullptr);

struct SweepOptions {
  std::string study_path;
  std::string out_dir;
  int jobs = 1;            ///< cases at once (per MPI rank)
  int threads = 0;         ///< threads per case; 0 = max(1, cores / (jobs x ranks on the node))
  std::string swarf_exe;   ///< the swarf binary; empty = /proc/self/exe
  bool list_only = false;  ///< print the cases (id, state, overrides) and run nothing
};

/// 'swarf sweep': runs the pending cases, then writes study.csv, timing.csv and the plots.
/// Under mpirun (OMPI_COMM_WORLD_SIZE or PMI_SIZE set) the ranks share the cases. Returns 0
/// when every case completed, 1 when some failed.
int run_sweep(const SweepOptions& options);

}  // namespace swarf

// sweep.h: parameter studies ('swarf sweep'): the study file, its expansion into cases, running
// each case as a subprocess of swarf itself (several at once, and across MPI ranks), and
// resuming an interrupted study. The study file is described in docs/studies.md.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace swarf {

/// One case of a study: the overrides that make it.
struct StudyCase {
  std::string id;                             ///< "0000", "0001", ...: the folder DIR/cases/<id>
  std::map<std::string, std::string> values;  ///< varied key (and seed key) -> TOML value text
  int repetition = 0;                         ///< 0-based repetition (seed = seed_start + repetition)
};

/// A study file, expanded into its cases.
struct Study {
  std::string file;                          ///< the study file as given
  std::string title;                         ///< key 'title' (may be empty)
  std::string base;                          ///< key 'base' as written
  std::string base_path;                     ///< 'base' resolved against the study file's directory
  std::string base_hash;                     ///< FNV-1a 64-bit hash of the base case text, hex
  std::map<std::string, std::string> fixed;  ///< [set]: key -> TOML value text, applied to every case
  std::vector<std::string> parameters;       ///< the varied keys in column order (seed key last)
  std::map<std::string, std::string> units;  ///< [units]: key -> unit text for the study.csv header
  int repetitions = 1;
  std::string seed_key;  ///< case key set to seed_start + repetition (empty: none)
  long long seed_start = 1;
  bool plots = true;
  double case_time_limit = 0;  ///< s of wall time per case; 0 = none. A case past it is stopped (SIGTERM, then SIGKILL)
  std::vector<std::string> plot_metrics;  ///< empty = the default subset (see study_table.h)
  std::vector<std::string> plot_against;  ///< empty = the numeric varied keys
  std::vector<StudyCase> cases;           ///< in id order
};

/// Parses and expands a study file's text (directory: where 'base' is resolved). Throws
/// InputError naming the file, the key and the value.
Study parse_study(const std::string& text, const std::string& source, const std::string& directory);
/// Reads and expands a study file; also reads the base case and hashes it.
Study load_study(const std::string& path);

/// The --set arguments of a case ("key=value"): the [set] keys, then the varied ones.
std::vector<std::string> case_overrides(const Study& study, const StudyCase& c);
/// Reads the base case with every case's overrides, so a bad key stops the study before it runs.
void check_cases(const Study& study);

/// Compares with DIR/study.json of an earlier run: known cases keep their ids, new ones are
/// numbered after them. Throws InputError naming the keys when the change would invalidate
/// finished cases (base case text, [set], seed key, a removed case). No study.json: no change.
void reconcile_study(Study& study, const std::string& out_dir);
void write_study_json(const Study& study, const std::string& out_dir);
/// The expanded study recorded by 'swarf sweep' in DIR/study.json.
Study read_study_json(const std::string& out_dir);

enum class CaseState { completed, failed, interrupted, not_run };
struct CaseStatus {
  CaseState state = CaseState::not_run;
  int exit_code = 0;         ///< failed: the exit code (128 + signal when killed by a signal)
  std::string log_tail;      ///< failed: the last lines of log.txt
  std::string text() const;  ///< "completed", "failed (exit 3)", "interrupted", "not run"
};
std::string case_dir(const std::string& out_dir, const StudyCase& c);
/// Completed only if DIR/cases/<id>/summary.json parses, says "completed" and was run with
/// this case's overrides.
CaseStatus case_status(const Study& study, const StudyCase& c, const std::string& out_dir);

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

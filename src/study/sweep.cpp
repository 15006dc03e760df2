// sweep.cpp: running a study's cases as subprocesses of swarf, several at once and across MPI
// ranks, and resuming (see sweep.h and docs/studies.md).
#include "study/sweep.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spawn.h>
#include <sys/wait.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "io/atomic_file.h"
#include "io/console.h"
#include "setup/case_config.h"
#include "study/study.h"
#include "study/study_record.h"
#include "study/study_table.h"
#include "study/study_text.h"
#include "study/sweep_mpi.h"
#include "swarf/core/errors.h"

extern char** environ;

namespace swarf {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace study_text;

// ---- running ---------------------------------------------------------------------------

int run_logged(const std::vector<std::string>& argv, const std::string& log_path, double time_limit, bool* timed_out) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // A case is a process of its own, not a rank of the study's mpirun: it gets the environment
  // without the launcher's rank variables, which 'swarf run' reads as one run over several ranks.
  std::vector<char*> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "OMPI_COMM_WORLD_", 16) != 0 && std::strncmp(*e, "PMI_", 4) != 0) env.push_back(*e);
  env.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0].c_str(), &fa, nullptr, args.data(), env.data());
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw std::runtime_error(fmt::format("cannot start '{}': {}", argv[0], std::strerror(rc)));
  int status = 0;
  if (timed_out) *timed_out = false;
  if (time_limit > 0) {
    // Polled every 50 ms: a case runs for seconds at least, and no signal handler is needed.
    const auto start = std::chrono::steady_clock::now();
    bool termed = false;
    while (true) {
      const pid_t w = waitpid(pid, &status, WNOHANG);
      if (w == pid) break;
      if (w < 0 && errno != EINTR)
        throw std::runtime_error(fmt::format("waiting for '{}': {}", argv[0], std::strerror(errno)));
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!termed && t > time_limit) {
        ::kill(pid, SIGTERM);
        termed = true;
        if (timed_out) *timed_out = true;
      } else if (termed && t > time_limit + 10.0) {
        ::kill(pid, SIGKILL);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  } else {
    while (waitpid(pid, &status, 0) < 0)
      if (errno != EINTR) throw std::runtime_error(fmt::format("waiting for '{}': {}", argv[0], std::strerror(errno)));
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

namespace {

std::string duration_text(double s) {
  if (!(s >= 0)) return "?";
  if (s < 10) return fmt::format("{:.1f} s", s);
  if (s < 60) return fmt::format("{:.0f} s", s);
  if (s < 3600) return fmt::format("{} min {:02.0f} s", int(s / 60), s - 60 * int(s / 60));
  return fmt::format("{} h {:02d} min", int(s / 3600), int(s / 60) % 60);
}

// Progress of this process's cases on stderr: one line per finished case.
class SweepProgress {
 public:
  SweepProgress(std::string prefix, std::size_t to_run) : prefix_(std::move(prefix)), to_run_(to_run) {}
  void started() {
    std::lock_guard<std::mutex> lock(m_);
    ++running_;
  }
  void finished(const std::string& id, bool ok, double seconds, const std::string& detail) {
    std::lock_guard<std::mutex> lock(m_);
    --running_;
    ++done_;
    if (!ok) ++failed_;
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const std::size_t left = to_run_ - done_;
    eprint("sweep{}: case {} {} in {}; {}/{} done, {} failed, {} running, ETA {}\n", prefix_, id,
           ok ? "completed" : "FAILED", duration_text(seconds), done_, to_run_, failed_, running_,
           left == 0 ? "0 s" : duration_text(el * double(left) / double(done_)));
    if (!ok && !detail.empty()) eprint("{}", detail);
    std::fflush(stderr);
  }
  std::size_t failed() const { return failed_; }

 private:
  std::mutex m_;
  std::string prefix_;
  std::size_t to_run_, done_ = 0, failed_ = 0, running_ = 0;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

// Runs one case as 'swarf run' in its folder and records a failure.
bool run_one(const Study& s, const StudyCase& c, const SweepOptions& o, int threads, SweepProgress& progress) {
  const std::string dir = case_dir(o.out_dir, c);
  const auto t0 = std::chrono::steady_clock::now();
  progress.started();
  int code = -1;
  std::string detail;
  try {
    fs::create_directories(dir);
    fs::remove(fs::path(dir) / "sweep_status.json");
    std::vector<std::string> argv{o.swarf_exe.empty() ? "/proc/self/exe" : o.swarf_exe, "run", s.base_path, "--out",
                                  dir};
    for (const auto& ov : case_overrides(s, c)) argv.insert(argv.end(), {"--set", ov});
    argv.insert(argv.end(), {"--threads", std::to_string(threads)});
    bool timed_out = false;
    code = run_logged(argv, (fs::path(dir) / "log.txt").string(), s.case_time_limit, &timed_out);
    if (timed_out)
      detail = fmt::format("stopped: the case ran longer than case_time_limit = {} s of wall time\n", s.case_time_limit);
  } catch (const std::exception& e) {
    detail = std::string(e.what()) + "\n";
  }
  bool ok = code == 0 && case_status(s, c, o.out_dir).state == CaseState::completed;
  if (!ok) {
    detail += log_tail((fs::path(dir) / "log.txt").string(), 8);
    if (code == 0) detail += "(exit code 0 but no complete summary.json)\n";
    try {
      const json st{{"exit_code", code}, {"log_tail", detail}};
      write_text_atomic((fs::path(dir) / "sweep_status.json").string(), st.dump(2) + "\n");
    } catch (const std::exception& e) {
      detail += fmt::format("(could not record the failure: {})\n", e.what());
    }
  }
  progress.finished(c.id, ok, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), detail);
  return ok;
}

}  // namespace

int run_sweep(const SweepOptions& o) {
  MpiSession mpi;
  const int rank = mpi.rank(), size = mpi.size();
  Study study;
  std::vector<std::size_t> pending;
  std::exception_ptr setup_error;
  try {
    if (o.jobs < 1) throw InputError(fmt::format("--jobs {}: must be at least 1", o.jobs));
    if (o.threads < 0) throw InputError(fmt::format("--threads {}: must be at least 1", o.threads));
    study = load_study(o.study_path);
    check_cases(study);
    reconcile_study(study, o.out_dir);
    for (std::size_t k = 0; k < study.cases.size(); ++k)
      if (case_status(study, study.cases[k], o.out_dir).state != CaseState::completed) pending.push_back(k);
  } catch (...) {
    setup_error = std::current_exception();
  }
  // Every rank reads the same files, so a bad study stops all of them; a rank-specific
  // failure (a file this rank cannot see) stops the others too instead of leaving them waiting.
  const int any_error = mpi.max_all(setup_error ? 1 : 0), root_error = mpi.from_root(setup_error ? 1 : 0);
  if (any_error) {
    if (rank == 0 && setup_error) std::rethrow_exception(setup_error);
    if (rank == 0) throw std::runtime_error("another MPI rank could not set up the study (see its message)");
    if (setup_error && !root_error) {
      try {
        std::rethrow_exception(setup_error);
      } catch (const std::exception& e) {
        eprint("swarf: error (MPI rank {}): {}\n", rank, e.what());
      }
    }
    return 2;
  }

  if (o.list_only) {
    if (rank == 0)
      for (const auto& c : study.cases)
        fmt::print("{} {:<11} {}\n", c.id, case_status(study, c, o.out_dir).text(),
                   fmt::join(case_overrides(study, c), " "));
    return 0;
  }
  if (rank == 0) {
    fs::create_directories(fs::path(o.out_dir) / "cases");
    write_study_json(study, o.out_dir);
    for (const auto& p : study.parameters)
      if (!study.units.count(p))
        eprint("sweep: note: no unit for '{}' in [units]: its unit in study_columns.csv stays empty\n", p);
  }
  mpi.barrier();

  std::vector<std::size_t> mine;
  for (std::size_t k = 0; k < pending.size(); ++k)
    if (int(k % std::size_t(size)) == rank) mine.push_back(pending[k]);
  const int cores = std::max(1, int(std::thread::hardware_concurrency()));
  const int threads = o.threads > 0 ? o.threads : std::max(1, cores / (o.jobs * mpi.local_size()));
  const std::string prefix = size > 1 ? fmt::format(" [rank {} of {}]", rank, size) : "";
  if (rank == 0)
    eprint("sweep: {}: {} cases, {} finished earlier, {} to run{}; {} at once x {} thread(s) per case\n", study.file,
           study.cases.size(), study.cases.size() - pending.size(), pending.size(),
           size > 1 ? fmt::format(" on {} ranks", size) : "", o.jobs, threads);
  SweepProgress progress(prefix, mine.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&]() {
    for (std::size_t k = next++; k < mine.size(); k = next++)
      run_one(study, study.cases[mine[k]], o, threads, progress);
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < std::min<int>(o.jobs, int(mine.size())); ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  mpi.barrier();
  if (rank != 0) return progress.failed() ? 1 : 0;

  // Rank 0 gathers what every rank wrote into the case folders.
  const StudyTable table = collect_table(study, o.out_dir);
  const StudyTable timing = collect_table(study, o.out_dir, true);
  write_text_atomic((fs::path(o.out_dir) / "study.csv").string(), table_csv(table));
  write_text_atomic((fs::path(o.out_dir) / "timing.csv").string(), table_csv(timing));
  write_text_atomic((fs::path(o.out_dir) / "study_columns.csv").string(), columns_csv(table, timing));
  std::size_t completed = 0;
  for (const auto& st : table.status) completed += st.state == CaseState::completed;
  std::string plots = "no plots (plots = false)";
  if (study.plots) {
    const std::string why = draw_plots(study, table, o.out_dir);
    plots = why.empty() ? "plots in plots/" : "no plots: " + why;
  }
  fmt::print(
      "sweep: {} cases: {} completed, {} failed or not finished; wrote {}/study.csv, timing.csv, study_columns.csv; "
      "{}\n",
      table.rows.size(), completed, table.rows.size() - completed, o.out_dir, plots);
  return completed == table.rows.size() ? 0 : 1;
}

}  // namespace swarf

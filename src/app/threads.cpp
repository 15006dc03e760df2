// threads.cpp: the OpenMP thread count and pinning (see threads.h).
#include "app/threads.h"

#include <fmt/format.h>
#include <omp.h>
#include <pthread.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "swarf/core/errors.h"

namespace swarf {
namespace {

// The CPUs this process may run on (empty if the affinity cannot be read), and whether they are
// the whole machine (mpirun --bind-to none) rather than a share mpirun bound it to.
struct AllowedCpus {
  std::vector<int> cpus;
  bool whole_machine = false;
};
// Read once, at the first call (set_threads makes it before it pins): sched_getaffinity(0)
// reads the calling thread's mask, and pinning makes the main thread OpenMP's thread 0 on one
// CPU, after which it would report a one-CPU process (the false "threads share 1 CPU" warning
// of every pinned run) and hand that one CPU to every process the run starts.
const AllowedCpus& allowed_cpus() {
  static const AllowedCpus a = [] {
    AllowedCpus r;
    cpu_set_t allowed;
    if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return r;
    for (int c = 0; c < CPU_SETSIZE; ++c)
      if (CPU_ISSET(c, &allowed)) r.cpus.push_back(c);
    r.whole_machine = static_cast<long>(r.cpus.size()) >= sysconf(_SC_NPROCESSORS_ONLN);
    return r;
  }();
  return a;
}

// Pins OpenMP thread t to the t-th CPU this process may run on, when it runs 2 or more
// threads, has at least as many CPUs, and the environment does not place threads itself
// (OMP_PROC_BIND, OMP_PLACES, GOMP_CPU_AFFINITY; OMP_PROC_BIND=false keeps them free).
// Unpinned threads were migrated between the cores and lost most of the second thread's gain
// (validation/bench/README.md). A process limited to one CPU (a sweep's case, an MPI rank
// bound to a core) is left alone. The ranks of one run on one machine (local_size > 1) that
// may each run anywhere take turns: rank r's threads go to CPUs r x threads, ...; when they do
// not all fit, they stay free (all ranks pinned to the first CPUs would share them).
void pin_threads(int threads, int local_rank, int local_size) {
  if (threads < 2 || std::getenv("OMP_PROC_BIND") || std::getenv("OMP_PLACES") || std::getenv("GOMP_CPU_AFFINITY"))
    return;
  const AllowedCpus& allowed = allowed_cpus();
  const std::vector<int>& cpus = allowed.cpus;
  if (static_cast<int>(cpus.size()) < threads) return;
  int first = 0;
  if (local_size > 1 && allowed.whole_machine) {  // (a rank bound to its own CPUs by mpirun pins within them)
    if (static_cast<int>(cpus.size()) < threads * local_size) return;
    first = local_rank * threads;
  }
#pragma omp parallel num_threads(threads)
  {
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpus[first + omp_get_thread_num()], &one);
    pthread_setaffinity_np(pthread_self(), sizeof one, &one);  // (on failure the thread stays free)
  }
}

}  // namespace

int set_threads(int n, int local_rank, int local_size) {
  if (n > 0) omp_set_num_threads(n);
  const int used = omp_get_max_threads();
  pin_threads(used, local_rank, local_size);
  return used;
}

CallingThreadUnpinned::CallingThreadUnpinned() {
  const AllowedCpus& a = allowed_cpus();
  if (a.cpus.empty() || pthread_getaffinity_np(pthread_self(), sizeof saved_, &saved_) != 0) return;
  cpu_set_t all;
  CPU_ZERO(&all);
  for (int c : a.cpus) CPU_SET(c, &all);
  restore_ = pthread_setaffinity_np(pthread_self(), sizeof all, &all) == 0;  // (on failure it stays where it is)
}

CallingThreadUnpinned::~CallingThreadUnpinned() {
  if (restore_) pthread_setaffinity_np(pthread_self(), sizeof saved_, &saved_);
}

std::string thread_placement_warning(int threads) {
  const AllowedCpus& a = allowed_cpus();
  const int cpus = static_cast<int>(a.cpus.size());
  if (a.cpus.empty() || threads <= cpus) return "";
  return fmt::format(
      "warning: {} threads share the {} CPU{} this process may run on (its affinity: under mpirun, the rank's "
      "binding), so they run at about the speed of {}; give each rank its threads' cores (Open MPI: mpirun "
      "--map-by slot:PE={} or --bind-to none; Slurm: --cpus-per-task={}) or ask for --threads {}",
      threads, cpus, cpus == 1 ? "" : "s", cpus, threads, threads, cpus);
}

int threads_per_rank(int local_size) {
  const AllowedCpus& a = allowed_cpus();
  const int cpus = a.cpus.empty() ? omp_get_num_procs() : static_cast<int>(a.cpus.size());
  return std::max(1, a.whole_machine || a.cpus.empty() ? cpus / std::max(1, local_size) : cpus);
}

int max_thread_count() { return std::max(64, 8 * omp_get_num_procs()); }

void check_thread_count(long long n, const char* option) {
  if (n < 1 || n > max_thread_count())
    throw InputError(fmt::format("{} {}: the thread count must lie in [1, {}] (8 per CPU of this machine, at least 64)",
                                 option, n, max_thread_count()));
}

}  // namespace swarf

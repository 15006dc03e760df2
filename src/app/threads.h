// threads.h: the OpenMP thread count of a run (and where its threads run).
#pragma once

#include <sched.h>

#include <string>

namespace swarf {

/// Sets the OpenMP thread count (n > 0) and returns the count in effect; pins the threads to
/// CPUs when that helps (threads.cpp says when). 'local_rank' of 'local_size': this process's
/// place among the MPI ranks of one run on its machine (their threads must not share CPUs).
int set_threads(int n, int local_rank = 0, int local_size = 1);
/// While it lives, the calling thread may run on every CPU the process could run on at its
/// start: set_threads pins the main thread (OpenMP's thread 0) to one CPU, and a process it
/// starts (the plots' Python) would inherit that one CPU. Restores the pinning when it goes.
class CallingThreadUnpinned {
 public:
  CallingThreadUnpinned();
  ~CallingThreadUnpinned();
  CallingThreadUnpinned(const CallingThreadUnpinned&) = delete;
  CallingThreadUnpinned& operator=(const CallingThreadUnpinned&) = delete;

 private:
  cpu_set_t saved_;
  bool restore_ = false;
};
/// "" if 'threads' threads each have a CPU of their own; otherwise a warning that they share the
/// fewer CPUs this process may run on (mpirun binds each rank to one core unless told
/// otherwise: two threads of one rank then run at the speed of one), with the remedy.
std::string thread_placement_warning(int threads);
/// The threads a rank of a run over MPI ranks takes when none are asked for: the CPUs it may run
/// on, shared with the other 'local_size' ranks on its machine unless mpirun bound it to its own.
int threads_per_rank(int local_size);

/// Throws InputError naming 'option' unless 1 <= n <= max_thread_count(): OpenMP crashes
/// when it cannot create the threads it was asked for.
void check_thread_count(long long n, const char* option);
/// The most threads a run may ask for: 8 per CPU, at least 64.
int max_thread_count();

}  // namespace swarf

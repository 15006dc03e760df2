// test_threads.cpp: the thread count's placement (src/app/threads.h). Pinning the threads puts
// the main thread, OpenMP's thread 0, on one CPU; what the run reads of the process's CPUs
// afterwards (the shared-CPU warning, the plots' process) must still be the process's.
#include <gtest/gtest.h>
#include <omp.h>
#include <pthread.h>
#include <sched.h>

#include <cstdlib>

#include "app/threads.h"

namespace swarf {
namespace {

int cpus_of_calling_thread() {
  cpu_set_t s;
  if (pthread_getaffinity_np(pthread_self(), sizeof s, &s) != 0) return -1;
  return CPU_COUNT(&s);
}

TEST(Threads, PinnedThreadsAreNotTakenForThreadsThatShareOneCpu) {
  const int process_cpus = cpus_of_calling_thread();
  if (process_cpus < 2 || std::getenv("OMP_PROC_BIND") || std::getenv("OMP_PLACES") || std::getenv("GOMP_CPU_AFFINITY"))
    GTEST_SKIP() << "needs 2 CPUs and threads that swarf pins";
  cpu_set_t start;
  ASSERT_EQ(pthread_getaffinity_np(pthread_self(), sizeof start, &start), 0);
  const int threads_before = omp_get_max_threads();

  ASSERT_EQ(set_threads(2), 2);
  EXPECT_EQ(cpus_of_calling_thread(), 1);  // (thread 0 is pinned: what the rest must not read)
  EXPECT_EQ(thread_placement_warning(2), "") << "two pinned threads on two CPUs do not share one";
  EXPECT_NE(thread_placement_warning(process_cpus + 1), "") << "more threads than CPUs still warns";
  {
    const CallingThreadUnpinned unpinned;  // (what a started process inherits)
    EXPECT_EQ(cpus_of_calling_thread(), process_cpus);
  }
  EXPECT_EQ(cpus_of_calling_thread(), 1) << "the pinning comes back";

  pthread_setaffinity_np(pthread_self(), sizeof start, &start);
  omp_set_num_threads(threads_before);
}

}  // namespace
}  // namespace swarf

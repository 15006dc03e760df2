// threads.h: the OpenMP thread count of a run (and where its threads run).
#pragma once

namespace swarf {

/// Sets the OpenMP thread count (n > 0) and returns the count in effect; pins the threads to
/// CPUs when that helps (threads.cpp says when).
int set_threads(int n);

/// Throws InputError naming 'option' unless 1 <= n <= max_thread_count(): OpenMP crashes
/// when it cannot create the threads it was asked for.
void check_thread_count(long long n, const char* option);
/// The most threads a run may ask for: 8 per CPU, at least 64.
int max_thread_count();

}  // namespace swarf

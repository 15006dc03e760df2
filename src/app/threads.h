// threads.h: the OpenMP thread count of a run (and where its threads run).
#pragma once

namespace swarf {

/// Sets the OpenMP thread count (n > 0) and returns the count in effect; pins the threads to
/// CPUs when that helps (threads.cpp says when).
int set_threads(int n);

}  // namespace swarf

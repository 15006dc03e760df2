// loopback_comm.h: N ranks as N threads of one process (comm.h), so that the tests cover the
// logic of several domains without mpirun.
//
// run_loopback(n, f) starts n threads, calls f(comm) in each with that rank's LoopbackComm and
// joins them. The collectives meet at a std::barrier: each rank posts its buffers in a shared
// mailbox, waits for all, takes what was sent to it, and waits again before the mailbox is
// reused. A rank that throws leaves the barrier for good and marks the group failed; the others
// then throw at their next collective instead of waiting for it, and run_loopback rethrows the
// first exception.
#pragma once

#include <functional>

#include "swarf/core/comm.h"

namespace swarf {

/// Runs f on n ranks (threads), each with its own Comm; rethrows the first exception thrown.
void run_loopback(int n, const std::function<void(Comm&)>& f);

}  // namespace swarf

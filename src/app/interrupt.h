// interrupt.h: SIGINT and SIGTERM end a run between steps, not in the middle of one.
//
// The handler only records the signal; the run loop looks after each step, writes a
// checkpoint if checkpoints are on, says where it stopped and ends with 128 + the signal
// (130 for SIGINT, 143 for SIGTERM). A second signal of the same kind ends the process at
// once (the handler is reset after the first).
#pragma once

#include <stdexcept>
#include <string>

namespace swarf {

/// Installs the handlers and forgets an earlier signal (each run in one process calls it).
void install_interrupt_handlers();
/// The signal received since the handlers were installed, or 0.
int interrupt_signal();

/// Thrown by the run loop after an interruption; main() exits with exit_code().
struct Interrupted : std::runtime_error {
  Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal(signal) {}
  int exit_code() const { return 128 + signal; }
  int signal;
};

}  // namespace swarf

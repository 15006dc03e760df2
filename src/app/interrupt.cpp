// interrupt.cpp: see interrupt.h.
#include "app/interrupt.h"

#include <csignal>

namespace swarf {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int s) { g_signal = s; }

}  // namespace

void install_interrupt_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  g_signal = 0;                // (a second run in one process, from the Python bindings, starts uninterrupted)
  sa.sa_flags = SA_RESETHAND;  // (a second signal takes the default action: the user insists)
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int interrupt_signal() { return g_signal; }

}  // namespace swarf

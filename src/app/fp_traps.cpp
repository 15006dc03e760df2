// fp_traps.cpp: floating-point traps and their SIGFPE handler (see fp_traps.h).
#include "app/fp_traps.h"

#include <execinfo.h>
#include <fenv.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace swarf {
namespace {

void write_err(const char* s) {
  // (async-signal-safe: write(2) only; a failed write has nowhere to be reported)
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, s, std::strlen(s));
}

void on_sigfpe(int sig, siginfo_t* info, void*) {
  const char* what = "floating-point exception";
  switch (info->si_code) {
    case FPE_FLTINV:
      what = "invalid floating-point operation (a NaN made)";
      break;
    case FPE_FLTDIV:
      what = "floating-point division by zero";
      break;
    case FPE_FLTOVF:
      what = "floating-point overflow";
      break;
    case FPE_INTDIV:
      what = "integer division by zero";
      break;
    default:
      break;
  }
  write_err("\nswarf: SIGFPE: ");
  write_err(what);
  write_err(" (traps on: SWARF_FP_TRAPS=1 or the test binary); backtrace:\n");
  void* frames[64];
  ::backtrace_symbols_fd(frames, ::backtrace(frames, 64), STDERR_FILENO);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

void enable_fp_traps() {
  // (backtrace() loads libgcc on its first call, which may allocate: not in the handler)
  void* warm[1];
  ::backtrace(warm, 1);
  struct sigaction sa {};
  sa.sa_sigaction = on_sigfpe;
  sa.sa_flags = SA_SIGINFO | SA_RESETHAND;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGFPE, &sa, nullptr);
  ::feclearexcept(FE_ALL_EXCEPT);
  ::feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
}

bool enable_fp_traps_from_env() {
  const char* v = std::getenv("SWARF_FP_TRAPS");
  if (!v || std::strcmp(v, "1") != 0) return false;
  enable_fp_traps();
  return true;
}

}  // namespace swarf

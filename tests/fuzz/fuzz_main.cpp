// fuzz_main.cpp: the libFuzzer entry of one harness; SWARF_FUZZ_TARGET names the function of
// fuzz_targets.h it feeds (tests/fuzz/CMakeLists.txt builds one executable per target).
#include <fenv.h>

#include <cstdlib>
#include <cstring>

#include "fuzz_targets.h"

// Floating-point traps as in the test build (tests/test_main.cpp): a NaN, an infinity or a
// division by zero made from an input is a finding (SIGFPE, reported by the sanitizer's
// handler with its stack). SWARF_FP_TRAPS=0 turns them off.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* v = std::getenv("SWARF_FP_TRAPS");
  if (!v || std::strcmp(v, "0") != 0) feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
  // The empty input once, outside the per-input time limit: it makes the valid files the HDF5
  // targets edit (the checkpoint's cut runs its first steps, seconds under the sanitizers).
  swarf::fuzz::SWARF_FUZZ_TARGET(nullptr, 0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  swarf::fuzz::SWARF_FUZZ_TARGET(data, size);
  return 0;
}

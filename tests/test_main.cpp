// test_main.cpp: the test binary's main: GoogleTest with floating-point traps on.
//
// Every test runs with invalid operations, divisions by zero and overflows trapped
// (app/fp_traps.h): a NaN or inf made anywhere in the engine, the readers or the tests ends
// the binary with SIGFPE and a backtrace at the operation that made it, and SWARF_FP_TRAPS=1
// is set for the swarf runs the tests start, so they trap too. SWARF_FP_TRAPS=0 in the
// environment turns both off (to see what a test does past the first trap).
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdlib>
#include <cstring>

#include "app/fp_traps.h"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const char* v = std::getenv("SWARF_FP_TRAPS");
  if (!v || std::strcmp(v, "0") != 0) {
    swarf::enable_fp_traps();
    ::setenv("SWARF_FP_TRAPS", "1", 1);
  }
  return RUN_ALL_TESTS();
}

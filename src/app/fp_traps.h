// fp_traps.h: floating-point exceptions as a crash where they happen, for tests.
//
// With the traps on, an invalid operation (0/0, inf - inf, sqrt(-1), a comparison that
// signals), a division by zero or an overflow raises SIGFPE at the instruction that did it,
// instead of a NaN or inf that travels on and surfaces steps later as "unstable". The test
// binary turns them on always; the swarf program only when SWARF_FP_TRAPS=1 is in its
// environment (ctest sets it for every test, so the runs the tests start trap too); a
// production run never dies of a SIGFPE. The handler names the exception and prints a
// backtrace before the process ends with the signal.
#pragma once

namespace swarf {

/// Traps FE_INVALID, FE_DIVBYZERO and FE_OVERFLOW in this thread and the threads it starts
/// after (they inherit the floating-point environment), and installs the SIGFPE handler.
void enable_fp_traps();
/// enable_fp_traps() if the environment variable SWARF_FP_TRAPS is "1"; returns whether.
bool enable_fp_traps_from_env();

}  // namespace swarf

// run_limits.h: what a run needs, checked before its first step (issue 37 item 2): the memory
// of the particles a case makes and the steps it takes. Beyond the machine or the limit, an
// InputError names the keys that set the size or the step, the count and the time it would
// take; 'swarf run' and the case fuzzer (tests/fuzz) call the same checks.
#pragma once

namespace swarf {

struct CaseSettings;
struct Model;

/// The memory a generated workpiece or membrane needs, estimated before it is built; beyond
/// the machine's memory an InputError naming the keys (unless 'force').
void check_memory(const CaseSettings& cs, bool force);

/// A run whose step count, from the end time and the step, exceeds integrator.max_steps
/// (unless 'allow_long'); an inflow asking more particles in one step than its box holds;
/// inflows whose particles over the run need more memory than the machine has (unless 'force').
void check_run_length(const Model& m, bool allow_long, bool force, double t_start);

}  // namespace swarf

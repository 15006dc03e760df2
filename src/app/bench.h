// bench.h: 'swarf bench': named scenes timed for several thread counts (not a test).
#pragma once

#include <string>
#include <vector>

namespace swarf {

struct BenchOptions {
  std::vector<std::string> cases;  ///< case files; the scene name is the file stem
  std::vector<int> threads{1, 2};
  long long steps = 0;  ///< 0 = run to the case's end_time
  int repeats = 3;      ///< the median of the repeats is reported
  std::vector<std::string> overrides;
  bool stages = false;  ///< also print the time per step stage (last repeat)
};

/// Prints a table: scene, particles, rods, steps, threads, median s, ns/particle-step and the
/// scene's physics check (broken rods, kinetic energy at the end).
void run_bench(const BenchOptions& options);

}  // namespace swarf

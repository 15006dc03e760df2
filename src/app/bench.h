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
  /// The Newton solve's CG preconditioner: "block_jacobi" (the engine's, matrix-free) or "amg"
  /// (hypre's BoomerAMG on the assembled tangent, study/hypre_amg.h).
  std::string preconditioner = "block_jacobi";
  int amg_refresh = 1;         ///< a new AMG hierarchy at every amg_refresh-th tangent
  double amg_threshold = 0.5;  ///< BoomerAMG's strong threshold
  bool amg_nodal = false;      ///< coarsen by particles
};

/// Prints a table: scene, particles, rods, steps, threads, median s, ns/particle-step and the
/// scene's physics check (broken rods, kinetic energy at the end); with the AMG preconditioner
/// also its hierarchies and the time in their setup and cycles.
void run_bench(const BenchOptions& options);

}  // namespace swarf

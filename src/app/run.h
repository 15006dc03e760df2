// run.h: 'swarf run': a case from start to outputs.
#pragma once

#include <string>
#include <vector>

#include "app/run_file.h"
#include "app/threads.h"  // (set_threads, which the run's callers use beside run_case)
#include "swarf/step_listener.h"

namespace swarf {

class Comm;

struct RunOptions {
  std::string case_path;                 ///< empty = the built-in default case
  std::string out_dir;                   ///< empty: "swarf-out", or the checkpoint's directory on restart
  std::string restart;                   ///< checkpoint to continue from (--restart)
  std::vector<std::string> overrides;    ///< --set key=value
  int threads = 0;                       ///< 0 = OpenMP default
  bool force = false;                    ///< --force: run a case whose memory estimate exceeds the machine's
  bool allow_long = false;               ///< --allow-long: run a case estimated to need more than integrator.max_steps
  bool energy_check = true;              ///< false (--no-energy-check): a lost energy balance does not stop the run
  bool check = false;                    ///< --check: build the case and print its set-up; no run, no outputs
  std::vector<StepListener*> listeners;  ///< called around every step of the run (not owned; swarf.run's)
  /// Under mpirun: the ranks, over which the run is one run by domain decomposition (every rank
  /// calls run_case; rank 0 writes; run_ranks.h). Null: one process.
  Comm* comm = nullptr;
  int local_rank = 0, local_size = 1;  ///< under mpirun: this rank among the ranks on its machine (thread pinning)
  /// Under mpirun: steps between new slab cuts (--rebalance-every) and between the checks for
  /// particles that left their slab (--stray-check-every). Neither changes the results.
  long long rebalance_every = 1000, stray_check_every = 10;
  /// Under mpirun: how the ranks' regions are cut (--partition): "rcb", boxes by Zoltan's
  /// recursive coordinate bisection, or "slabs" along x; empty: rcb where swarf was built with
  /// Zoltan, slabs otherwise. Neither changes the results.
  std::string partition;
};

/// Runs the case and writes DIR/series.csv, DIR/summary.json, DIR/results.h5, the ParaView
/// series and the plots (with options.check: builds the case, prints its set-up and returns).
/// Throws InputError / SimulationError.
void run_case(const RunOptions& options);
/// The files run_case writes itself: summary.json (and summary.json.plotting, the copy the
/// plot script reads), results.h5, and run.log, which a restart appends to.
std::vector<RunFile> run_case_files();

}  // namespace swarf

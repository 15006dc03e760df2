// observer.h: what a run measures, one observer per quantity (Jolt's step listeners and
// LAMMPS's computes and fixes, seen from the output side).
//
// An observer declares its series columns by name and appends their values to each row;
// keeps whatever it accumulates between rows (and saves it in checkpoints under its own
// name); adds to results.h5 if it has a setup to record; and at the end writes its part of
// summary.json and prints its lines of the report. The run loop knows none of them by type:
// it asks each in turn (ObserverSet), so a new probe is one new file and one line in
// observers_for.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "app/series_columns.h"

namespace swarf {

class H5File;
class Simulation;
class StateArchive;
class StepListener;
class VtkSeries;

/// One series column: its name (the CSV header, the /series dataset), its unit ("1" for
/// counts and ratios) and a one-line meaning (docs/outputs.md has the full definitions).
struct Column {
  std::string name;
  std::string unit;
  std::string meaning;
};

/// What an observer may use at the end of the run.
struct RunEnd {
  const Simulation& sim;
  const SeriesColumns& series;  ///< every row of the run (those written before a restart too)
  const std::string& dir;       ///< the run directory
  VtkSeries* vtk;               ///< the ParaView series; null without output.vtk
  bool pictures;                ///< output.plots: render pictures
  int threads;                  ///< OpenMP threads in effect
  double wall_s;                ///< wall time of the whole run (the part before a restart too), s
  double step_wall_s;           ///< of it, outside the outputs, s
  int ranks = 1;                ///< MPI ranks of the run (mpirun -n N swarf run)
};

class Observer {
 public:
  virtual ~Observer() = default;
  /// Its name; its checkpoint state is stored under /run/<name>/.
  virtual std::string_view name() const = 0;
  /// Appends its series columns, in the order row() appends the values.
  virtual void columns(std::vector<Column>& out) const = 0;
  /// Appends one value per column for the state now.
  virtual void row(const Simulation& sim, std::vector<double>& values) = 0;
  /// A fresh run (not a restart) begins: the initial state, before the first row.
  virtual void begin(const Simulation&) {}
  /// Its checkpoint state, each field named once for save and load (as Simulation::visit_state).
  virtual void visit_state(StateArchive&) {}
  /// The listener to register when it must see every step, not only the rows (else null). In a
  /// run over MPI ranks it is called with rank 0's domain Simulation, whose time, counters and
  /// settings are the run's but whose particles are only that rank's (app/run_ranks.h): a
  /// listener that needs the particles at every step cannot run over ranks yet.
  virtual StepListener* step_listener() { return nullptr; }
  /// Adds its datasets to results.h5 (the final state) before the file is closed.
  virtual void write_results(H5File&) const {}
  /// Writes its part of summary.json and prints its lines of the final report; observers
  /// finish in the order of their columns.
  virtual void finish(const RunEnd&, nlohmann::json&) {}
};

}  // namespace swarf

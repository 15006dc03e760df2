// observer_set.h: the observers of one run, asked in turn by the run loop.
//
// The series' first column is the time, the key of every row (the chip analysis and the
// uniaxial loop read their columns against it); the observers' columns follow in the order
// they were given, which is the order of series.csv and of the final report.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/observers/observer.h"

namespace swarf {

class ObserverSet {
 public:
  /// Takes the observers and registers with 'sim' those that watch every step; the set must
  /// not outlive 'sim' (it removes them again when it ends).
  ObserverSet(Simulation& sim, std::vector<std::unique_ptr<Observer>> observers);
  ~ObserverSet();
  ObserverSet(const ObserverSet&) = delete;
  ObserverSet& operator=(const ObserverSet&) = delete;

  /// "time", then each observer's columns, with units and meanings.
  std::vector<Column> column_specs() const;
  /// Their names.
  std::vector<std::string> columns() const;
  /// A fresh run begins (each observer's begin).
  void begin();
  /// The row for the state now: the time, then each observer's values.
  std::vector<double> row();
  /// Every observer's state under "<name>/" of 'ar' (the checkpoint's /run/).
  void visit_state(StateArchive& ar);
  void write_results(H5File& f) const;
  void finish(const RunEnd& end, nlohmann::json& summary);
  /// The observers' step listeners (registered with the Simulation already; a run over ranks
  /// registers them with rank 0's domain too).
  std::vector<StepListener*> step_listeners() const;
  /// True if an observer of that name is in the set.
  bool has(std::string_view name) const;

 private:
  Simulation& sim_;
  std::vector<std::unique_ptr<Observer>> observers_;
};

}  // namespace swarf

// run_outputs.h: what the run loop writes while it goes: series rows, ParaView frames and
// checkpoints, each at the first step that reaches its time, and the record (RunRecord) that
// lets a restart go on with them.
//
// A row is the observers' (ObserverSet::row); every row written is kept (the checkpoint
// carries them, a restart rewrites series.csv whole, the observers read them back by column
// name at the end). Output time is measured apart from the steps for the summary's speed.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/observers/observer.h"
#include "app/run_file.h"
#include "app/series_columns.h"
#include "io/checkpoint.h"
#include "io/field_history.h"
#include "io/series.h"

namespace swarf {

class H5File;
class ObserverSet;
class Simulation;
class VtkSeries;
struct Model;

/// DIR/series_columns.csv: one row per series.csv column (column, unit, meaning), so that a
/// reader needs no second header row; written when the run starts.
void write_column_table(const std::string& path, const std::vector<Column>& columns);

/// The time history in results.h5: one dataset /series/<column> per column, with its unit and
/// meaning as attributes.
void write_series_datasets(H5File& f, const std::vector<Column>& columns, const SeriesColumns& series);

class RunOutputs {
 public:
  /// Opens DIR/series.csv.part (and the ParaView series with output.vtk); the observers'
  /// columns make the header. 'stored' is the case a checkpoint records.
  RunOutputs(const std::string& dir, const Model& model, Simulation& sim, ObserverSet& observers, CheckpointCase stored);
  ~RunOutputs();

  /// The files it may write: series.csv, series_columns.csv, results.xdmf, and kept by a
  /// restart, which continues them, checkpoint.h5, particles.pvd and frames/ (the ParaView series).
  static std::vector<RunFile> files();

  /// A fresh run: the observers begin, the initial row and frame, the schedule from t = 0.
  void begin();
  /// A restart: the state, the record and the observers' state from the checkpoint; the rows
  /// and frames written before it. Throws InputError.
  void restore(const std::string& checkpoint);
  /// After a step: the row, frame and checkpoint due now ('last': the final step, which
  /// writes a row and a frame and no checkpoint).
  void after_step(bool last);
  /// Whether after_step would write anything after the step that ended at time t (s) as step
  /// number 'steps' (a run over ranks gathers its state only then).
  bool due(double t, std::int64_t steps, bool last) const;

  struct WallTimes {
    double wall_s = 0;    ///< the whole run so far (the part before a restart too), s
    double output_s = 0;  ///< of it, writing outputs, s
  };
  /// Closes series.csv (renamed from .part) and returns the wall times.
  WallTimes finish();

  /// With output.vtk: the frames' per-particle fields into the results file being written, as
  /// groups /frames/NNNNN (io/field_history.h).
  void write_field_history(H5File& f);
  /// DIR/results.xdmf, the XDMF sidecar of the history in DIR/'results' (written atomically,
  /// after the results file is in place); nothing without output.vtk.
  void write_field_history_sidecar(const std::string& results);

  /// Every row written, by column name.
  SeriesColumns series() const { return SeriesColumns(columns_, rec_.rows); }
  /// The ParaView series, or null without output.vtk.
  VtkSeries* vtk() { return vtk_.get(); }
  bool checkpoints() const { return checkpoint_every_ > 0 || checkpoint_at_end_; }
  /// Writes DIR/checkpoint.h5 of the current state now (an interrupted run keeps its place).
  void write_checkpoint_now();

 private:
  void write_row();
  bool row_due(double t, bool last) const { return t >= rec_.next_row * (1.0 - 1e-12) || last; }
  bool frame_due(double t, bool last) const { return vtk_ && (t >= rec_.next_frame * (1.0 - 1e-12) || last); }
  bool checkpoint_due(std::int64_t steps, bool last) const {
    return last ? checkpoint_at_end_ : checkpoint_every_ > 0 && steps % checkpoint_every_ == 0;
  }
  void write_frame(double t);  // the ParaView frame with the per-particle fields
  double seconds_since(std::chrono::steady_clock::time_point t) const;

  std::string dir_;
  const Model& model_;
  Simulation& sim_;
  ObserverSet& observers_;
  CheckpointCase stored_;
  std::vector<std::string> columns_;
  double series_interval_;  ///< s
  double frame_interval_;   ///< s; 0 = the first and the last frame only
  int checkpoint_every_;    ///< steps; 0 = none
  bool checkpoint_at_end_;  ///< a checkpoint after the last step too
  std::unique_ptr<VtkSeries> vtk_;
  SeriesWriter series_;
  RunRecord rec_;
  std::vector<HistoryFrame> history_;            ///< the frames write_field_history wrote
  std::chrono::steady_clock::time_point start_;  ///< of this process's steps
  double wall_before_ = 0;                       ///< wall time before a restart, s
  double output_s_ = 0;                          ///< wall time spent writing outputs (the part before a restart too), s
};

}  // namespace swarf

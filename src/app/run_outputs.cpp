// run_outputs.cpp: rows, frames and checkpoints at their times (see run_outputs.h).
#include "app/run_outputs.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "app/observers/observer_set.h"
#include "app/paraview_script.h"
#include "app/run_directory.h"
#include "io/atomic_file.h"
#include "io/console.h"
#include "io/h5file.h"
#include "io/vtk_output.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/measure/particle_fields.h"
#include "swarf/simulation.h"

namespace swarf {

namespace {

// The fields the frames hold: output.fields, without the temperature when the run has no heat.
std::vector<std::string> frame_fields(const Model& model) {
  std::vector<std::string> f = model.settings.output.fields;
  if (!model.heat.enabled) std::erase(f, std::string("temperature"));
  return f;
}

// Its files in the run directory (files() declares them; VtkSeries names the ParaView series).
constexpr const char* kSeries = "series.csv";
constexpr const char* kColumnTable = "series_columns.csv";
constexpr const char* kCheckpoint = "checkpoint.h5";
constexpr const char* kFieldHistory = "results.xdmf";

}  // namespace

std::vector<RunFile> RunOutputs::files() {
  using K = RunFile::Keep;
  return {{kSeries},
          {kColumnTable},
          {kFieldHistory},
          {kCheckpoint, K::on_restart},
          {"particles.pvd", K::on_restart},
          {"frames", K::on_restart}};
}

RunOutputs::RunOutputs(const std::string& dir, const Model& model, Simulation& sim, ObserverSet& observers,
                       CheckpointCase stored)
    : dir_(dir),
      model_(model),
      sim_(sim),
      observers_(observers),
      stored_(std::move(stored)),
      columns_(observers.columns()),
      series_interval_(model.settings.output.series_interval > 0 ? model.settings.output.series_interval
                                                                 : model.settings.integrator.end_time / 2000),
      frame_interval_(model.settings.output.frame_interval),
      checkpoint_every_(model.settings.output.checkpoint_every),
      checkpoint_at_end_(model.settings.output.checkpoint_at_end),
      vtk_(model.settings.output.vtk
               ? std::make_unique<VtkSeries>(dir, model.settings.output.rods_in_vtk, model.settings.output.orientations,
                                             frame_fields(model))
               : nullptr),
      series_(dir + "/" + kSeries, columns_) {
  if (vtk_) {
    vtk_->set_periodic(model.periodic);
    if (const std::string why = write_paraview_script(dir, model); !why.empty())
      eprint("swarf: warning: {}/open_in_paraview.py not written: {}\n", dir, why);
  }
  rec_.columns = columns_.size();
  write_column_table(dir + "/" + kColumnTable, observers.column_specs());
}

void write_column_table(const std::string& path, const std::vector<Column>& columns) {
  // (CSV quoting: a meaning may hold commas; quotes are doubled)
  auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  std::string text = "column,unit,meaning\n";
  for (const auto& c : columns) text += c.name + "," + quoted(c.unit) + "," + quoted(c.meaning) + "\n";
  write_text_atomic(path, text);
}

void write_series_datasets(H5File& f, const std::vector<Column>& columns, const SeriesColumns& series) {
  for (const auto& c : columns) {
    const std::vector<double> v = series[c.name];
    f.write("/series/" + c.name, v.data(), v.size());
    f.describe("/series/" + c.name, c.unit, c.meaning);
  }
}

RunOutputs::~RunOutputs() = default;

double RunOutputs::seconds_since(std::chrono::steady_clock::time_point t) const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void RunOutputs::write_frame(double t) {
  if (!needs_particle_fields(model_.settings.output.fields)) {  // (none chosen: not computed)
    vtk_->write_frame(t, model_.particles, model_.rods, model_.meshes, nullptr);
    return;
  }
  const ParticleFields fields = particle_fields(model_.particles, model_.rods, model_.periodic, &sim_.contacts());
  vtk_->write_frame(t, model_.particles, model_.rods, model_.meshes, &fields);
}

void RunOutputs::write_row() {
  const std::vector<double> row = observers_.row();
  series_.row(row);
  rec_.rows.insert(rec_.rows.end(), row.begin(), row.end());
}

void RunOutputs::begin() {
  observers_.begin();
  write_row();
  if (vtk_) write_frame(0.0);
  rec_.next_row = series_interval_;
  rec_.next_frame = frame_interval_ > 0 ? frame_interval_ : HUGE_VAL;
  start_ = std::chrono::steady_clock::now();
}

void RunOutputs::restore(const std::string& checkpoint) {
  read_checkpoint(checkpoint, sim_, rec_, [&](StateArchive& ar) {
    if (rec_.columns != columns_.size())
      throw InputError(fmt::format("--restart {}: the checkpoint's series has {} columns, this case {}", checkpoint,
                                   rec_.columns, columns_.size()));
    observers_.visit_state(ar);
  });
  for (std::size_t r = 0; r * rec_.columns < rec_.rows.size(); ++r)
    series_.row(std::vector<double>(rec_.rows.begin() + r * rec_.columns, rec_.rows.begin() + (r + 1) * rec_.columns));
  if (vtk_) {
    vtk_->resume(rec_.frame_times);
    carry_frames(std::filesystem::path(checkpoint).parent_path(), dir_, rec_.frame_times.size());
  }
  say("  restarted from {} at t = {:.6g} s, step {} ({} series rows, {} frames)\n", checkpoint, sim_.time(),
      sim_.steps(), rec_.rows.size() / rec_.columns, rec_.frame_times.size());
  wall_before_ = rec_.wall_s;
  output_s_ = rec_.output_s;
  start_ = std::chrono::steady_clock::now();
}

bool RunOutputs::due(double t, std::int64_t steps, bool last) const {
  return row_due(t, last) || frame_due(t, last) || checkpoint_due(steps, last);
}

void RunOutputs::after_step(bool last) {
  const double t = sim_.time();
  const bool row = row_due(t, last);
  const bool frame = frame_due(t, last);
  const bool checkpoint = checkpoint_due(sim_.steps(), last);
  if (!row && !frame && !checkpoint) return;
  const auto o0 = std::chrono::steady_clock::now();
  if (row) write_row();
  if (frame) write_frame(t);
  while (rec_.next_row <= t * (1.0 + 1e-12)) rec_.next_row += series_interval_;
  while (rec_.next_frame <= t * (1.0 + 1e-12)) rec_.next_frame += frame_interval_;
  if (checkpoint) write_checkpoint_now();
  output_s_ += seconds_since(o0);
}

void RunOutputs::write_checkpoint_now() {
  if (vtk_) rec_.frame_times = vtk_->times();
  rec_.wall_s = wall_before_ + seconds_since(start_);
  rec_.output_s = output_s_;
  write_checkpoint(dir_ + "/" + kCheckpoint, sim_, rec_, stored_, [&](StateArchive& ar) { observers_.visit_state(ar); });
}

void RunOutputs::write_field_history(H5File& f) {
  if (!vtk_) return;
  history_ = swarf::write_field_history(f, dir_, vtk_->times());
  if (history_.size() < vtk_->frames())
    eprint("swarf: warning: {} of the {} frames are missing from {}/frames and from the field history\n",
           vtk_->frames() - history_.size(), vtk_->frames(), dir_);
}

void RunOutputs::write_field_history_sidecar(const std::string& results) {
  if (vtk_) write_text_atomic(dir_ + "/" + kFieldHistory, field_history_xdmf(history_, results));
}

RunOutputs::WallTimes RunOutputs::finish() {
  const WallTimes w{wall_before_ + seconds_since(start_), output_s_};
  series_.finish();
  return w;
}

}  // namespace swarf

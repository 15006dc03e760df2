// output.h: the outputs' module of setup: [output]'s settings, key table, rules (the output
// schedule) and build into the step's settings (what the chosen fields need the run to keep).
// The per-particle fields output.fields chooses from are the table io/output_fields.h. Listed
// once in each central list: parse_case (case_config.cpp), the key rows (case_key_text.cpp), the
// case echo (app/case_echo.cpp) and build_model (model.cpp).
#pragma once

#include <string>
#include <vector>

#include "io/output_fields.h"
#include "setup/key.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct StepSettings;

/// [output]
struct OutputSettings {
  double frame_interval = 0.0;   ///< ParaView frame interval, s; 0 = first and last state only
  double series_interval = 0.0;  ///< series.csv row interval, s; 0 = end_time/2000
  bool vtk = true;               ///< write the ParaView series
  bool rods_in_vtk = true;       ///< include the rods as lines in each frame
  bool plots = true;             ///< write PNG plots at the end (needs python3-matplotlib)
  bool progress = true;          ///< progress line on stderr
  double steady_from = -1.0;     ///< cutting: force statistics over rows with time >= this, s; < 0 = half the end time
  int checkpoint_every = 0;      ///< write DIR/checkpoint.h5 every this many steps; 0 = never
  bool checkpoint_at_end = false;  ///< also write DIR/checkpoint.h5 after the last step (to extend the run)
  bool orientations = false;       ///< integrate the spheres' orientations and write them and the angular velocities
  /// per-particle fields written (frames, results.h5): names of the table's rows (io/output_fields.h)
  std::vector<std::string> fields = output_field_names();
};

const std::vector<Key<OutputSettings>>& output_keys();

/// Reads [output] (absent: the defaults).
void read_output(const CaseInput& in, CaseSettings& cs);

/// The run's end and its output intervals: each a finite positive time, and no more rows or
/// frames than a run can write. Throws InputError.
void check_output_schedule(const CaseSettings& cs);

/// What the outputs need of the step: the spheres' orientations integrated, PEEQ accumulated
/// (only when a chosen field needs it: otherwise it costs nothing).
void build_output(const CaseSettings& cs, StepSettings& s);

}  // namespace swarf

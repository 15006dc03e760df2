// checkpoint.h: restart files. A checkpoint (HDF5) holds the case as it was read (TOML after
// overrides), the whole state of the step under /sim/ (particles, rods with their plastic
// state and trial values, contact lists with their friction histories, meshes, step control,
// energy ledger, counters: Simulation::visit_state) and the run's own state under /run/: the
// loop's record under /run/loop/ and whatever the caller's visit adds (the app's observers,
// each under /run/<observer>/), so that a run continued from it is bit-identical to one that
// was never interrupted. Every field is a named dataset, saved and loaded by one visit. It is
// written to NAME.part and renamed: a kill at any moment leaves the previous checkpoint intact.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace swarf {

class Simulation;
class StateArchive;

/// What the run loop itself needs to go on: the series so far and the output schedule.
struct RunRecord {
  std::size_t columns = 0;              ///< series.csv columns
  std::vector<double> rows;             ///< series rows so far, row-major
  double next_row = 0, next_frame = 0;  ///< next output times, s
  std::vector<double> frame_times;      ///< ParaView frames written, s
  double wall_s = 0, output_s = 0;      ///< wall time spent so far (all, outputs), s
};

/// The rest of the run's state: a visit of named fields (as Simulation::visit_state) through
/// an archive rooted at /run/; names are the caller's ("uniaxial/stress_predicted_Pa"), except
/// "loop/", the record's own.
using RunStateVisit = std::function<void(StateArchive&)>;

/// The case stored in a checkpoint.
struct CheckpointCase {
  std::string toml;       ///< effective TOML (after overrides)
  std::string source;     ///< the case file's name
  std::string directory;  ///< where its relative paths resolve
  std::vector<std::string> overrides;
  double time = 0;  ///< simulated time of the checkpoint, s
  double steps = 0;
};

/// Writes the checkpoint atomically (path.part, then rename).
void write_checkpoint(const std::string& path, const Simulation& sim, const RunRecord& rec, const CheckpointCase& c,
                      const RunStateVisit& run_state);
/// Reads the case of a checkpoint (to rebuild the model). Throws InputError.
CheckpointCase read_checkpoint_case(const std::string& path);
/// Restores the state, the record and then the rest of the run's state (run_state, which may
/// check the record first) into a simulation built from that case. Throws InputError naming
/// the dataset that is missing or has another shape.
void read_checkpoint(const std::string& path, Simulation& sim, RunRecord& rec, const RunStateVisit& run_state);

}  // namespace swarf

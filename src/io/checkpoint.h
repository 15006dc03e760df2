// checkpoint.h: restart files. A checkpoint (HDF5) holds the case as it was read (TOML after
// overrides), the whole state of the step (particles, rods with their plastic state and
// trial values, contact lists with their friction histories, meshes, step control, energy
// ledger, counters) and the run loop's record (series rows so far, output schedule, frame
// times, loop samples), so that a run continued from it is bit-identical to one that was
// never interrupted. It is written to NAME.part and renamed: a kill at any moment leaves the
// previous checkpoint intact.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace swarf {

class Simulation;
class H5File;

/// What the run loop has accumulated besides the simulation state.
struct RunRecord {
  std::size_t columns = 0;          ///< series.csv columns
  std::vector<double> rows;         ///< series rows so far, row-major
  double e0 = 0;                    ///< initial kinetic + elastic + potential energy, J
  double next_row = 0, next_frame = 0;  ///< next output times, s
  double predicted = 0;             ///< uniaxial: rod-law prediction of the last row, Pa
  double bar_shift = 0;             ///< uniaxial: the prediction's plastic shift, 1
  double bar_broken = 0;            ///< uniaxial: 1 if the prediction broke
  std::vector<double> s_strain, s_stress, s_segment;  ///< uniaxial loop samples
  double max_stress = 0, max_mismatch = 0;             ///< uniaxial quasi-static check, Pa
  std::vector<double> frame_times;  ///< ParaView frames written, s
  double wall_s = 0, output_s = 0;  ///< wall time spent so far (all, outputs), s
  std::int64_t last_checkpoint_step = 0;
};

/// The case stored in a checkpoint.
struct CheckpointCase {
  std::string toml;        ///< effective TOML (after overrides)
  std::string source;      ///< the case file's name
  std::string directory;   ///< where its relative paths resolve
  std::vector<std::string> overrides;
  double time = 0;         ///< simulated time of the checkpoint, s
  double steps = 0;
};

/// Writes the checkpoint atomically (path.part, then rename).
void write_checkpoint(const std::string& path, const Simulation& sim, const RunRecord& rec,
                      const CheckpointCase& c);
/// Reads the case of a checkpoint (to rebuild the model). Throws InputError.
CheckpointCase read_checkpoint_case(const std::string& path);
/// Restores the state and the record into a simulation built from that case.
void read_checkpoint(const std::string& path, Simulation& sim, RunRecord& rec);

}  // namespace swarf

// motion.h: the prescribed motion's part of setup: the keys that [[group]] and [[mesh]] share (not a
// table of their own), their settings, rules and build into the engine's Motion. The groups' and the
// meshes' modules read them (groups.h, meshes.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "setup/key.h"
#include "swarf/state/motion.h"

namespace swarf {

class TableReader;

/// The prescribed translation of a group or a mesh (keys shared by [[group]] and [[mesh]]).
struct MotionSettings {
  std::string kind = "fixed";               ///< key 'motion': "fixed", "velocity", "ramp", "table" or "velocity_table"
  std::array<double, 3> velocity{0, 0, 0};  ///< m/s ("velocity"; the final velocity of "ramp")
  double ramp_time = 0.0;                   ///< s: "ramp" reaches 'velocity' linearly in this time
  std::vector<double> table_time;           ///< s, ascending, first 0 ("table", "velocity_table")
  std::vector<std::array<double, 3>> table_displacement;  ///< m, piecewise linear in time ("table")
  std::vector<std::array<double, 3>> table_velocity;      ///< m/s, piecewise linear in time ("velocity_table")
  std::string velocity_file;  ///< CSV 'time,vx,vy,vz' (s, m/s) for "velocity_table" instead of the arrays
};

/// The motion keys, read by [[group]] and [[mesh]] after their own.
const std::vector<Key<MotionSettings>>& motion_keys();

/// The motion keys' rules (each key only where the motion uses it; tables and a velocity file
/// relative to 'directory').
void check_motion(const TableReader& r, const std::string& directory, MotionSettings& m);

/// The engine's Motion of the settings.
Motion motion_from(const MotionSettings& ms);

}  // namespace swarf

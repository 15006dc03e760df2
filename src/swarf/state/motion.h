// motion.h: prescribed motions as data, and the groups of particles that follow them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "swarf/core/vec3.h"

namespace swarf {

/// Prescribed rigid translation of a group or mesh: fixed, constant velocity, a linear ramp
/// up to a velocity, a piecewise-linear displacement table (constant past its end) or a
/// piecewise-linear velocity table (integrated exactly; the last velocity holds past its end).
struct Motion {
  enum class Kind { Fixed, Velocity, Ramp, Table, VelocityTable };
  Kind kind = Kind::Fixed;
  Vec3 velocity = Vec3::Zero();      ///< m/s (Velocity; final velocity of Ramp)
  double ramp_time = 0;              ///< s (Ramp)
  std::vector<double> time;          ///< s (Table, VelocityTable)
  std::vector<Vec3> displacement;    ///< m at each time (Table; for VelocityTable the integral at each time)
  std::vector<Vec3> table_velocity;  ///< m/s at each time (VelocityTable, piecewise linear)

  /// Displacement from the start position at time t, m.
  Vec3 displacement_at(double t) const;
};

struct Group {
  std::string name;
  std::uint8_t dofs = 7;  ///< prescribed components, bit c = component c
  Motion motion;
  std::vector<std::int32_t> members;  ///< particle indices, ascending
};

}  // namespace swarf

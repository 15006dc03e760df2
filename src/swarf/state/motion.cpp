// motion.cpp: prescribed rigid translations (see motion.h).
#include "swarf/state/motion.h"

#include <algorithm>

namespace swarf {

Vec3 Motion::displacement_at(double t) const {
  switch (kind) {
    case Kind::Fixed:
      return Vec3::Zero();
    case Kind::Velocity:
      return velocity * t;
    case Kind::Ramp:
      return t < ramp_time ? Vec3(velocity * (0.5 * t * t / ramp_time)) : Vec3(velocity * (t - 0.5 * ramp_time));
    case Kind::VelocityTable: {
      if (t <= 0.0) return Vec3::Zero();
      if (t >= time.back()) return displacement.back() + table_velocity.back() * (t - time.back());
      const auto it = std::upper_bound(time.begin(), time.end(), t);
      const std::size_t k = static_cast<std::size_t>(it - time.begin()) - 1;
      const double s = t - time[k], span = time[k + 1] - time[k];
      const Vec3 slope = (table_velocity[k + 1] - table_velocity[k]) / span;
      return displacement[k] + table_velocity[k] * s + slope * (0.5 * s * s);
    }
    case Kind::Table: {
      if (t <= time.front()) return displacement.front();
      if (t >= time.back()) return displacement.back();
      const auto it = std::upper_bound(time.begin(), time.end(), t);
      const std::size_t k = static_cast<std::size_t>(it - time.begin());
      const double s = (t - time[k - 1]) / (time[k] - time[k - 1]);
      return displacement[k - 1] + s * (displacement[k] - displacement[k - 1]);
    }
  }
  return Vec3::Zero();
}

}  // namespace swarf

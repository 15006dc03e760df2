// lagged_rate.h: a rod's axial strain rate at Newton's step start, the rate at which its
// Johnson-Cook rate factor is held through the solve (integrate/newton.cpp). One definition for
// the kernel that evaluates the rods with it (rod_forces.cpp) and the tangent that must match
// that evaluation (rod_tangent.cpp).
#pragma once

#include <cstddef>

#include "swarf/core/periodic.h"
#include "swarf/core/vec3.h"

namespace swarf {

/// (dx . dv) / |dx| / L0 of the rod from end i to end j at the positions x and velocities v
/// (m, m/s), 1/s; 0 for a rod of zero length.
template <bool Wrap = true>
inline double lagged_rate(const Vec3* x, const Vec3* v, std::size_t i, std::size_t j, double inv_rest_length,
                          const Periodic& periodic) {
  Vec3 dx = x[j] - x[i];
  if constexpr (Wrap) periodic.wrap(dx);
  const double l = dx.norm();
  return l > 0.0 ? dx.dot(v[j] - v[i]) / l * inv_rest_length : 0.0;
}

}  // namespace swarf

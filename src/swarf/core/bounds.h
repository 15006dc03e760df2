// bounds.h: finiteness and range of coordinates that come from input files, tested without
// raising a floating-point exception (the tests and the fuzzers trap them, app/fp_traps.h).
#pragma once

#include <cmath>

#include "swarf/core/vec3.h"

namespace swarf {

/// Whether every component is finite, by classification only. Eigen's allFinite() computes
/// x - x == 0, which raises FE_INVALID on an infinity: with the traps on, the check that was
/// to refuse an infinite vertex trapped on it (found by the STL fuzzer).
inline bool all_finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

/// The largest coordinate a mesh or a lattice file may give, m: farther is a unit or scale
/// mistake, and the squares of such lengths (areas, distances) overflow.
inline constexpr double kMaxMeshCoordinate = 1e6;
/// A particle radius, m (workpiece.radius and the radii of a lattice file): beyond these the
/// derived step, the masses and the pair search overflow or divide by zero.
inline constexpr double kMinRadius = 1e-9, kMaxRadius = 1.0;

}  // namespace swarf

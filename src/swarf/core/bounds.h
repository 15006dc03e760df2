// bounds.h: finiteness and range of coordinates that come from input files, tested without
// raising a floating-point exception (the tests and the fuzzers trap them, app/fp_traps.h).
#pragma once

#include <bit>
#include <cstdint>

#include "swarf/core/vec3.h"

namespace swarf {

/// Whether x is finite, from its bits alone: no floating-point operation, so that neither an
/// infinity nor a signalling NaN (a binary STL or an HDF5 file can hold one) raises an
/// exception in the check that is to refuse it (std::isfinite may compile to a comparison,
/// which signals on a signalling NaN; the STL fuzzer found one).
inline bool finite_bits(double x) {
  return (std::bit_cast<std::uint64_t>(x) & 0x7ff0000000000000ull) != 0x7ff0000000000000ull;
}
inline bool finite_bits(float x) { return (std::bit_cast<std::uint32_t>(x) & 0x7f800000u) != 0x7f800000u; }

/// Whether every component is finite (finite_bits). Eigen's allFinite() computes x - x == 0,
/// which raises FE_INVALID on an infinity: with the traps on, the check that was to refuse an
/// infinite vertex trapped on it (found by the STL fuzzer).
inline bool all_finite(const Vec3& v) { return finite_bits(v[0]) && finite_bits(v[1]) && finite_bits(v[2]); }

/// The largest coordinate a mesh or a lattice file may give, m: farther is a unit or scale
/// mistake, and the squares of such lengths (areas, distances) overflow.
inline constexpr double kMaxMeshCoordinate = 1e6;
/// A particle radius, m (workpiece.radius and the radii of a lattice file): beyond these the
/// derived step, the masses and the pair search overflow or divide by zero.
inline constexpr double kMinRadius = 1e-9, kMaxRadius = 1.0;

}  // namespace swarf

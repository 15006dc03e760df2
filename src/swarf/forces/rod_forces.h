// rod_forces.h: the rod kernel, a free function over views of the rod and particle arrays.
//
// Every intact rod is evaluated from its COMMITTED state (plastic shift, intact flag): the law
// gives a trial shift, a trial break flag and the stress; the force is stored as one
// coefficient per rod (force on end i = coef (x_j - x_i)). Nothing committed changes here, so
// an implicit step may evaluate as often as it sweeps and commit once (integrate::commit).
//
// The law is a template parameter of the block loop (no virtual call per rod): a law is a
// value type with a pure evaluate(law, strain, rate, shift) -> RodResponse (laws/rod_law.h);
// the variant of laws (laws/any_rod_law.h) is visited once per call.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "swarf/core/periodic.h"
#include "swarf/core/vec3.h"
#include "swarf/laws/any_rod_law.h"

namespace swarf {

/// What the rod kernel reads and writes; pointers into the Rods and Particles arrays (and
/// the per-block sums), owned elsewhere.
struct RodKernelView {
  std::size_t rods = 0;
  const std::array<std::int32_t, 2>* ends = nullptr;
  const double* rest_length = nullptr;   ///< m
  const double* shift = nullptr;         ///< committed plastic shift, 1
  const std::uint8_t* intact = nullptr;  ///< committed
  const Vec3* x = nullptr;               ///< particle positions, m
  const Vec3* v = nullptr;               ///< particle velocities, m/s
  const double* temperature = nullptr;   ///< particle temperatures, K (0 = not set); nullptr: none (T_ref)
  double* trial_shift = nullptr;         ///< out, 1
  std::uint8_t* trial_broken = nullptr;  ///< out
  double* stress = nullptr;              ///< out, Pa
  double* coef = nullptr;                ///< out, N/m
  double* block_viscous = nullptr;       ///< out per block of kBlock rods: viscous power, W
  int* block_changed = nullptr;          ///< out per block: 1 if a rod yielded or broke
  double* rod_viscous = nullptr;         ///< out per rod when set: viscous power, W (0 for a broken rod)
  /// Positions and velocities from which a law that scales its flow stresses by the rate
  /// (Johnson-Cook) takes the rate of its factor, m and m/s; nullptr: x and v (the trial's own
  /// rate). The Newton solve passes the step's start: a lagged rate factor, so that the trial's
  /// residual is smooth in the iterate (integrate/newton.cpp). The viscous stress reads x and v.
  const Vec3* rate_x = nullptr;
  const Vec3* rate_v = nullptr;
};

/// Evaluates every intact rod of cross-section 'area' (m^2) with 'law', in parallel over
/// fixed blocks of rods (the same results for any thread count).
void evaluate_rods(const AnyRodLaw& law, double area, const RodKernelView& view, Periodic periodic);

}  // namespace swarf

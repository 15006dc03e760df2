// rods.h: the bonds of the workpiece, each rod stored once.
//
// Per rod: its two particles, rest length, the COMMITTED plastic shift and intact flag,
// plus the trial values and the force of the last evaluation. The force on particle i is
// gathered in a fixed order from a per-particle list of its rods (compressed rows built
// once), so that the sum does not depend on the number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rod_law.h"
#include "vec3.h"

namespace swarf {

struct Rods {
  RodLaw law;                  ///< one rod family: the law's parameters
  double area = 0.0;           ///< cross-section A of every rod, m^2

  std::vector<std::array<std::int32_t, 2>> ends;  ///< particle indices (i, j), i < j
  std::vector<double> rest_length;                ///< L0, m
  std::vector<double> shift;                      ///< committed plastic shift eps0, 1
  std::vector<std::uint8_t> intact;               ///< committed: 1 intact, 0 broken for good

  // Results of the last evaluation (trial state, not committed).
  std::vector<double> trial_shift;      ///< 1
  std::vector<std::uint8_t> trial_broken;  ///< 1 if this evaluation broke the rod
  std::vector<double> stress;           ///< elastic-plastic stress, Pa
  std::vector<Vec3> force;              ///< force on end i (end j gets the opposite), N

  // Per-particle rod lists (compressed rows): entries are 2*rod + side (side 0: particle is
  // end i, side 1: end j), in ascending rod order.
  std::vector<std::int32_t> row_start;  ///< size particles + 1
  std::vector<std::int32_t> entries;

  std::size_t size() const { return ends.size(); }

  /// Sets the committed state to virgin (no shift, all intact) and sizes the scratch arrays.
  void reset_state();
  /// Builds the per-particle rod lists for n particles.
  void build_rows(std::size_t n_particles);
  /// Number of rods broken for good.
  std::size_t broken_count() const;
};

}  // namespace swarf

// lattice_disorder.h: a seeded jitter of a generated lattice's positions (workpiece.disorder_seed),
// so that repetitions of a case differ by their disorder only.
//
// Particle i moves by amplitude x R_i x u_i, with u_i drawn uniformly from the unit ball. u_i is
// a function of (seed, i) alone: a counter-based hash (SplitMix64's mixing function of seed, i
// and a draw number) feeds a rejection from the cube [-1, 1)^3, so a particle's displacement does
// not depend on the thread count, on the order in which particles are visited, or on the others.
// Lattice particle i is particle id i (the workpiece comes first, ids 0, 1, ... in site order).
//  - Not std::uniform_real_distribution: its algorithm is the standard library's choice, and
//    the same seed would give other positions with another library. The hash and the
//    rejection use integer arithmetic and exact scalings only: the same bits everywhere.
//  - A ball rather than a cube: isotropic, and |displacement| <= amplitude x R exactly.
// The rods stay those of the ordered lattice (the FCC topology: a generated site keeps its 12
// neighbours; no distance search after the jitter), and each rest length becomes the distance
// between the moved ends, so the block starts stress-free.
#pragma once

#include <cstddef>
#include <cstdint>

#include "lattice_gen/fcc_lattice.h"
#include "swarf/core/periodic.h"
#include "swarf/core/vec3.h"

namespace swarf {

/// The largest amplitude (in radii) that keeps every rod shorter than every unbonded pair:
/// rods of 2R end up at most 2R (1 + A) long, second neighbours (a = 2 sqrt(2) R) at least
/// 2 sqrt(2) R - 2 A R apart; the two meet at A = (sqrt(2) - 1)/2 = 0.207.
inline constexpr double kMaxPositionJitter = 0.2;

/// u(seed, id): a point of the closed unit ball, uniformly distributed, the same bits for the
/// same (seed, id) on every machine.
Vec3 unit_ball_jitter(std::uint64_t seed, std::uint64_t id);

/// Moves the first 'count' particles of 'lattice' by amplitude x radius[i] x u(seed, i) and sets
/// every rest length to the distance between the moved ends (through the nearest image along
/// the periodic direction, as the rod kernel measures it). Nothing changes when seed or
/// amplitude is 0. Throws InputError for an amplitude outside [0, kMaxPositionJitter].
void jitter_lattice(Lattice& lattice, std::uint64_t seed, double amplitude, std::size_t count, const Periodic& periodic);

}  // namespace swarf

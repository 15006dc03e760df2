// neighbor_pairs.h: all pairs of points whose distance lies in a range, by a cell grid.
//
// Used to bond a lattice (nearest neighbours at 2R within a relative tolerance). Cost is
// linear in the number of points for a bounded density; the output is sorted (i < j,
// ascending), so it does not depend on the traversal order.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "swarf/core/vec3.h"

namespace swarf {

std::vector<std::array<std::int32_t, 2>> find_pairs_in_range(const std::vector<Vec3>& points, double min_distance,
                                                             double max_distance);

/// Two points (i < j) closer than 'tolerance' (m; 0: at exactly the same place), or {-1, -1}.
/// Two particles there have no contact normal: 0/0 at one place, and a distance whose square
/// underflows (1e-170 m) divides by zero too. A lattice file, the free particles or a checkpoint
/// that puts them so is refused (found by the lattice-file fuzzer, twice).
std::array<std::int32_t, 2> find_coincident(const std::vector<Vec3>& points, double tolerance = 0.0);

}  // namespace swarf

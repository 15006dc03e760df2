// partition.h: which rank owns a point: slabs along x (the cut direction), one per rank.
//
// Rank k owns [cut[k-1], cut[k]) (the first and last slabs open). The cuts are either given or
// balanced: each slab about the same total weight (a particle's weight: 1 + its intact rods,
// the work of its gather), found from a histogram of the ranks' particles along x whose integer
// weights are summed exactly, so that every rank finds the same cuts, for any split of the
// particles over the ranks. Slabs are the simplest partition that follows the work as a cut
// moves along x; a recursive coordinate bisection (Zoltan's RCB) can replace it behind owner()
// when the 3D cut needs blocks (issue 38). Ownership never changes the bits (domain_run.h): it
// only decides where the work is done.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "swarf/core/comm.h"
#include "swarf/core/vec3.h"

namespace swarf {

class SlabPartition {
 public:
  /// One slab: everything is rank 0's.
  SlabPartition() = default;
  /// Slabs between the ascending 'cuts' (m): cuts.size() + 1 ranks. Throws InputError if not ascending.
  explicit SlabPartition(std::vector<double> cuts);

  /// Collective: the cuts that balance the weights 'w' of this rank's particles at x-coordinates
  /// 'x' (m) with those of the other ranks, in comm.size() slabs, to the width of one of
  /// bins_per_rank * size bins of the particles' extent along x.
  static SlabPartition balanced(Comm& comm, const std::vector<double>& x, const std::vector<std::int64_t>& w,
                                int bins_per_rank = 64);

  int ranks() const { return static_cast<int>(cuts_.size()) + 1; }
  int owner(const Vec3& x) const {
    return static_cast<int>(std::upper_bound(cuts_.begin(), cuts_.end(), x[0]) - cuts_.begin());
  }
  /// True if x lies in rank's slab widened by 'skin' (m) on each side.
  bool near(const Vec3& x, int rank, double skin) const {
    return (rank == 0 || x[0] >= cuts_[rank - 1] - skin) && (rank == ranks() - 1 || x[0] < cuts_[rank] + skin);
  }
  const std::vector<double>& cuts() const { return cuts_; }

 private:
  std::vector<double> cuts_;  // m, ascending
};

}  // namespace swarf

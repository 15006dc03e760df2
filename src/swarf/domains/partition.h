// partition.h: which rank owns a point: one axis-aligned box per rank.
//
// Rank k owns the half-open box [lo, hi) of boxes()[k] (the outer faces at +-inf), the boxes
// tiling space. Two ways to make them:
// - slabs along x (the cut direction), balanced: each slab about the same total weight (a
//   particle's weight: 1 + its intact rods, the work of its gather), found from a histogram of
//   the ranks' particles along x whose integer weights are summed exactly, so that every rank
//   finds the same cuts, for any split of the particles over the ranks. Slabs follow the work
//   as a cut moves along x, but a slab thins as the ranks grow (a 2 mm cut on 64 ranks is two
//   particles thick per slab: all ghosts);
// - boxes of a recursive coordinate bisection from a Partitioner (Zoltan's RCB under MPI,
//   study/zoltan_rcb.h): a box's surface, and so its halo, shrinks with the ranks as N^(2/3)/P^(2/3)
//   instead of staying a whole cross-section.
// Ownership never changes the bits (domain_run.h): it only decides where the work is done, so a
// partitioner need not be deterministic, only the same boxes on every rank.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "swarf/core/comm.h"
#include "swarf/core/vec3.h"

namespace swarf {

/// One rank's region, [lo, hi) along each axis, m (+-inf for an open side; all of space by default).
struct DomainBox {
  Vec3 lo = Vec3::Constant(-HUGE_VAL), hi = Vec3::Constant(HUGE_VAL);
  bool contains(const Vec3& x) const {
    return x[0] >= lo[0] && x[0] < hi[0] && x[1] >= lo[1] && x[1] < hi[1] && x[2] >= lo[2] && x[2] < hi[2];
  }
  /// True if x lies in the box widened by 'skin' (m) on every side.
  bool near(const Vec3& x, double skin) const {
    for (int a = 0; a < 3; ++a)
      if (!(x[a] >= lo[a] - skin && x[a] < hi[a] + skin)) return false;
    return true;
  }
};

class Partition {
 public:
  /// One rank: all of space.
  Partition();
  /// Slabs between the ascending 'cuts' along x (m): cuts.size() + 1 ranks. Throws InputError if
  /// not ascending or not finite.
  static Partition slabs(std::vector<double> cuts);
  /// Given boxes, one per rank (a Partitioner's). Throws InputError for a box with lo > hi or a
  /// NaN bound.
  explicit Partition(std::vector<DomainBox> boxes);

  /// Collective: the slabs that balance the weights 'w' of this rank's particles at x-coordinates
  /// 'x' (m) with those of the other ranks, in comm.size() slabs, to the width of one of
  /// bins_per_rank * size bins of the particles' extent along x.
  static Partition balanced_slabs(Comm& comm, const std::vector<double>& x, const std::vector<std::int64_t>& w,
                                  int bins_per_rank = 64);

  int ranks() const { return static_cast<int>(boxes_.size()); }
  /// The rank whose box holds x, by the cut tree in O(log ranks) (a NaN ends in some box: the
  /// step that follows stops on it).
  int owner(const Vec3& x) const {
    if (slabs_) return static_cast<int>(std::upper_bound(cuts_.begin(), cuts_.end(), x[0]) - cuts_.begin());
    if (tree_.empty()) return scan_owner(x);
    int node = 0;
    while (node >= 0) node = x[tree_[node].axis] < tree_[node].cut ? tree_[node].below : tree_[node].above;
    return -node - 1;
  }
  /// True if x lies in rank's box widened by 'skin' (m) on each side.
  bool near(const Vec3& x, int rank, double skin) const { return boxes_[rank].near(x, skin); }
  /// Every rank whose box widened by 'skin' (m) holds x, ascending, into 'out' (cleared): the
  /// cut tree visits only the boxes within reach, not every rank's.
  void near_ranks(const Vec3& x, double skin, std::vector<int>& out) const;
  const std::vector<DomainBox>& boxes() const { return boxes_; }
  /// "slabs" or "boxes", for the run's report.
  std::string kind() const { return slabs_ ? "slabs" : "boxes"; }

 private:
  // The cut tree of the boxes (a recursive bisection's, slabs too: every inner node splits its
  // boxes by one plane); a child index < 0 is the leaf of rank -index - 1. Empty for one box or
  // boxes that no sequence of planes separates (then owner and near_ranks scan the boxes).
  struct Node {
    int axis;
    double cut;  // m: x[axis] < cut goes below
    int below, above;
  };
  void build_index();                      // tree_ from boxes_
  int build_tree(std::vector<int> ranks);  // the node (or leaf) index of the ranks' subtree; -0x7fffffff: none
  int scan_owner(const Vec3& x) const;
  std::vector<DomainBox> boxes_;
  bool slabs_ = true;
  std::vector<double> cuts_;  // m, ascending (slabs)
  std::vector<Node> tree_;
};

/// Makes the boxes of a run's ranks from where the work is (issue 38 asks for a well-kept
/// partitioner: study/zoltan_rcb.h wraps Zoltan's recursive coordinate bisection). The domains
/// cut balanced slabs without one.
class Partitioner {
 public:
  virtual ~Partitioner() = default;
  /// Collective: one box per rank that together tile space and balance the weights 'w' of this
  /// rank's points 'x' (m) with the other ranks'. A periodic y (cut_y false) is never cut: every
  /// box spans it whole, so that no spatial ghost needs its periodic image.
  virtual std::vector<DomainBox> partition(const std::vector<Vec3>& x, const std::vector<std::int64_t>& w,
                                           bool cut_y) = 0;
  /// The method's name for the run's report ("Zoltan RCB").
  virtual std::string name() const = 0;
};

}  // namespace swarf

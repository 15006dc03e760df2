// partition.cpp: the slabs and boxes of the ranks (see partition.h).
#include "swarf/domains/partition.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "swarf/core/errors.h"

namespace swarf {

namespace {
constexpr int kNoTree = -0x7fffffff;  // (build_tree: the boxes have no separating plane)
}  // namespace

Partition::Partition() : boxes_{DomainBox{}} {}

Partition Partition::slabs(std::vector<double> cuts) {
  for (std::size_t k = 0; k < cuts.size(); ++k)
    if (!std::isfinite(cuts[k]) || (k > 0 && cuts[k] < cuts[k - 1]))
      throw InputError("the domains' cut planes along x must be finite and ascending (cut " + std::to_string(k) +
                       " is " + std::to_string(cuts[k]) + " m)");
  Partition p;
  p.boxes_.assign(cuts.size() + 1, DomainBox{});
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    p.boxes_[k].hi[0] = cuts[k];
    p.boxes_[k + 1].lo[0] = cuts[k];
  }
  p.cuts_ = std::move(cuts);
  p.build_index();
  return p;
}

Partition::Partition(std::vector<DomainBox> boxes) : boxes_(std::move(boxes)), slabs_(false) {
  if (boxes_.empty()) throw InputError("the domains' partition has no box");
  for (std::size_t k = 0; k < boxes_.size(); ++k)
    for (int a = 0; a < 3; ++a)
      if (!(boxes_[k].lo[a] <= boxes_[k].hi[a]))
        throw InputError("the domains' box " + std::to_string(k) + " has lower bound " +
                         std::to_string(boxes_[k].lo[a]) + " m above its upper bound " +
                         std::to_string(boxes_[k].hi[a]) + " m along axis " + std::to_string(a));
  if (boxes_.size() == 1) boxes_[0] = DomainBox{};  // (one rank owns everything, whatever it was given)
  build_index();
}

void Partition::build_index() {
  tree_.clear();
  if (boxes_.size() < 2) return;
  std::vector<int> all(boxes_.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  if (build_tree(std::move(all)) == kNoTree) tree_.clear();  // (not a bisection's boxes: scan)
}

int Partition::build_tree(std::vector<int> ranks) {
  if (ranks.size() == 1) return -ranks[0] - 1;
  // A plane that puts every box wholly on one side, both sides non-empty: a bisection's boxes
  // always have one (its first cut). Of those among the boxes' lower faces the most even split,
  // so that the tree is about log2 of the ranks deep (slabs too, whose first lower face would
  // make a chain); O(n^2) per axis, once per rebalance.
  int best_axis = -1;
  double best_cut = 0.0;
  std::size_t best_smaller = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const int r : ranks) {
      const double c = boxes_[r].lo[axis];
      if (!std::isfinite(c)) continue;
      std::size_t below = 0, above = 0;
      for (const int q : ranks) {
        if (boxes_[q].hi[axis] <= c)
          ++below;
        else if (boxes_[q].lo[axis] >= c)
          ++above;
        else
          break;
      }
      if (below == 0 || above == 0 || below + above != ranks.size()) continue;
      if (std::min(below, above) > best_smaller) best_axis = axis, best_cut = c, best_smaller = std::min(below, above);
    }
  if (best_axis < 0) return kNoTree;
  std::vector<int> below, above;
  for (const int q : ranks) (boxes_[q].hi[best_axis] <= best_cut ? below : above).push_back(q);
  const int node = static_cast<int>(tree_.size());
  tree_.push_back({best_axis, best_cut, 0, 0});
  const int b = build_tree(std::move(below));
  const int a = build_tree(std::move(above));
  if (b == kNoTree || a == kNoTree) return kNoTree;
  tree_[node].below = b;
  tree_[node].above = a;
  return node;
}

int Partition::scan_owner(const Vec3& x) const {
  for (std::size_t k = 0; k < boxes_.size(); ++k)
    if (boxes_[k].contains(x)) return static_cast<int>(k);
  return ranks() - 1;
}

void Partition::near_ranks(const Vec3& x, double skin, std::vector<int>& out) const {
  out.clear();
  if (tree_.empty()) {
    for (int k = 0; k < ranks(); ++k)
      if (boxes_[k].near(x, skin)) out.push_back(k);
    return;
  }
  // Down the tree: a subtree below a cut holds boxes whose faces along the axis end at or before
  // it, so x is within reach of one of them only if x < cut + skin (above: x >= cut - skin);
  // the leaves check their whole box.
  const auto visit = [&](const auto& self, int node) -> void {
    if (node < 0) {
      if (boxes_[-node - 1].near(x, skin)) out.push_back(-node - 1);
      return;
    }
    const Node& n = tree_[node];
    if (x[n.axis] < n.cut + skin) self(self, n.below);
    if (x[n.axis] >= n.cut - skin) self(self, n.above);
  };
  visit(visit, 0);
  std::sort(out.begin(), out.end());
}

Partition Partition::balanced_slabs(Comm& comm, const std::vector<double>& x, const std::vector<std::int64_t>& w,
                                    int bins_per_rank) {
  const int n = comm.size();
  if (n == 1) return Partition();
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (double v : x) lo = std::min(lo, v), hi = std::max(hi, v);
  lo = comm.min_all(lo);
  hi = comm.max_all(hi);
  const std::size_t bins = static_cast<std::size_t>(std::max(1, bins_per_rank)) * n;
  if (!(hi > lo) || !std::isfinite(hi - lo)) return slabs(std::vector<double>(n - 1, std::isfinite(lo) ? lo : 0.0));
  const double scale = static_cast<double>(bins) / (hi - lo);
  std::vector<std::int64_t> hist(bins, 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double b = std::floor((x[i] - lo) * scale);
    hist[static_cast<std::size_t>(std::clamp(b, 0.0, static_cast<double>(bins - 1)))] += w[i];
  }
  hist = comm.sum_all(hist);  // (exact: the same on every rank, whatever the split)
  std::int64_t total = 0;
  for (std::int64_t h : hist) total += h;
  // Cut k at the first bin edge with at least k/n of the weight below it.
  std::vector<double> cuts;
  std::int64_t below = 0;
  std::size_t edge = 0;
  for (int k = 1; k < n; ++k) {
    while (edge < bins && below * n < k * total) below += hist[edge++];
    cuts.push_back(lo + static_cast<double>(edge) * (hi - lo) / static_cast<double>(bins));
  }
  return slabs(std::move(cuts));
}

}  // namespace swarf

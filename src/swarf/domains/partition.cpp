// partition.cpp: the slabs and boxes of the ranks (see partition.h).
#include "swarf/domains/partition.h"

#include <cmath>
#include <string>

#include "swarf/core/errors.h"

namespace swarf {

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

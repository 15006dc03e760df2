// reindex.cpp: reordering and removal applied to particles, rods and groups (see reindex.h).
#include "swarf/state/reindex.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace swarf {

Reindex Reindex::permutation(const std::vector<std::int32_t>& order) {
  Reindex r;
  const std::size_t n = order.size();
  r.new_count = n;
  r.new_index.assign(n, kRemoved);
  for (std::size_t k = 0; k < n; ++k) {
    const std::int32_t old = order[k];
    if (old < 0 || std::size_t(old) >= n || r.new_index[old] != kRemoved)
      throw std::invalid_argument("a particle permutation must list every index 0..n-1 once");
    r.new_index[old] = static_cast<std::int32_t>(k);
  }
  return r;
}

Reindex Reindex::removal(const std::vector<std::uint8_t>& remove) {
  Reindex r;
  r.new_index.assign(remove.size(), kRemoved);
  for (std::size_t i = 0; i < remove.size(); ++i)
    if (!remove[i]) r.new_index[i] = static_cast<std::int32_t>(r.new_count++);
  return r;
}

void reindex(Particles& p, const Reindex& r) {
  p.for_each_field([&](const char*, auto& v) { reindex_array(v, r); });
}

std::size_t reindex(Rods& rods, const Reindex& r) {
  const std::size_t m = rods.size();
  std::vector<std::size_t> keep;
  keep.reserve(m);
  for (std::size_t k = 0; k < m; ++k)
    if (r.new_index[rods.ends[k][0]] != Reindex::kRemoved && r.new_index[rods.ends[k][1]] != Reindex::kRemoved)
      keep.push_back(k);
  // The force coefficient and the law's state do not depend on which end is 'i': the kernel
  // uses x_j - x_i for both the strain and the force, so swapping the ends changes no bit.
  std::vector<std::array<std::int32_t, 2>> ends(keep.size());
  for (std::size_t q = 0; q < keep.size(); ++q) {
    std::int32_t i = r.new_index[rods.ends[keep[q]][0]], j = r.new_index[rods.ends[keep[q]][1]];
    if (i > j) std::swap(i, j);
    ends[q] = {i, j};
  }
  rods.ends.swap(ends);
  rods.for_each_field([&](const char*, auto& v) {
    std::remove_reference_t<decltype(v)> out(keep.size());
    for (std::size_t q = 0; q < keep.size(); ++q) out[q] = v[keep[q]];
    v.swap(out);
  });
  rods.build_rows(r.new_count);
  return m - keep.size();
}

void reindex(std::vector<Group>& groups, const Reindex& r) {
  for (auto& g : groups) {
    std::vector<std::int32_t> members;
    members.reserve(g.members.size());
    for (std::int32_t i : g.members)
      if (r.new_index[i] != Reindex::kRemoved) members.push_back(r.new_index[i]);
    std::sort(members.begin(), members.end());
    g.members.swap(members);
  }
}

}  // namespace swarf

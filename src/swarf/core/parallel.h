// parallel.h: loops whose results do not depend on the number of threads.
//
// Work is cut into fixed-size blocks (independent of the thread count); a reduction sums
// each block serially and then the block sums serially in block order, so the rounding is
// the same for 1 or N threads. OpenMP static schedules hand out the blocks.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "swarf/core/exact_sum.h"

namespace swarf {

inline constexpr std::size_t kBlock = 2048;

inline std::size_t block_count(std::size_t n) { return (n + kBlock - 1) / kBlock; }

/// Sum over i in [0, n) of f(i), bit-identical for any thread count.
template <class F>
double deterministic_sum(std::size_t n, F&& f) {
  const std::size_t nb = block_count(n);
  std::vector<double> part(nb, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    double s = 0.0;
    const std::size_t end = std::min(n, (b + 1) * kBlock);
    for (std::size_t i = b * kBlock; i < end; ++i) s += f(i);
    part[b] = s;
  }
  double total = 0.0;
  for (double s : part) total += s;
  return total;
}

/// Sum of the terms that f(i, sum) adds through sum.add (any number per index) for i in [0, n),
/// exact before its one rounding (exact_sum.h). Blocks of 256 indices: an exact sum is the same
/// for any split, so short loops (a group's members, a step's rod runs) still share the threads.
template <class F>
ExactSum exact_sum_of(std::size_t n, F&& f) {
  constexpr std::size_t kExactBlock = 256;
  const std::size_t nb = (n + kExactBlock - 1) / kExactBlock;
  std::vector<ExactSum> part(nb);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t end = std::min(n, (b + 1) * kExactBlock);
    for (std::size_t i = b * kExactBlock; i < end; ++i) f(i, part[b]);
  }
  ExactSum total;
  for (const ExactSum& s : part) total.add(s);
  return total;
}

/// Sum over i in [0, n) of f(i), exact before its one rounding (exact_sum.h): the same bits for
/// any thread count and for any split of the terms over domains. A few ns per term: for sums that
/// are read (energies at the rows), not for the step's inner loops.
template <class F>
ExactSum exact_sum(std::size_t n, F&& f) {
  return exact_sum_of(n, [&](std::size_t i, ExactSum& s) {
    if (const double x = f(i); x != 0.0) s.add(x);
  });
}

}  // namespace swarf

// neighbor_pairs.cpp: cell-grid pair search (see neighbor_pairs.h).
#include "swarf/neighbors/neighbor_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"

namespace swarf {

std::vector<std::array<std::int32_t, 2>> find_pairs_in_range(const std::vector<Vec3>& points, double min_distance,
                                                             double max_distance) {
  std::vector<std::array<std::int32_t, 2>> pairs;
  if (points.size() < 2) return pairs;
  if (!(max_distance > 0.0)) throw InputError("pair search: the distance must be positive");
  Vec3 lo = points[0], hi = points[0];
  for (const auto& p : points) {
    if (!all_finite(p)) throw InputError("pair search: a position is not finite");
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double cell = max_distance;
  std::array<std::int64_t, 3> n{};
  for (int c = 0; c < 3; ++c) n[c] = std::max<std::int64_t>(1, static_cast<std::int64_t>((hi[c] - lo[c]) / cell) + 1);
  if (n[0] * n[1] * n[2] > std::int64_t{1} << 31) throw InputError("pair search: domain too large for the cell grid");
  auto cell_of = [&](const Vec3& p) {
    std::array<std::int64_t, 3> c{};
    for (int k = 0; k < 3; ++k) c[k] = std::min(n[k] - 1, static_cast<std::int64_t>((p[k] - lo[k]) / cell));
    return c;
  };
  auto linear = [&](const std::array<std::int64_t, 3>& c) { return (c[2] * n[1] + c[1]) * n[0] + c[0]; };
  // Counting sort of the points into cells.
  std::vector<std::int64_t> start(n[0] * n[1] * n[2] + 1, 0);
  std::vector<std::int64_t> cell_id(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    cell_id[i] = linear(cell_of(points[i]));
    ++start[cell_id[i] + 1];
  }
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::int32_t> sorted(points.size());
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i) sorted[fill[cell_id[i]]++] = static_cast<std::int32_t>(i);
  }
  const double min2 = min_distance * min_distance, max2 = max_distance * max_distance;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto c = cell_of(points[i]);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          std::array<std::int64_t, 3> o{c[0] + dx, c[1] + dy, c[2] + dz};
          if (o[0] < 0 || o[1] < 0 || o[2] < 0 || o[0] >= n[0] || o[1] >= n[1] || o[2] >= n[2]) continue;
          const auto l = linear(o);
          for (std::int64_t s = start[l]; s < start[l + 1]; ++s) {
            const std::int32_t j = sorted[s];
            if (j <= static_cast<std::int32_t>(i)) continue;
            const double d2 = (points[j] - points[i]).squaredNorm();
            if (d2 >= min2 && d2 <= max2) pairs.push_back({static_cast<std::int32_t>(i), j});
          }
        }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::array<std::int32_t, 2> find_coincident(const std::vector<Vec3>& points, double tolerance) {
  // Sorted by x, then y, then z: a point need be compared only with those of the same x up to
  // 'tolerance' further in y, and with those less than 'tolerance' further in x (a lattice
  // plane of one x is not scanned whole for every point of it).
  const std::size_t n = points.size();
  std::vector<std::int32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::int32_t>(i);
  auto key = [&](std::int32_t i) { return std::array<double, 3>{points[i][0], points[i][1], points[i][2]}; };
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return key(a) < key(b); });
  auto close = [&](const Vec3& a, const Vec3& b) { return a == b || (b - a).norm() <= tolerance; };
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& a = points[order[k]];
    auto found = [&](std::size_t l) {
      return std::array<std::int32_t, 2>{std::min(order[k], order[l]), std::max(order[k], order[l])};
    };
    std::size_t l = k + 1;
    for (; l < n && points[order[l]][0] == a[0]; ++l) {
      if (points[order[l]][1] - a[1] > tolerance) {  // (the rest of this x lies further in y)
        l = static_cast<std::size_t>(std::upper_bound(order.begin() + static_cast<std::ptrdiff_t>(l), order.end(), a[0],
                                                      [&](double x, std::int32_t i) { return x < points[i][0]; }) -
                                     order.begin());
        break;
      }
      if (close(a, points[order[l]])) return found(l);
    }
    for (; l < n && points[order[l]][0] - a[0] <= tolerance; ++l)
      if (close(a, points[order[l]])) return found(l);
  }
  return {-1, -1};
}

}  // namespace swarf

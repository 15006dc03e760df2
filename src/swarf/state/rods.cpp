// rods.cpp: bookkeeping of the rod arrays (state reset, per-particle rows).
#include "swarf/state/rods.h"

#include <algorithm>

namespace swarf {

void Rods::reset_state() {
  const std::size_t m = size();
  shift.assign(m, 0.0);
  intact.assign(m, 1);
  formed.assign(m, 0);
  trial_shift.assign(m, 0.0);
  trial_broken.assign(m, 0);
  stress.assign(m, 0.0);
  force_coef.assign(m, 0.0);
}

void build_rod_rows(const std::vector<std::array<std::int32_t, 2>>& ends, std::size_t n_particles, RodRows& out) {
  auto& row_start = out.row_start;
  row_start.assign(n_particles + 1, 0);
  for (const auto& e : ends) {
    ++row_start[e[0] + 1];
    ++row_start[e[1] + 1];
  }
  for (std::size_t p = 0; p < n_particles; ++p) row_start[p + 1] += row_start[p];
  out.entries.assign(row_start.back(), Rods::Entry{0, 0});
  std::vector<std::int32_t> fill(row_start.begin(), row_start.end() - 1);
  // Rods are visited in ascending order, so every row comes out sorted.
  for (std::size_t r = 0; r < ends.size(); ++r) {
    out.entries[fill[ends[r][0]]++] = Rods::Entry{static_cast<std::int32_t>(r), ends[r][1]};
    out.entries[fill[ends[r][1]]++] = Rods::Entry{static_cast<std::int32_t>(r), ends[r][0]};
  }
}

void Rods::build_rows(std::size_t n_particles) {
  RodRows rows{std::move(row_start), std::move(entries)};
  build_rod_rows(ends, n_particles, rows);
  row_start = std::move(rows.row_start);
  entries = std::move(rows.entries);
}

void Rods::append_formed(std::int32_t i, std::int32_t j, double length) {
  if (i > j) std::swap(i, j);
  ends.push_back({i, j});
  rest_length.push_back(length);
  shift.push_back(0.0);
  intact.push_back(1);
  formed.push_back(1);
  trial_shift.push_back(0.0);
  trial_broken.push_back(0);
  stress.push_back(0.0);
  force_coef.push_back(0.0);
}

std::size_t Rods::broken_count() const {
  std::size_t n = 0;
  for (std::size_t k = 0; k < size(); ++k) n += !intact[k] && !(k < formed.size() && formed[k]);
  return n;
}

std::size_t Rods::original_count() const {
  if (formed.size() != size()) return size();
  return size() - static_cast<std::size_t>(std::count(formed.begin(), formed.end(), std::uint8_t{1}));
}

std::size_t Rods::remove_broken_formed() {
  const std::size_t m = size();
  if (formed.size() != m) return m;
  std::size_t tail = m;  // the formed rods at the end
  while (tail > 0 && formed[tail - 1]) --tail;
  std::size_t first = tail;
  while (first < m && intact[first]) ++first;
  if (first == m) return m;
  const std::vector<std::uint8_t> keep(intact.begin() + first, intact.end());  // (intact is compacted too)
  auto compact = [&](auto& v) {
    std::size_t out = first;
    for (std::size_t k = first; k < m; ++k)
      if (keep[k - first]) v[out++] = v[k];
    v.resize(out);
  };
  compact(ends);
  for_each_field([&](const char*, auto& v) { compact(v); });
  return first;
}

void Rods::update_rows(std::size_t first_changed, std::size_t n_particles) {
  if (row_start.size() != n_particles + 1 || first_changed == 0) return build_rows(n_particles);
  const auto t = static_cast<std::int32_t>(first_changed);
  // Per particle: how many of its old entries stay (the prefix below t), then the changed rods.
  // (The per-particle loops are independent: parallel, with the same result for any number
  // of threads; this runs at most steps of a cut, and serial it held back the second thread.)
  std::vector<std::int32_t> start(n_particles + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t p = 0; p < n_particles; ++p) {
    std::int32_t e = row_start[p + 1];
    while (e > row_start[p] && entries[e - 1].rod >= t) --e;
    start[p + 1] = e - row_start[p];
  }
  for (std::size_t r = first_changed; r < ends.size(); ++r) {
    ++start[ends[r][0] + 1];
    ++start[ends[r][1] + 1];
  }
  for (std::size_t p = 0; p < n_particles; ++p) start[p + 1] += start[p];
  std::vector<Entry>& fresh = spare_entries;
  fresh.resize(start.back());
  std::vector<std::int32_t> fill(n_particles);
#pragma omp parallel for schedule(static)
  for (std::size_t p = 0; p < n_particles; ++p) {
    std::int32_t out = start[p];
    for (std::int32_t e = row_start[p]; e < row_start[p + 1] && entries[e].rod < t; ++e) fresh[out++] = entries[e];
    fill[p] = out;
  }
  // Changed rods in ascending order after the kept prefix: every row stays sorted.
  for (std::size_t r = first_changed; r < ends.size(); ++r) {
    fresh[fill[ends[r][0]]++] = Entry{static_cast<std::int32_t>(r), ends[r][1]};
    fresh[fill[ends[r][1]]++] = Entry{static_cast<std::int32_t>(r), ends[r][0]};
  }
  row_start.swap(start);
  entries.swap(fresh);
}

}  // namespace swarf

// plastic_volume.cpp: the rods' plastic flow made to keep the volume (see plastic_volume.h).
#include "swarf/forces/plastic_volume.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "swarf/core/parallel.h"

namespace swarf {

void keep_plastic_volume(Rods& rods, const Vec3* x, std::size_t particles, Periodic periodic, PlasticVolumeScratch& w,
                         int* block_changed) {
  const std::int32_t* row = rods.row_start.data();
  const Rods::Entry* entries = rods.entries.data();
  const std::uint8_t* intact = rods.intact.data();
  const std::uint8_t* broken = rods.trial_broken.data();
  const double* shift = rods.shift.data();
  double* trial = rods.trial_shift.data();
  const auto* ends = rods.ends.data();
  const std::size_t nr = rods.size(), nb = block_count(nr);
  w.mark.resize(particles, 0);
  w.mean.resize(particles, 0.0);
  std::uint8_t* mark = w.mark.data();
  double* m = w.mean.data();
  // Only where a rod yielded: the particles at the ends of a rod whose trial moved its shift
  // (in the blocks the kernel marked), and one ring of neighbours around them (a correction
  // reaches the other end of each of their rods). Marked through atomic_ref: several rods may
  // mark one particle, all with the same value. Most of a cut's workpiece is elastic and stays
  // out of every pass below.
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t b = 0; b < nb; ++b) {
    if (!block_changed[b]) continue;
    const std::size_t end = std::min(nr, (b + 1) * kBlock);
    for (std::size_t k = b * kBlock; k < end; ++k)
      if (intact[k] && !broken[k] && trial[k] != shift[k])
        for (const std::int32_t e : ends[k]) std::atomic_ref<std::uint8_t>(mark[e]).store(1, std::memory_order_relaxed);
  }
  w.set.clear();
  for (std::size_t i = 0; i < particles; ++i)
    if (mark[i] == 1) w.set.push_back(static_cast<std::int32_t>(i));
  if (w.set.empty()) return;
  const std::size_t yielded = w.set.size();  // (the loop appends: by index, not by iterator)
  for (std::size_t q = 0; q < yielded; ++q)
    for (std::int32_t i = w.set[q], e = row[i]; e < row[i + 1]; ++e)
      if (mark[entries[e].other] == 0) {
        mark[entries[e].other] = 2;
        w.set.push_back(entries[e].other);
      }
  std::sort(w.set.begin(), w.set.end());  // (particle order: the same passes on any thread count)
  const std::int32_t* set = w.set.data();
  const std::int64_t ns = static_cast<std::int64_t>(w.set.size());
  // Each pass takes (m_i + m_j) / 2 off every rod at the set; a particle's new mean is then
  // m_i / 2 - (mean of the neighbours' m) / 2: a mean shared with the neighbours (a uniform
  // pressure's) goes at once, a mean that alternates from particle to particle falls by at least
  // a third per pass (the FCC graph's adjacency, normalised, has its eigenvalues in [-1/3, 1]).
  // A rod is corrected by one of its ends: the set's lower index, or its only end in the set.
  const double H = shift_modulus(rods.law), A = rods.area;
  double* stress = rods.stress.data();
  double* coef = rods.force_coef.data();
  for (int pass = 0; pass < kPlasticVolumePasses; ++pass) {
#pragma omp parallel for schedule(static)
    for (std::int64_t q = 0; q < ns; ++q) {
      const std::int32_t i = set[q];
      double sum = 0.0;
      int count = 0;
      for (std::int32_t e = row[i]; e < row[i + 1]; ++e) {
        const std::int32_t k = entries[e].rod;
        if (!intact[k] || broken[k]) continue;
        sum += trial[k] - shift[k];
        ++count;
      }
      m[i] = count > 0 ? sum / count : 0.0;
    }
#pragma omp parallel for schedule(static)
    for (std::int64_t q = 0; q < ns; ++q) {
      const std::int32_t i = set[q];
      for (std::int32_t e = row[i]; e < row[i + 1]; ++e) {
        const std::int32_t k = entries[e].rod, o = entries[e].other;
        if (!intact[k] || broken[k] || (mark[o] != 0 && o < i)) continue;
        const double corr = 0.5 * (m[i] + m[o]);  // (m = 0 off the set)
        if (corr == 0.0) continue;
        trial[k] -= corr;
        Vec3 d = x[ends[k][1]] - x[ends[k][0]];
        periodic.wrap(d);
        const double ds = H * corr;
        stress[k] += ds;
        coef[k] += ds * A / d.norm();
        std::atomic_ref<int>(block_changed[k / kBlock]).store(1, std::memory_order_relaxed);
      }
    }
  }
  for (const std::int32_t i : w.set) {
    mark[i] = 0;
    m[i] = 0.0;
  }
}

}  // namespace swarf

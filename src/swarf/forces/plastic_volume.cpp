// plastic_volume.cpp: the rods' plastic flow made to keep the volume (see plastic_volume.h).
#include "swarf/forces/plastic_volume.h"

#include <algorithm>
#include <cmath>

#include "swarf/core/parallel.h"

namespace swarf {

void keep_plastic_volume(Rods& rods, const Vec3* x, std::size_t particles, Periodic periodic, std::vector<double>& mean,
                         std::vector<double>& correction, int* block_changed) {
  mean.resize(particles);
  const std::int32_t* row = rods.row_start.data();
  const Rods::Entry* entries = rods.entries.data();
  const std::uint8_t* intact = rods.intact.data();
  const std::uint8_t* broken = rods.trial_broken.data();
  const double* shift = rods.shift.data();
  double* trial = rods.trial_shift.data();
  double* m = mean.data();
  const std::int64_t n = static_cast<std::int64_t>(particles);
  const auto* ends = rods.ends.data();
  const std::size_t nr = rods.size(), nb = block_count(nr);
  // Each pass takes (m_i + m_j) / 2 off every rod; the particles' new means are then
  // m_i / 2 - (mean of the neighbours' m) / 2: a mean shared with the neighbours (a uniform
  // pressure's) goes at once, a mean that alternates from particle to particle falls by at most
  // 2/3 per pass (the FCC graph's adjacency, normalised, has its eigenvalues in [-1/3, 1]).
  // The rods' increments are corrected pass by pass; the stresses and forces once, at the end.
  correction.assign(nr, 0.0);
  double* total = correction.data();
  for (int pass = 0; pass < kPlasticVolumePasses; ++pass) {
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
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
    for (std::size_t k = 0; k < nr; ++k) {
      if (!intact[k] || broken[k]) continue;
      const double corr = 0.5 * (m[ends[k][0]] + m[ends[k][1]]);
      trial[k] -= corr;
      total[k] += corr;
    }
  }
  const double H = shift_modulus(rods.law), A = rods.area;
  double* stress = rods.stress.data();
  double* coef = rods.force_coef.data();
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    int changed = 0;
    const std::size_t end = std::min(nr, (b + 1) * kBlock);
    for (std::size_t k = b * kBlock; k < end; ++k) {
      if (total[k] == 0.0) continue;
      Vec3 d = x[ends[k][1]] - x[ends[k][0]];
      periodic.wrap(d);
      const double ds = H * total[k];
      stress[k] += ds;
      coef[k] += ds * A / d.norm();
      changed = 1;
    }
    if (changed) block_changed[b] = 1;
  }
}

}  // namespace swarf

// density_floor.cpp: the bulk modulus of a compacted neighbourhood (see density_floor.h).
#include "swarf/forces/density_floor.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/errors.h"
#include "swarf/geometry/site_volume.h"

namespace swarf {

void DensityFloor::build(const Vec3* x, const double* radius, std::size_t n, Periodic periodic) {
  double rmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) rmax = std::max(rmax, radius[i]);
  skin_ = 0.2 * rmax;
  double rmin = rmax;
  for (std::size_t i = 0; i < n; ++i) rmin = std::min(rmin, radius[i]);
  inv_l_ = 1.0 / (2.0 * rmin);
  const double reach = kFloorReach * 2.0 * rmax + skin_;
  if (periodic.on() && !(reach < periodic.half))  // (the nearest image would not be the only one in reach)
    throw InputError(
        fmt::format("key 'rod.compaction_modulus': the floor's neighbours reach {:.4g} m (1.15 (r_i + "
                    "r_j) and a skin of 0.2 R), more than half the periodic width {:.4g} m: widen "
                    "the workpiece",
                    reach, periodic.period));
  Vec3 lo = x[0], hi = x[0];
  for (std::size_t i = 1; i < n; ++i) {
    lo = lo.cwiseMin(x[i]);
    hi = hi.cwiseMax(x[i]);
  }
  // Cells of at least the reach: a particle's neighbours are in its own cell and the 26 around
  // (along a periodic y, the cells' y index wraps; with fewer than 3 cells, each is visited once).
  std::array<int, 3> nc;
  for (int c = 0; c < 3; ++c) nc[c] = std::max(1, static_cast<int>((hi[c] - lo[c]) / reach));
  if (periodic.on()) {
    nc[1] = std::max(1, static_cast<int>(periodic.period / reach));
    lo[1] = 0.0;
  }
  // (a particle flung far away would stretch the grid over millions of empty cells: larger cells
  // find the same neighbours)
  while (static_cast<double>(nc[0]) * nc[1] * nc[2] > 8.0 * static_cast<double>(n) + 64.0) {
    int& widest = nc[0] >= nc[1] && nc[0] >= nc[2] ? nc[0] : (nc[1] >= nc[2] ? nc[1] : nc[2]);
    widest = std::max(1, widest / 2);
  }
  auto cell_of = [&](const Vec3& p) {
    std::array<int, 3> c;
    for (int k = 0; k < 3; ++k) {
      double q = p[k] - lo[k];
      if (k == 1 && periodic.on()) q -= periodic.period * std::floor(q * periodic.inv_period);
      const double size = (k == 1 && periodic.on()) ? periodic.period / nc[1] : (hi[k] - lo[k]) / nc[k];
      c[k] = std::clamp(size > 0.0 ? static_cast<int>(q / size) : 0, 0, nc[k] - 1);
    }
    return c;
  };
  const std::size_t ncells = static_cast<std::size_t>(nc[0]) * nc[1] * nc[2];
  std::vector<std::int32_t> cstart(ncells + 1, 0), members(n), cell(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = cell_of(x[i]);
    cell[i] = (c[0] * nc[1] + c[1]) * nc[2] + c[2];
    ++cstart[cell[i] + 1];
  }
  for (std::size_t c = 0; c < ncells; ++c) cstart[c + 1] += cstart[c];
  {
    std::vector<std::int32_t> fill(cstart.begin(), cstart.end() - 1);
    for (std::size_t i = 0; i < n; ++i) members[fill[cell[i]]++] = static_cast<std::int32_t>(i);
  }
  std::vector<std::vector<std::int32_t>> lists(n);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t ii = 0; ii < static_cast<std::int64_t>(n); ++ii) {
    const std::size_t i = static_cast<std::size_t>(ii);
    const auto c = cell_of(x[i]);
    std::vector<int> ys;
    for (int dy = -1; dy <= 1; ++dy) {
      int y = c[1] + dy;
      if (periodic.on())
        y = (y % nc[1] + nc[1]) % nc[1];
      else if (y < 0 || y >= nc[1])
        continue;
      if (std::find(ys.begin(), ys.end(), y) == ys.end()) ys.push_back(y);
    }
    auto& mine = lists[i];
    for (int dx = -1; dx <= 1; ++dx) {
      const int cx = c[0] + dx;
      if (cx < 0 || cx >= nc[0]) continue;
      for (const int cy : ys)
        for (int dz = -1; dz <= 1; ++dz) {
          const int cz = c[2] + dz;
          if (cz < 0 || cz >= nc[2]) continue;
          const int cc = (cx * nc[1] + cy) * nc[2] + cz;
          for (std::int32_t q = cstart[cc]; q < cstart[cc + 1]; ++q) {
            const std::int32_t j = members[q];
            if (static_cast<std::size_t>(j) == i) continue;
            Vec3 d = x[j] - x[i];
            periodic.wrap(d);
            const double r = kFloorReach * (radius[i] + radius[j]) + skin_;
            if (d.squaredNorm() < r * r) mine.push_back(j);
          }
        }
    }
    std::sort(mine.begin(), mine.end());
  }
  start_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) start_[i + 1] = start_[i] + static_cast<std::int32_t>(lists[i].size());
  nb_.resize(static_cast<std::size_t>(start_[n]));
  for (std::size_t i = 0; i < n; ++i) std::copy(lists[i].begin(), lists[i].end(), nb_.begin() + start_[i]);
  x_build_.assign(x, x + n);
}

void DensityFloor::evaluate(const Vec3* x, const double* radius, std::size_t n, Periodic periodic, double K,
                            double onset) {
  const std::int64_t ns = static_cast<std::int64_t>(n);
  bool rebuild = x_build_.size() != n;
  if (!rebuild) {
    moved_.resize(n);
    double moved2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : moved2)
    for (std::int64_t i = 0; i < ns; ++i) {
      Vec3 d = x[i] - x_build_[i];
      periodic.wrap(d);
      const double d2 = d.squaredNorm();
      moved2 = std::max(moved2, d2);
      moved_[i] = std::sqrt(d2);
    }
    rebuild = 4.0 * moved2 > skin_ * skin_;
  }
  if (rebuild) build(x, radius, n, periodic);
  theta_.resize(n);
  a_.resize(n);
  u_.resize(n);
  force_.resize(n);
  rho_ref_.resize(n);
  const double rho0 = 12.0 * floor_weight(1.0);
  // (a particle whose rho stays at or below this has g = 0: the margin is far above the sums' rounding)
  const double inactive = rho0 + 4.0 * onset - 1e-9;
  const bool bound = !rebuild && !exact_;
#pragma omp parallel for schedule(static)
  for (std::int64_t ii = 0; ii < ns; ++ii) {
    const std::size_t i = static_cast<std::size_t>(ii);
    if (bound) {
      // (rho now <= rho at the build + sum_j (|dx_i| + |dx_j|) / l_ij)
      double reach = 0.0;
      for (std::int32_t q = start_[i]; q < start_[i + 1]; ++q) reach += moved_[i] + moved_[nb_[q]];
      const double most = rho_ref_[i] + reach * inv_l_;
      if (most <= inactive) {
        theta_[i] = -(most - rho0) / 4.0;
        a_[i] = u_[i] = 0.0;
        continue;
      }
    }
    double rho = 0.0;
    for (std::int32_t q = start_[i]; q < start_[i + 1]; ++q) {
      const std::int32_t j = nb_[q];
      Vec3 d = x[j] - x[i];
      periodic.wrap(d);
      rho += floor_weight(d.norm() / (radius[i] + radius[j]));
    }
    if (rebuild) rho_ref_[i] = rho;
    const double theta = -(rho - rho0) / 4.0;
    const double g = std::min(theta + onset, 0.0), V = particle_volume(radius[i]);
    theta_[i] = theta;
    a_[i] = K * V * g;
    u_[i] = 0.5 * K * V * g * g;
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t ii = 0; ii < ns; ++ii) {
    const std::size_t i = static_cast<std::size_t>(ii);
    Vec3 f = Vec3::Zero();
    for (std::int32_t q = start_[i]; q < start_[i + 1]; ++q) {
      const std::int32_t j = nb_[q];
      const double sum = a_[i] + a_[j];
      if (sum == 0.0) continue;
      Vec3 d = x[j] - x[i];
      periodic.wrap(d);
      const double L = d.norm(), l = radius[i] + radius[j];
      // (dU/dL = (|w'| / (4 l)) (K V_i g_i + K V_j g_j), negative when compacted: the force on i,
      // dU/dL e, points away from j)
      const double dUdL = floor_slope(L / l) / (4.0 * l) * sum;
      f += (dUdL / L) * d;
    }
    force_[i] = f;
  }
}

double DensityFloor::energy() const {
  double e = 0.0;
  for (const double u : u_) e += u;
  return e;
}

}  // namespace swarf

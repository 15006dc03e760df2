// tangent_matrix.cpp: J assembled from the Newton tangent's blocks (see tangent_matrix.h).
#include "swarf/integrate/tangent_matrix.h"

#include <Eigen/Dense>
#include <algorithm>
#include <utility>

#include "swarf/integrate/integration.h"

namespace swarf {

void TangentMatrix::times(const double* x, double* y) const {
  const std::int64_t n = static_cast<std::int64_t>(rows());
#pragma omp parallel for schedule(static)
  for (std::int64_t r = 0; r < n; ++r) {
    double s = 0.0;
    for (std::int64_t e = row_start[r]; e < row_start[r + 1]; ++e) s += value[e] * x[column[e]];
    y[r] = s;
  }
}

namespace {

// Particle i's blocks of J: (column particle, 3x3 block), the diagonal first, then its rods'
// and contacts' -S in the product's order; merged by column and sorted.
void row_blocks(const Integration& it, std::size_t i, std::vector<std::pair<std::int32_t, Eigen::Matrix3d>>& out) {
  const auto& p = it.world.particles;
  const auto& r = it.world.rods;
  const NewtonWork& w = it.ms.newton;
  out.clear();
  Eigen::Matrix3d diag = p.mass[i] * Eigen::Matrix3d::Identity();
  auto block = [](const Vec3& n, double axial, double lateral) {
    Eigen::Matrix3d s = axial * (n * n.transpose());
    s.diagonal().array() += lateral;
    return s;
  };
  for (std::int32_t e = r.row_start[i]; e < r.row_start[i + 1]; ++e) {
    const Rods::Entry en = r.entries[e];
    const Eigen::Matrix3d s = block(w.axis[en.rod], w.axial[en.rod], w.lateral[en.rod]);
    diag += s;
    out.emplace_back(en.other, -s);
  }
  if (it.sys.contacts.enabled()) {
    const ContactSystem::TangentRows ct = it.sys.contacts.tangent_rows();
    ct.add_diagonal(i, diag);
    ct.for_each_pair(i, [&](std::int32_t other, const Vec3& n, double axial, double lateral) {
      out.emplace_back(other, -block(n, axial, lateral));
    });
  }
  out.emplace_back(static_cast<std::int32_t>(i), diag);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t k = 0;
  for (std::size_t m = 1; m < out.size(); ++m) {
    if (out[m].first == out[k].first)
      out[k].second += out[m].second;
    else
      out[++k] = out[m];
  }
  if (!out.empty()) out.resize(k + 1);
}

}  // namespace

void assemble_tangent(const Integration& it, TangentMatrix& J) {
  const auto& p = it.world.particles;
  const std::size_t n = p.size();
  const std::uint8_t* mask = p.prescribed.data();
  // Two passes over the particles (the counts, then the entries at their offsets), each
  // particle's rows written by one thread: the same matrix for any number of threads.
  using Blocks = std::vector<std::pair<std::int32_t, Eigen::Matrix3d>>;
  auto each_particle = [&](auto&& f) {
#pragma omp parallel
    {
      Blocks b;
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        row_blocks(it, i, b);
        f(i, b);
      }
    }
  };
  J.row_start.assign(3 * n + 1, 0);
  each_particle([&](std::size_t i, const Blocks& b) {
    for (int c = 0; c < 3; ++c) {
      std::int64_t count = 0;
      if (mask[i] & (1u << c))
        count = 1;
      else
        for (const auto& [j, s] : b)
          for (int d = 0; d < 3; ++d) count += (mask[j] & (1u << d)) ? 0 : 1;
      J.row_start[3 * i + c + 1] = count;
    }
  });
  for (std::size_t r = 0; r < 3 * n; ++r) J.row_start[r + 1] += J.row_start[r];
  J.column.resize(J.row_start[3 * n]);
  J.value.resize(J.row_start[3 * n]);
  each_particle([&](std::size_t i, const Blocks& b) {
    for (int c = 0; c < 3; ++c) {
      std::int64_t e = J.row_start[3 * i + c];
      if (mask[i] & (1u << c)) {
        J.column[e] = static_cast<std::int32_t>(3 * i + c);
        J.value[e] = 1.0;
        continue;
      }
      for (const auto& [j, s] : b)
        for (int d = 0; d < 3; ++d) {
          if (mask[j] & (1u << d)) continue;
          J.column[e] = 3 * j + d;
          J.value[e++] = s(c, d);
        }
    }
  });
}

}  // namespace swarf

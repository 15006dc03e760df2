// particle_fields.cpp: per-particle stress and plastic strain (see particle_fields.h). Run at
// output times only, so it favours plainness over speed: one pass over the rods, one over the
// contacts, a 6 x 6 least-squares solve per particle.
#include "swarf/measure/particle_fields.h"

#include <Eigen/Dense>
#include <cmath>

#include "swarf/contacts/contacts.h"

namespace swarf {

double particle_volume(double radius) { return 4.0 * std::sqrt(2.0) * radius * radius * radius; }

double von_mises(const SymTensor& t) {
  const double m = (t[0] + t[1] + t[2]) / 3.0;
  const double sx = t[0] - m, sy = t[1] - m, sz = t[2] - m;
  const double ss = sx * sx + sy * sy + sz * sz + 2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]);
  return std::sqrt(1.5 * ss);
}

namespace {

// The coefficients g of a normal strain: n.E.n = g . [Exx, Eyy, Ezz, Exy, Eyz, Exz].
Eigen::Matrix<double, 6, 1> normal_strain_row(const Vec3& n) {
  Eigen::Matrix<double, 6, 1> g;
  g << n[0] * n[0], n[1] * n[1], n[2] * n[2], 2 * n[0] * n[1], 2 * n[1] * n[2], 2 * n[0] * n[2];
  return g;
}

}  // namespace

ParticleFields particle_fields(const Particles& p, const Rods& r, const Periodic& periodic,
                               const ContactSystem* contacts) {
  const std::size_t n = p.size();
  // The moments are summed into the output's stress and scaled there; the plastic fit's
  // normal equations are built one particle at a time from its rod list (ascending rods, as
  // one pass over the rods adds them): per-particle 6 x 6 matrices for the whole body would
  // be the largest arrays of the run.
  ParticleFields out;
  out.stress.assign(n, SymTensor{});
  auto& moment = out.stress;
  // Each rod's plastic strain from its state, as its law defines it (one visit for all rods).
  std::vector<double> rod_plastic(r.size());
  std::visit(
      [&](const auto& law) {
        for (std::size_t k = 0; k < r.size(); ++k) rod_plastic[k] = plastic_strain(law, r.shift[k]);
      },
      r.law);
  const bool have_coef = r.force_coef.size() == r.size();
  auto axis = [&](std::size_t k) {
    const auto [i, j] = r.ends[k];
    Vec3 d = p.position[j] - p.position[i];
    periodic.wrap(d);
    return d;
  };
  if (have_coef)
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (!r.intact[k]) continue;
      // Force on i = coef d at the midpoint d/2; on j = -coef d at -d/2: the same moment.
      const Vec3 d = axis(k), half = 0.5 * d, f = r.force_coef[k] * d;
      add_moment(moment[r.ends[k][0]], half, f);
      add_moment(moment[r.ends[k][1]], half, f);
    }
  if (contacts && contacts->enabled()) contacts->add_virial(p, moment);
  // The rod lists: the rods' own when they are current, else built here.
  RodRows rows;
  const bool current = r.row_start.size() == n + 1 && r.entries.size() == 2 * r.size();
  if (!current) build_rod_rows(r.ends, n, rows);
  const std::vector<std::int32_t>& row_start = current ? r.row_start : rows.row_start;
  const std::vector<Rods::Entry>& entries = current ? r.entries : rows.entries;

  out.von_mises.resize(n);
  out.hydrostatic.resize(n);
  out.plastic_strain.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double inv_v = 1.0 / particle_volume(p.radius[i]);
    for (int c = 0; c < 6; ++c) out.stress[i][c] = moment[i][c] * inv_v;
    out.von_mises[i] = von_mises(out.stress[i]);
    out.hydrostatic[i] = (out.stress[i][0] + out.stress[i][1] + out.stress[i][2]) / 3.0;
    Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::int32_t q = row_start[i]; q < row_start[i + 1]; ++q) {
      const std::int32_t k = entries[q].rod;
      if (!r.intact[k]) continue;
      const Vec3 d = axis(k);
      const double len = d.norm();
      if (len <= 0) continue;
      const auto g = normal_strain_row(d / len);
      normal += g * g.transpose();
      rhs += g * rod_plastic[k];
    }
    if (rhs.isZero(0.0)) continue;  // (no plastic strain in any rod: 0 without a solve)
    // Least squares through the normal matrix's eigenvectors, keeping those it determines
    // well: an eigenvalue below kWellDetermined of the largest (rods nearly parallel, or
    // fewer than 6 directions) is dropped rather than inverted, which bounds each kept
    // component by the rods' rms plastic strain / sqrt(kWellDetermined). An interior FCC
    // particle's smallest ratio is 1/4, so it keeps all six (the fit is exact there).
    constexpr double kWellDetermined = 0.05;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(normal);
    const double top = eig.eigenvalues().maxCoeff();
    Eigen::Matrix<double, 6, 1> e = Eigen::Matrix<double, 6, 1>::Zero();
    for (int q = 0; q < 6; ++q)
      if (eig.eigenvalues()[q] > kWellDetermined * top)
        e += (eig.eigenvectors().col(q).dot(rhs) / eig.eigenvalues()[q]) * eig.eigenvectors().col(q);
    // von Mises equivalent strain of the fitted tensor: sqrt(2/3 dev:dev), off-diagonals twice.
    out.plastic_strain[i] = std::sqrt(2.0 / 3.0) * von_mises(SymTensor{e[0], e[1], e[2], e[3], e[4], e[5]}) /
                            std::sqrt(1.5);
  }
  return out;
}

}  // namespace swarf

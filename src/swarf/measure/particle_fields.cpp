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
  std::vector<SymTensor> moment(n, SymTensor{});
  std::vector<Eigen::Matrix<double, 6, 6>> normal(n, Eigen::Matrix<double, 6, 6>::Zero());
  std::vector<Eigen::Matrix<double, 6, 1>> rhs(n, Eigen::Matrix<double, 6, 1>::Zero());
  // eps_p = (E - k)/E eps0, the relation plastic_work_density books (laws/rod_law.h).
  const double to_plastic = r.law.youngs_modulus > 0 ? (r.law.youngs_modulus - r.law.hardening) / r.law.youngs_modulus
                                                     : 0.0;
  const bool have_coef = r.force_coef.size() == r.size();
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (!r.intact[k]) continue;
    const auto [i, j] = r.ends[k];
    Vec3 d = p.position[j] - p.position[i];
    periodic.wrap(d);
    if (have_coef) {
      // Force on i = coef d at the midpoint d/2; on j = -coef d at -d/2: the same moment.
      const Vec3 half = 0.5 * d, f = r.force_coef[k] * d;
      add_moment(moment[i], half, f);
      add_moment(moment[j], half, f);
    }
    const double len = d.norm();
    if (len <= 0) continue;
    const auto g = normal_strain_row(d / len);
    const double eps_p = to_plastic * r.shift[k];
    for (const std::int32_t e : {i, j}) {
      normal[e] += g * g.transpose();
      rhs[e] += g * eps_p;
    }
  }
  if (contacts && contacts->enabled()) contacts->add_virial(p, moment);

  ParticleFields out;
  out.stress.resize(n);
  out.von_mises.resize(n);
  out.hydrostatic.resize(n);
  out.plastic_strain.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double inv_v = 1.0 / particle_volume(p.radius[i]);
    for (int c = 0; c < 6; ++c) out.stress[i][c] = moment[i][c] * inv_v;
    out.von_mises[i] = von_mises(out.stress[i]);
    out.hydrostatic[i] = (out.stress[i][0] + out.stress[i][1] + out.stress[i][2]) / 3.0;
    if (rhs[i].isZero(0.0)) continue;  // (no plastic strain in any rod: 0 without a solve)
    // Least squares through the normal matrix's eigenvectors, keeping those it determines
    // well: an eigenvalue below kWellDetermined of the largest (rods nearly parallel, or
    // fewer than 6 directions) is dropped rather than inverted, which bounds each kept
    // component by the rods' rms plastic strain / sqrt(kWellDetermined). An interior FCC
    // particle's smallest ratio is 1/4, so it keeps all six (the fit is exact there).
    constexpr double kWellDetermined = 0.05;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(normal[i]);
    const double top = eig.eigenvalues().maxCoeff();
    Eigen::Matrix<double, 6, 1> e = Eigen::Matrix<double, 6, 1>::Zero();
    for (int q = 0; q < 6; ++q)
      if (eig.eigenvalues()[q] > kWellDetermined * top)
        e += (eig.eigenvectors().col(q).dot(rhs[i]) / eig.eigenvalues()[q]) * eig.eigenvectors().col(q);
    // von Mises equivalent strain of the fitted tensor: sqrt(2/3 dev:dev), off-diagonals twice.
    out.plastic_strain[i] = std::sqrt(2.0 / 3.0) * von_mises(SymTensor{e[0], e[1], e[2], e[3], e[4], e[5]}) /
                            std::sqrt(1.5);
  }
  return out;
}

}  // namespace swarf

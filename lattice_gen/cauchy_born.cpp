// cauchy_born.cpp: the bonded FCC crystal under a homogeneous deformation (see cauchy_born.h).
#include "lattice_gen/cauchy_born.h"

#include <fmt/format.h>

#include <cmath>

#include "swarf/core/errors.h"

namespace swarf {

namespace {

// Voigt order xx yy zz yz xz xy.
constexpr int kVoigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

}  // namespace

CauchyBornCrystal::CauchyBornCrystal(const AnyRodLaw& law, double cell_edge, double rod_area)
    : law_(law), a_(cell_edge), l0_(cell_edge / std::sqrt(2.0)), area_(rod_area) {
  if (!(cell_edge > 0) || !std::isfinite(cell_edge))
    throw InputError(fmt::format("material: the cell edge must be a positive length in m, got {}", cell_edge));
  if (!(rod_area > 0) || !std::isfinite(rod_area))
    throw InputError(fmt::format("material: the rod area must be a positive area in m^2, got {}", rod_area));
  const double E = elastic_modulus(law);
  if (!(E > 0) || !std::isfinite(E))
    throw InputError(fmt::format("material: the rod's Young's modulus must be positive in Pa, got {}", E));
  for (int k = 0; k < 6; ++k) r0_[k] = 0.5 * a_ * Eigen::Vector3d(kFccBonds[k][0], kFccBonds[k][1], kFccBonds[k][2]);
}

CrystalTrial CauchyBornCrystal::evaluate(const Eigen::Matrix3d& F, const std::array<bool, 6>& carry_nothing) const {
  CrystalTrial t;
  const double volume = F.determinant() * a_ * a_ * a_ / 4.0;  // per atom
  for (int k = 0; k < 6; ++k) {
    const Eigen::Vector3d r = F * r0_[k];
    const double len = r.norm();
    const double eps = (len - l0_) / l0_;
    t.rod_strain[k] = eps;
    t.shift[k] = shift_[k];
    if (broken_[k] || carry_nothing[k]) {
      t.broken[k] = true;
      continue;
    }
    const RodResponse resp = swarf::evaluate(law_, eps, 0.0, shift_[k]);  // quasi-static: strain rate 0
    t.shift[k] = resp.shift;
    t.broken[k] = resp.broken;
    t.rod_stress[k] = resp.stress;
    t.sigma += (resp.stress * area_ / len) * (r * r.transpose());
  }
  t.sigma /= volume;
  return t;
}

void CauchyBornCrystal::commit(const CrystalTrial& trial) {
  for (int k = 0; k < 6; ++k) {
    if (broken_[k]) continue;
    if (trial.broken[k])
      broken_[k] = true;
    else
      shift_[k] = trial.shift[k];
  }
}

int CauchyBornCrystal::broken_count() const {
  int n = 0;
  for (bool b : broken_) n += b ? 1 : 0;
  return n;
}

Eigen::Matrix<double, 6, 6> CauchyBornCrystal::elastic_constants() const {
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  const double kb = rod_stiffness(), volume = a_ * a_ * a_ / 4.0;
  for (int k = 0; k < 6; ++k) {
    const Eigen::Vector3d n = r0_[k].normalized();
    for (int I = 0; I < 6; ++I)
      for (int J = 0; J < 6; ++J)
        C(I, J) += kb * l0_ * l0_ * n[kVoigt[I][0]] * n[kVoigt[I][1]] * n[kVoigt[J][0]] * n[kVoigt[J][1]] / volume;
  }
  return C;
}

double CauchyBornCrystal::closest_unbonded(const Eigen::Matrix3d& F) const {
  // Lattice vectors a/2 (i, j, k) with i + j + k even; half of them (the other half are their
  // negatives, at the same distance). |i|, |j|, |k| <= 8 reaches the short images that a shear
  // F = I + gamma s (x) m of gamma up to about 3 brings in.
  constexpr int kReach = 8;
  double best = HUGE_VAL;
  for (int i = 0; i <= kReach; ++i)
    for (int j = -kReach; j <= kReach; ++j)
      for (int k = -kReach; k <= kReach; ++k) {
        if ((i + j + k) % 2 != 0) continue;
        if (i == 0 && (j < 0 || (j == 0 && k <= 0))) continue;  // one of each +-pair, not 0
        bool bonded = false;
        for (int b = 0; b < 6 && !bonded; ++b) {
          const auto& v = kFccBonds[b];
          const bool same = v[0] == i && v[1] == j && v[2] == k;
          const bool opposite = v[0] == -i && v[1] == -j && v[2] == -k;
          bonded = (same || opposite) && !broken_[b];
        }
        if (bonded) continue;
        best = std::min(best, (F * Eigen::Vector3d(i, j, k)).norm() * 0.5 * a_);
      }
  return best;
}

double directional_youngs_modulus(const Eigen::Matrix<double, 6, 6>& C, const Eigen::Vector3d& direction) {
  const Eigen::Vector3d d = direction.normalized();
  Eigen::Matrix<double, 6, 1> w;
  w << d[0] * d[0], d[1] * d[1], d[2] * d[2], d[1] * d[2], d[0] * d[2], d[0] * d[1];
  return 1.0 / w.dot(C.fullPivLu().solve(w));
}

double simple_shear_modulus(const Eigen::Matrix<double, 6, 6>& C, const Eigen::Vector3d& s, const Eigen::Vector3d& m) {
  Eigen::Matrix<double, 6, 1> v;
  v << s[0] * m[0], s[1] * m[1], s[2] * m[2], s[1] * m[2] + s[2] * m[1], s[0] * m[2] + s[2] * m[0],
      s[0] * m[1] + s[1] * m[0];
  return v.dot(C * v);
}

}  // namespace swarf

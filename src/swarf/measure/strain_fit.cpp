// strain_fit.cpp: the least-squares strain tensor of a particle's rods (see strain_fit.h).
#include "swarf/measure/strain_fit.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "swarf/measure/particle_fields.h"

namespace swarf {

SymTensor fit_strain(const Mat6& normal, const Vec6& rhs) {
  if (rhs.isZero(0.0)) return SymTensor{};  // (no value in any rod: 0 without a solve)
  constexpr double kWellDetermined = 0.05;
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(normal);
  const double top = eig.eigenvalues().maxCoeff();
  Vec6 e = Vec6::Zero();
  for (int q = 0; q < 6; ++q)
    if (eig.eigenvalues()[q] > kWellDetermined * top)
      e += (eig.eigenvectors().col(q).dot(rhs) / eig.eigenvalues()[q]) * eig.eigenvectors().col(q);
  return SymTensor{e[0], e[1], e[2], e[3], e[4], e[5]};
}

SymTensor fit_deviatoric_strain(const Mat6& normal, const Vec6& rhs, double well_determined) {
  if (rhs.isZero(0.0)) return SymTensor{};
  // Columns: an orthonormal basis of the deviators in [xx, yy, zz, xy, yz, xz] (the shear
  // components count twice in the tensor norm, hence 1/sqrt(2)).
  const double a = 1.0 / std::sqrt(2.0), b = 1.0 / std::sqrt(6.0);
  Eigen::Matrix<double, 6, 5> t;
  t << a, b, 0, 0, 0,  //
      -a, b, 0, 0, 0,  //
      0, -2 * b, 0, 0, 0, 0, 0, a, 0, 0, 0, 0, 0, a, 0, 0, 0, 0, 0, a;
  const Eigen::Matrix<double, 5, 5> m = t.transpose() * normal * t;
  const Eigen::Matrix<double, 5, 1> r = t.transpose() * rhs;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 5, 5>> eig(m);
  const double top = eig.eigenvalues().maxCoeff();
  Eigen::Matrix<double, 5, 1> y = Eigen::Matrix<double, 5, 1>::Zero();
  for (int q = 0; q < 5; ++q)
    if (eig.eigenvalues()[q] > well_determined * top)
      y += (eig.eigenvectors().col(q).dot(r) / eig.eigenvalues()[q]) * eig.eigenvectors().col(q);
  const Vec6 e = t * y;
  return SymTensor{e[0], e[1], e[2], e[3], e[4], e[5]};
}

double equivalent_strain(const SymTensor& strain) {
  // von Mises' sqrt(3/2 s:s) times sqrt(2/3) / sqrt(3/2) (off-diagonals counted twice in both).
  return std::sqrt(2.0 / 3.0) * von_mises(strain) / std::sqrt(1.5);
}

}  // namespace swarf

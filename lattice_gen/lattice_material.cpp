// lattice_material.cpp: the virtual material tests (see lattice_material.h).
#include "lattice_gen/lattice_material.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "lattice_gen/cauchy_born.h"
#include "swarf/core/errors.h"

namespace swarf {

namespace {

using Vec5 = Eigen::Matrix<double, 5, 1>;

Eigen::Vector3d unit(const std::array<double, 3>& v, const char* what) {
  const Eigen::Vector3d e(v[0], v[1], v[2]);
  if (!e.allFinite() || !(e.norm() > 0))
    throw InputError(
        fmt::format("material: the {} must be a non-zero finite vector, got ({}, {}, {})", what, v[0], v[1], v[2]));
  return e.normalized();
}

// Rows: the test frame's axes in the lattice frame.
Eigen::Matrix3d frame(const Eigen::Vector3d& e1, const Eigen::Vector3d& e2) {
  Eigen::Matrix3d Q;
  Q.row(0) = e1.transpose();
  Q.row(1) = e2.transpose();
  Q.row(2) = e1.cross(e2).transpose();
  return Q;
}

// The uniaxial test frame: 1 along the direction; 2 = helper x 1 with the helper [001] (or
// [100] for a direction near [001]), so [100] gives 2 = [010], [110] gives 2 = [-110]/sqrt2.
Eigen::Matrix3d uniaxial_frame(const Eigen::Vector3d& e1) {
  const Eigen::Vector3d helper = std::abs(e1.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  return frame(e1, helper.cross(e1).normalized());
}

void check_increment(double increment) {
  if (!(increment > 0) || !std::isfinite(increment))
    throw InputError(fmt::format("material: the increment must be a positive strain, got {}", increment));
}

// The strains of a path: each segment in equal steps of at most 'increment', ends exact.
std::vector<double> path_strains(const std::vector<double>& turning_points, double increment) {
  std::vector<double> out;
  for (std::size_t s = 1; s < turning_points.size(); ++s) {
    const double a = turning_points[s - 1], b = turning_points[s];
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(b - a) / increment - 1e-9)));
    for (int i = 1; i <= n; ++i) out.push_back(i == n ? b : a + (b - a) * (double(i) / n));
  }
  return out;
}

double von_mises(const Eigen::Matrix3d& s) {
  const double d01 = s(0, 0) - s(1, 1), d12 = s(1, 1) - s(2, 2), d20 = s(2, 2) - s(0, 0);
  return std::sqrt(0.5 * (d01 * d01 + d12 * d12 + d20 * d20) +
                   3.0 * (s(0, 1) * s(0, 1) + s(1, 2) * s(1, 2) + s(0, 2) * s(0, 2)));
}

// One point of a curve from the committed crystal at F (lattice frame); Q the test frame.
MaterialPoint record(const CauchyBornCrystal& crystal, const CrystalTrial& t, const Eigen::Matrix3d& F,
                     const Eigen::Matrix3d& Q, bool shear, double strain, double mode_modulus) {
  MaterialPoint p;
  const Eigen::Matrix3d s = Q * t.sigma * Q.transpose();
  const Eigen::Matrix3d Ft = Q * F * Q.transpose();
  p.strain = strain;
  p.stress = shear ? s(0, 1) : s(0, 0);
  p.equivalent_strain = shear ? std::abs(strain) / std::sqrt(3.0) : std::abs(strain);
  p.equivalent_stress = von_mises(s);
  p.plastic_strain = p.equivalent_strain - p.equivalent_stress / mode_modulus;
  p.volume_ratio = F.determinant();
  p.mean_stress = s.trace() / 3.0;
  p.sigma = {s(0, 0), s(1, 1), s(2, 2), s(1, 2), s(0, 2), s(0, 1)};
  p.broken = crystal.broken_count();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p.deformation[3 * i + j] = Ft(i, j);
  p.closest_unbonded = crystal.closest_unbonded(F);
  p.max_rod_strain = -HUGE_VAL;
  for (int k = 0; k < 6; ++k)
    if (!crystal.broken()[k]) p.max_rod_strain = std::max(p.max_rod_strain, t.rod_strain[k]);
  if (p.broken == 6) p.max_rod_strain = 0.0;
  return p;
}

// Rods whose law says broken but which still carry in 't' (the set to add before re-solving).
bool newly_broken(const CrystalTrial& t, const CauchyBornCrystal& c, std::array<bool, 6>& carry_nothing) {
  bool any = false;
  for (int k = 0; k < 6; ++k)
    if (t.broken[k] && !carry_nothing[k] && !c.broken()[k]) {
      carry_nothing[k] = true;
      any = true;
    }
  return any;
}

// The stops: every rod broken; no stress left once one broke; or the lattice collapsed, an
// unbonded neighbour closer than l0/2 (the particles would overlap by half a diameter: the
// DEM's contacts engage at l0 and would resist; the rods alone let [110] tension flatten the
// crystal along [001] through itself once the axial rods flow).
bool finished(const MaterialPoint& p, double peak_equivalent_stress, double rest_length) {
  if (p.broken == 6 || p.closest_unbonded < 0.5 * rest_length) return true;
  return p.broken > 0 && !(p.equivalent_stress > 1e-9 * peak_equivalent_stress);
}

// A stretch the lattice can take: U symmetric positive definite (det F > 0).
bool admissible(double eps, const Vec5& x) {
  Eigen::Matrix3d U;
  U << std::exp(eps), x[4], x[3], x[4], x[0], x[2], x[3], x[2], x[1];
  return x.allFinite() && U.llt().info() == Eigen::Success;
}

// The uniaxial test's deformation: U11 = exp(eps), the five other components of the symmetric
// stretch x = (U22, U33, U23, U13, U12), in the lattice frame F = Q^T U Q.
Eigen::Matrix3d uniaxial_F(const Eigen::Matrix3d& Q, double eps, const Vec5& x) {
  Eigen::Matrix3d U;
  U << std::exp(eps), x[4], x[3], x[4], x[0], x[2], x[3], x[2], x[1];
  return Q.transpose() * U * Q;
}

// The five stresses that uniaxial stress holds at zero, divided by the scale kb/a.
Vec5 lateral_residual(const CauchyBornCrystal& c, const Eigen::Matrix3d& Q, double eps, const Vec5& x,
                      const std::array<bool, 6>& carry_nothing, double scale) {
  const Eigen::Matrix3d s = Q * c.evaluate(uniaxial_F(Q, eps, x), carry_nothing).sigma * Q.transpose();
  Vec5 r;
  r << s(1, 1), s(2, 2), s(1, 2), s(0, 2), s(0, 1);
  return r / scale;
}

// Newton on the lateral stretches: central finite differences (h = 1e-7 of a stretch), a
// minimum-norm step (the Jacobian is singular once broken rods leave a mechanism) and
// backtracking on the residual's norm. Converged at max |r| <= 1e-10 (r in units of kb/a).
constexpr double kLateralTolerance = 1e-10;

Vec5 solve_lateral(const CauchyBornCrystal& c, const Eigen::Matrix3d& Q, double eps, Vec5 x,
                   const std::array<bool, 6>& carry_nothing, double scale) {
  constexpr double h = 1e-7;
  Vec5 r = lateral_residual(c, Q, eps, x, carry_nothing, scale);
  for (int iter = 0; iter < 100; ++iter) {
    if (r.cwiseAbs().maxCoeff() <= kLateralTolerance) return x;
    Eigen::Matrix<double, 5, 5> J;
    for (int j = 0; j < 5; ++j) {
      Vec5 xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      J.col(j) = (lateral_residual(c, Q, eps, xp, carry_nothing, scale) -
                  lateral_residual(c, Q, eps, xm, carry_nothing, scale)) /
                 (2 * h);
    }
    const Vec5 dx = -J.completeOrthogonalDecomposition().solve(r);
    double t = 1.0;
    Vec5 x_new = x + dx, r_new = lateral_residual(c, Q, eps, x_new, carry_nothing, scale);
    while (!(admissible(eps, x_new) && r_new.norm() < r.norm()) && t > 1e-6) {
      t *= 0.5;
      x_new = x + t * dx;
      r_new = lateral_residual(c, Q, eps, x_new, carry_nothing, scale);
    }
    if (!(admissible(eps, x_new) && r_new.norm() < r.norm())) break;
    x = x_new;
    r = r_new;
  }
  if (r.cwiseAbs().maxCoeff() <= kLateralTolerance) return x;
  throw SimulationError(
      fmt::format("material: the lateral stresses of the uniaxial test at log strain {:.6g} did not vanish "
                  "(largest {:.3g} kb/a after 100 Newton iterations)",
                  eps, r.cwiseAbs().maxCoeff()));
}

}  // namespace

std::vector<MaterialPoint> uniaxial_test(const AnyRodLaw& law, double cell_edge, double rod_area,
                                         const std::array<double, 3>& direction,
                                         const std::vector<double>& turning_points, double increment) {
  CauchyBornCrystal crystal(law, cell_edge, rod_area);
  const Eigen::Vector3d d = unit(direction, "direction");
  check_increment(increment);
  if (turning_points.size() < 2 || turning_points[0] != 0.0)
    throw InputError("material: the uniaxial test needs at least two turning points, the first 0");
  for (double p : turning_points)
    if (!std::isfinite(p) || std::abs(p) > 10.0)
      throw InputError(fmt::format("material: turning point {} is not a log strain in [-10, 10]", p));
  const Eigen::Matrix3d Q = uniaxial_frame(d);
  const double scale = crystal.rod_stiffness() / cell_edge;
  const double mode_modulus = directional_youngs_modulus(crystal.elastic_constants(), d);

  std::vector<MaterialPoint> out;
  Vec5 x;
  x << 1, 1, 0, 0, 0;
  out.push_back(record(crystal, crystal.evaluate(Eigen::Matrix3d::Identity()), Eigen::Matrix3d::Identity(), Q, false,
                       0.0, mode_modulus));
  double peak = 0.0;
  for (double eps : path_strains(turning_points, increment)) {
    std::array<bool, 6> carry_nothing{};
    CrystalTrial t;
    // Solve with the set of broken rods held fixed; a rod the law breaks at the converged
    // state joins the set and the increment is solved again (at most 6 times).
    for (;;) {
      x = solve_lateral(crystal, Q, eps, x, carry_nothing, scale);
      t = crystal.evaluate(uniaxial_F(Q, eps, x), carry_nothing);
      if (!newly_broken(t, crystal, carry_nothing)) break;
    }
    crystal.commit(t);
    out.push_back(record(crystal, t, uniaxial_F(Q, eps, x), Q, false, eps, mode_modulus));
    peak = std::max(peak, out.back().equivalent_stress);
    if (finished(out.back(), peak, crystal.rest_length())) break;
  }
  return out;
}

std::vector<MaterialPoint> simple_shear_test(const AnyRodLaw& law, double cell_edge, double rod_area,
                                             const std::array<double, 3>& direction,
                                             const std::array<double, 3>& normal, double gamma_max, double increment) {
  CauchyBornCrystal crystal(law, cell_edge, rod_area);
  const Eigen::Vector3d s = unit(direction, "shear direction"), m = unit(normal, "plane normal");
  if (std::abs(s.dot(m)) > 1e-12)
    throw InputError(fmt::format("material: the shear direction must lie in the plane (s.m = {:.3g})", s.dot(m)));
  check_increment(increment);
  if (!(gamma_max > 0) || !(gamma_max <= 10.0))
    throw InputError(fmt::format("material: the shear strain to reach must lie in (0, 10], got {}", gamma_max));
  const Eigen::Matrix3d Q = frame(s, m);
  const double mode_modulus = 3.0 * simple_shear_modulus(crystal.elastic_constants(), s, m);

  std::vector<MaterialPoint> out;
  out.push_back(record(crystal, crystal.evaluate(Eigen::Matrix3d::Identity()), Eigen::Matrix3d::Identity(), Q, true,
                       0.0, mode_modulus));
  double peak = 0.0;
  for (double gamma : path_strains({0.0, gamma_max}, increment)) {
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + gamma * s * m.transpose();
    std::array<bool, 6> carry_nothing{};
    CrystalTrial t = crystal.evaluate(F, carry_nothing);
    // The deformation is prescribed: a rod that breaks changes no other rod's strain.
    if (newly_broken(t, crystal, carry_nothing)) t = crystal.evaluate(F, carry_nothing);
    crystal.commit(t);
    out.push_back(record(crystal, t, F, Q, true, gamma, mode_modulus));
    peak = std::max(peak, out.back().equivalent_stress);
    if (finished(out.back(), peak, crystal.rest_length())) break;
  }
  return out;
}

}  // namespace swarf

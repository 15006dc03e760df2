// cauchy_born.h: the bonded FCC crystal under a homogeneous deformation (Cauchy-Born).
//
// The workpiece is an FCC Bravais lattice (cube edge a, nearest-neighbour distance
// l0 = a/sqrt(2)), every nearest-neighbour pair bonded by a rod of cross-section A with the
// rod law (laws/rod_law.h). Under a homogeneous deformation gradient F every atom is a centre
// of inversion symmetry, so the affinely deformed periodic crystal is in equilibrium with no
// relaxation of the atoms, and its Cauchy stress is exactly
//     sigma = 1 / (det(F) a^3/4) * sum_k T_k (r_k (x) r_k) / |r_k|,
// the sum over the 6 rod directions of one atom (each atom has 12 rods, each shared by two
// atoms), r_k = F r0_k, r0_k = a/2 (1,1,0), (1,-1,0), (1,0,1), (1,0,-1), (0,1,1), (0,1,-1),
// T_k = A sigma_rod(eps_k) with the rod strain eps_k = (|r_k| - l0) / l0.
//
// All rods of one direction share one state (their committed shift and broken flag), as the
// engine's rods do: evaluate() is a pure trial from the committed state (quasi-static, strain
// rate 0, so the viscous part is zero), and commit() writes a converged trial back.
#pragma once

#include <Eigen/Dense>
#include <array>

#include "swarf/laws/any_rod_law.h"

namespace swarf {

/// The 6 rod vectors of an FCC atom in units of a/2 (the other 6 are their negatives).
inline constexpr std::array<std::array<int, 3>, 6> kFccBonds{
    {{1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1}, {0, 1, -1}}};

/// The trial response of the crystal to a deformation gradient.
struct CrystalTrial {
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();  ///< Cauchy stress in the lattice frame, Pa
  std::array<double, 6> rod_strain{};               ///< (|r_k| - l0) / l0, 1
  std::array<double, 6> rod_stress{};               ///< sigma_rod of each direction (0 when broken), Pa
  std::array<double, 6> shift{};                    ///< trial shift of each direction, 1
  std::array<bool, 6> broken{};                     ///< trial broken flag (the law's verdict, or already broken)
};

class CauchyBornCrystal {
 public:
  /// 'cell_edge' a (m), 'rod_area' A (m^2). Throws InputError on non-positive lengths or modulus.
  CauchyBornCrystal(const AnyRodLaw& law, double cell_edge, double rod_area);

  /// The trial at F (lattice frame) from the committed state. A rod already broken, or marked in
  /// 'carry_nothing', carries no stress (its trial flag then says broken); the law's own trial
  /// verdict is reported in 'broken' but the rod still carries its trial stress, so that a
  /// caller can hold the set of broken rods fixed while it solves (see lattice_material.cpp).
  CrystalTrial evaluate(const Eigen::Matrix3d& F, const std::array<bool, 6>& carry_nothing = {}) const;
  /// Writes a converged trial's shifts and broken flags back.
  void commit(const CrystalTrial& trial);

  const std::array<double, 6>& shift() const { return shift_; }
  const std::array<bool, 6>& broken() const { return broken_; }
  int broken_count() const;

  double cell_edge() const { return a_; }
  double rest_length() const { return l0_; }  ///< l0 = a/sqrt(2), m
  double rod_area() const { return area_; }
  /// kb = E A / l0, N/m.
  double rod_stiffness() const { return elastic_modulus(law_) * area_ / l0_; }
  const AnyRodLaw& law() const { return law_; }

  /// The small-strain elastic constants (Voigt 6x6, order xx yy zz yz xz xy, Pa) of the intact
  /// crystal: C_ijkl = (1/(a^3/4)) sum_k kb l0^2 n_i n_j n_k n_l. C11 = 2 kb/a, C12 = C44 = kb/a.
  Eigen::Matrix<double, 6, 6> elastic_constants() const;

  /// The smallest distance between an atom and a lattice neighbour not joined to it by an
  /// intact rod, m: second, third and further neighbours (lattice vectors up to 4 a along each
  /// cube axis) and the neighbours of broken rods. The DEM adds a Hertz contact below 2R = l0.
  double closest_unbonded(const Eigen::Matrix3d& F) const;

 private:
  AnyRodLaw law_;  ///< (evaluated six rods at a time, a visit each: not a kernel)
  double a_, l0_, area_;
  std::array<Eigen::Vector3d, 6> r0_;  ///< the rod vectors, m
  std::array<double, 6> shift_{};
  std::array<bool, 6> broken_{};
};

/// Young's modulus along the unit 'direction' from the Voigt constants, 1 / (d.S.d), Pa.
double directional_youngs_modulus(const Eigen::Matrix<double, 6, 6>& C, const Eigen::Vector3d& direction);
/// The simple-shear modulus C_smsm (stress s.sigma.m per shear gamma of F = I + gamma s (x) m at
/// small strain), Pa.
double simple_shear_modulus(const Eigen::Matrix<double, 6, 6>& C, const Eigen::Vector3d& s, const Eigen::Vector3d& m);

}  // namespace swarf

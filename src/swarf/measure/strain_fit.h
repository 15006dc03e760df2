// strain_fit.h: a particle's strain tensor from its rods' axial strains, by least squares.
//
// A rod along the unit vector n feels the normal strain n.E.n = g(n) . [Exx, Eyy, Ezz, Exy, Eyz,
// Exz] of a homogeneous strain E, g(n) = [nx^2, ny^2, nz^2, 2 nx ny, 2 ny nz, 2 nx nz] (the
// normal-strain row). Given values v_k along its rods' directions n_k, the particle's tensor is the
// E minimising sum_k (g_k . E - v_k)^2: the normal equations (sum g g^T) E = sum g v, solved over
// the part the rods determine well (fit_strain). Exact when the rods span the six independent
// directions, as an interior FCC particle's 12 rods do, and the values are those of one tensor.
// Used by the plastic strain the rods hold (particle_fields.h) and by the accumulated plastic
// strain (systems/plastic_strain_system.h), which sums g v over a window of steps.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "swarf/core/periodic.h"
#include "swarf/core/sym_tensor.h"
#include "swarf/core/vec3.h"
#include "swarf/state/rods.h"

namespace swarf {

using Vec6 = Eigen::Matrix<double, 6, 1>;

/// The coefficients g of a normal strain along the unit vector n: n.E.n = g . [Exx, Eyy, Ezz, Exy, Eyz, Exz].
inline Vec6 normal_strain_row(const Vec3& n) {
  Vec6 g;
  g << n[0] * n[0], n[1] * n[1], n[2] * n[2], 2 * n[0] * n[1], 2 * n[1] * n[2], 2 * n[0] * n[2];
  return g;
}

using Mat6 = Eigen::Matrix<double, 6, 6>;

/// Adds particle i's intact rods (its row of the rod lists 'row_start', 'entries': Rods' own or
/// a copy) to its normal equations at the positions x: normal += g g^T and rhs += g value(k) for
/// each intact rod k, g of the rod's current direction (the nearest image under 'periodic').
template <class Value>
void add_rods_to_fit(const std::vector<Vec3>& x, const Rods& r, const Periodic& periodic,
                     const std::vector<std::int32_t>& row_start, const std::vector<Rods::Entry>& entries, std::size_t i,
                     Mat6& normal, Vec6& rhs, Value&& value) {
  for (std::int32_t q = row_start[i]; q < row_start[i + 1]; ++q) {
    const std::int32_t k = entries[q].rod;
    if (!r.intact[k]) continue;
    Vec3 d = x[r.ends[k][1]] - x[r.ends[k][0]];
    periodic.wrap(d);
    const double len = d.norm();
    if (len <= 0) continue;
    const Vec6 g = normal_strain_row(d / len);
    normal += g * g.transpose();
    rhs += g * value(k);
  }
}

/// The least-squares strain tensor of the normal equations normal E = rhs (normal = sum g g^T,
/// rhs = sum g v over the rods), as xx, yy, zz, xy, yz, xz. Through the normal matrix's
/// eigenvectors, keeping those it determines well: an eigenvalue below 0.05 of the largest (rods
/// nearly parallel, or fewer than 6 directions) is dropped rather than inverted, which bounds each
/// kept component by the rods' rms value / sqrt(0.05). An interior FCC particle's smallest ratio is
/// 1/4, so it keeps all six (the fit is exact there). Zero for a zero rhs.
SymTensor fit_strain(const Mat6& normal, const Vec6& rhs);

/// The same least squares over the trace-free tensors (E = T y, T an orthonormal basis of the
/// deviators in the tensor norm, the normal equations T^T normal T y = T^T rhs), keeping the
/// eigenvalues above 'well_determined' of the largest: for increments of plastic flow, which is
/// isochoric. Better conditioned than fit_strain when the rods crowd towards one direction: a
/// lattice sheared by gamma 2 keeps all five components above 0.03 of the largest, where the
/// six-component matrix's smallest has fallen to 0.002 (the FCC lattice's volumetric direction is
/// an eigenvector of its normal matrix, so there a volumetric part does not leak into the fit).
SymTensor fit_deviatoric_strain(const Mat6& normal, const Vec6& rhs, double well_determined);

/// The von Mises equivalent strain sqrt(2/3 e:e) of a strain tensor (e its deviator), 1.
double equivalent_strain(const SymTensor& strain);

}  // namespace swarf

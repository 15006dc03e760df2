// density_floor.h: a particle whose neighbourhood has lost more than a set share of its volume
// pushes back with the material's bulk modulus (rod.compaction_modulus).
//
// A rod yields by its axial stress, so a bonded pair's only resistance in compression is its rod,
// whose force stops at its flow stress times A: in the cut, pressed pairs flow onto each other and
// the chip ends 1.5-1.8 times as dense as the workpiece (validation/cutting/compaction/). A
// metal's volume change is elastic whatever its plastic flow, so its pressure grows with the bulk
// modulus K and never stops at a flow stress. This adds that response as an elastic energy per
// particle, a function of its neighbours' distances alone, the form of the embedded-atom method
// (Daw and Baskes 1984, Phys Rev B 29:6443: E_i = F(rho_i), rho_i = sum_j f(r_ij)):
//
//   rho_i   = sum_j w(L_ij / l_ij)        over every particle j within s_c l_ij, l_ij = r_i + r_j
//   theta_i = -(rho_i - 12 w(1)) / 4      the volume change (1)
//   U_i     = 1/2 K V_i min(theta_i + theta_0, 0)^2,   V_i = 4 sqrt(2) r_i^3 (an FCC site's volume)
//
// with w(s) = u - tau/2 for u = s_c - s >= tau, u^2 / (2 tau) for 0 <= u < tau, 0 beyond: slope
// -1 up to s_c - tau and a smooth end. For a particle of the lattice with its 12 neighbours
// strained uniformly by eps, rho_i - 12 w(1) = -3 tr(eps) to first order (sum_k n_k n_k^T = 4 I),
// so theta_i is the volume strain; a shear keeps it to first order and reads as a dilation at
// second (the pairs it stretches lengthen more than those it shortens shorten), so the floor does
// not act on a shear. Whether a pair is bonded does not enter: neither a rod's breaking nor its forming nor a
// neighbour exchange moves U, so the energy is a function of the positions alone (a rod-based
// measure jumps at every exchange, which turns each into a source of energy: the compaction
// README). A particle with fewer neighbours than the lattice's (a free surface) reads as
// dilated and feels nothing. Below theta_0 (the onset) nothing acts either, so the lattice's
// calibrated elastic response is untouched. The force is -grad U, a pair force along each pair,
//
//   force on j (along e_ij, away from i) = -(|w'(s_ij)| / (4 l_ij)) K (V_i g_i + V_j g_j),  g = min(theta + theta_0, 0)
//
// Most particles of a cut are far from the onset (the elastic workpiece): between two builds of the
// lists, a particle whose rho at the build plus what its and its neighbours' displacements since
// could have added (w is 1-Lipschitz in s) stays below the onset is not summed; its g is 0, as its sum
// would give to the bit, so the results are the same.
//
// Neighbours come from the floor's own lists (cells of the cut-off plus a skin, rebuilt when a
// particle has moved half the skin), each particle's list in index order; each particle sums its
// own list, so every pair is evaluated by both its ends from the same numbers (Newton's third law
// to the bit) and the sums do not depend on the threads.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/core/periodic.h"
#include "swarf/core/vec3.h"

namespace swarf {

/// The kernel's end s_c and taper tau (in units of r_i + r_j).
inline constexpr double kFloorReach = 1.15, kFloorTaper = 0.05;

/// w(s) and -w'(s) of the kernel above.
inline double floor_weight(double s) {
  const double u = kFloorReach - s;
  return u >= kFloorTaper ? u - 0.5 * kFloorTaper : (u > 0.0 ? 0.5 * u * u / kFloorTaper : 0.0);
}
inline double floor_slope(double s) {
  const double u = kFloorReach - s;
  return u >= kFloorTaper ? 1.0 : (u > 0.0 ? u / kFloorTaper : 0.0);
}

class DensityFloor {
 public:
  /// Evaluates the floor for n particles at x with radii 'radius': the per-particle forces (N)
  /// and energies (J), with bulk modulus K (Pa) and onset theta_0 (1).
  void evaluate(const Vec3* x, const double* radius, std::size_t n, Periodic periodic, double K, double onset);
  /// The forces of the last evaluation, per particle (N).
  const Vec3* force() const { return force_.data(); }
  /// theta_i of the last evaluation (1); for a particle the bound below proved inactive, a lower bound
  /// of it, at least -theta_0.
  const std::vector<double>& dilatation() const { return theta_; }
  /// Every particle's rho summed at every evaluation, without the bound (the tests' reference).
  void always_exact(bool on) { exact_ = on; }
  /// sum_i U_i of the last evaluation, in particle order (J).
  double energy() const;
  /// The lists are built again at the next evaluation (the particles changed).
  void invalidate() { x_build_.clear(); }

 private:
  void build(const Vec3* x, const double* radius, std::size_t n, Periodic periodic);
  std::vector<Vec3> x_build_;            // positions at the last build
  std::vector<double> rho_ref_, moved_;  // rho_i at the build; |x_i - x_build_i| (m)
  bool exact_ = false;
  std::vector<std::int32_t> start_, nb_;  // per particle, its neighbours (both directions, ascending)
  double skin_ = 0.0;                     // m
  double inv_l_ = 0.0;                    // 1 / (2 r_min) at the build, 1/m (the radii do not change)
  std::vector<double> theta_, a_, u_;     // theta_i; K V_i g_i (N m); U_i (J)
  std::vector<Vec3> force_;
};

}  // namespace swarf

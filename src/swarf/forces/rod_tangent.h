// rod_tangent.h: the rods' part of the Newmark step's Jacobian, matrix-free (Newton solver).
//
// The Newton solve of the implicit step (integrate/newton.cpp) needs products of
// J = M + beta h^2 K + gamma h C with a vector d of acceleration corrections. For one rod k
// between particles i and j, with unit axis n (i to j), current length L, rest length L0 and
// force coefficient c (force on i = c (x_j - x_i), so c = T / L with T the axial force):
//   K_k = (E_t A / L0 - c) n n^T + c I     (axial tangent and the geometric part c (I - n n^T))
//   C_k = (eta A / L0) n n^T               (the viscous stress eta n.(v_j - v_i) / L0)
// E_t is the slope of the rod law's branch in the latest evaluation (its trial state): E
// when the trial kept the committed shift, the plastic branch's slope (plastic_tangent: k, or
// the hardening curve's E H / (E + H)) when the trial moved it
// (plastic flow); a rod broken in the trial carries nothing. The law's tangent() gives E_t and
// the rate slope that replaces eta in C_k (eta, or more for a rate-hardening law); a law whose
// tangent reads the trial's strain and rate (kTangentReadsMotion) gets them from x and v; a
// rate-scaled law (Johnson-Cook) whose factor the kernel read at the step start's rate (rate_x,
// rate_v: Newton's lagged rate) gets E_t at that factor and no rate term (tangent_at_scale).
// The viscous stress also depends on the positions through n; that term is left out (it is not symmetric and is of the
// order of the strain rate times h; Newton then converges linearly on damped 3-D motion instead of quadratically, and
// exactly on the axial motion the tests check).
//
// The per-rod block S_k = beta h^2 K_k + gamma h C_k = lateral I + axial n n^T is set up once
// per Newton iteration (rod_tangent_setup) and applied in every Krylov iteration particle by
// particle, in the rows' fixed order (rod_block_times):
//   (J d)_i = m_i d_i - sum over i's rods of S_k (d_other - d_i).
// Each rod is thus applied from both ends; the two results are exact negatives of each other
// (every operation is odd in u), so Newton's third law holds bit for bit, and the product
// needs no per-rod store and no second pass.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "swarf/core/periodic.h"
#include "swarf/core/vec3.h"
#include "swarf/laws/any_rod_law.h"

namespace swarf {

/// What the tangent set-up reads (the latest rod evaluation) and writes (the per-rod blocks).
struct RodTangentView {
  std::size_t rods = 0;
  const std::array<std::int32_t, 2>* ends = nullptr;
  const double* rest_length = nullptr;         ///< m
  const double* shift = nullptr;               ///< committed plastic shift, 1
  const double* trial_shift = nullptr;         ///< of the latest evaluation, 1
  const std::uint8_t* intact = nullptr;        ///< committed
  const std::uint8_t* trial_broken = nullptr;  ///< of the latest evaluation
  const double* coef = nullptr;                ///< of the latest evaluation, N/m
  const Vec3* x = nullptr;                     ///< positions of that evaluation, m
  const Vec3* v = nullptr;                     ///< velocities of that evaluation, m/s (read only by a law
                                               ///< whose tangent depends on the rate)
  const double* temperature = nullptr;         ///< particle temperatures, K (0 = not set); nullptr: none (T_ref);
                                               ///< read by a law with kReadsTemperature
  Vec3* axis = nullptr;                        ///< out: unit axis n, 1
  double* axial = nullptr;                     ///< out: coefficient of n n^T in S_k, kg
  double* lateral = nullptr;                   ///< out: coefficient of I in S_k, kg
  /// The rate factor's positions and velocities (RodKernelView::rate_x), m and m/s; given, a
  /// rate-scaled law's factor is held at the rate they give and has no rate term.
  const Vec3* rate_x = nullptr;
  const Vec3* rate_v = nullptr;
};

/// Sets up S_k = kx K_k + kv C_k for every rod (kx = beta h^2 in s^2, kv = gamma h in s),
/// in parallel over rods (each rod's values depend on nothing else); the law is visited once.
void rod_tangent_setup(const AnyRodLaw& law, double area, double kx, double kv, const RodTangentView& view,
                       Periodic periodic);

/// S_k u = lateral u + axial (n . u) n, in N (u in m/s^2, the coefficients in kg).
inline Vec3 rod_block_times(const Vec3& n, double axial, double lateral, const Vec3& u) {
  return lateral * u + (axial * n.dot(u)) * n;
}

}  // namespace swarf

// newton_newmark.h: the scratch of the Newton-Krylov solve of the Newmark step.
//
// integrate::newton_try (newton.cpp) solves the step's residual in the new
// accelerations a,  R(a) = M a - F(x(a), v(a)),  with
//   x = x_n + h v_n + h^2 ((1/2 - beta) a_n + beta a),  v = v_n + h ((1 - gamma) a_n + gamma a),
// by Newton: J d = -R with J = M + beta h^2 K + gamma h C (forces/rod_tangent.h), solved by
// conjugate gradients with a 3x3 block-Jacobi preconditioner per particle, matrix-free (or a
// preconditioner handed in that reads J assembled: tangent_matrix.h).
// Prescribed components are removed: their rows and columns of J are dropped (d = 0 there).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "swarf/core/vec3.h"
#include "swarf/integrate/tangent_matrix.h"

namespace swarf {

/// Counters of the Newton solver (not part of the state: diagnostics only).
struct NewtonStats {
  std::int64_t solves = 0;             ///< Newton iterations (linear solves), rejected steps included
  std::int64_t tangent_products = 0;   ///< products J d (one per CG iteration)
  std::int64_t krylov_iterations = 0;  ///< CG iterations
  std::int64_t indefinite = 0;         ///< steps rejected because CG met d^T J d <= 0
  std::int64_t krylov_capped = 0;      ///< linear solves stopped at krylov_max_iterations
  int last_krylov = 0;                 ///< CG iterations of the last accepted step (all its solves)
  bool last_capped = false;            ///< a solve of the last accepted step hit krylov_max_iterations
};

/// Per-rod and per-particle arrays of the solve, sized on first use.
struct NewtonWork {
  std::vector<Vec3> residual;       ///< R_i (free components; 0 where prescribed), N
  std::vector<Vec3> d, r, z, p, q;  ///< CG: solution (m/s^2), residual and preconditioned residual (N, m/s^2),
                                    ///< direction (m/s^2), J p (N)
  std::vector<Eigen::Matrix3d> block_inverse;  ///< inverse of particle i's diagonal block of J, 1/kg
  std::vector<Vec3> axis;                      ///< per rod: unit axis
  std::vector<double> axial, lateral;          ///< per rod: coefficients of S_k, kg
  double level2 = 0.0;                         ///< squared force level of the latest residual, N^2
  /// A preconditioner that reads the assembled J in place of the block-Jacobi (none: block-Jacobi;
  /// Simulation::set_newton_preconditioner), and J assembled for it.
  std::shared_ptr<LinearPreconditioner> preconditioner;
  TangentMatrix matrix;
  // The rods' trial state at the start of the step (restored with the particles when a
  // step is rejected, so that a rejected try leaves the state hash as it was).
  std::vector<double> trial_shift, stress, coef;
  std::vector<std::uint8_t> trial_broken;
};

}  // namespace swarf

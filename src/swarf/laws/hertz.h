// hertz.h: the Hertz normal contact law with restitution damping, and its parameters
// (paper eqs. 14-16; docs/physics.md section 5).
//
//   F = K delta^(3/2) + alpha sqrt(m* K) delta^(1/4) d(delta)/dt,   F >= 0 (no adhesion)
//   K = 4/3 E* sqrt(R*),  1/E* = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j,  1/R* = 1/R_i + 1/R_j,
//   1/m* = 1/m_i + 1/m_j.
// The paper's damping D is taken proportional to delta^(1/4) (Tsuji et al. 1992): with it
// the dimensionless impact x'' = -x^(3/2) - alpha x^(1/4) x' (x = delta/delta*, delta* =
// (m* v^2/K)^(2/5)) does not depend on the impact speed, so one alpha gives one coefficient
// of restitution e at every speed. alpha(e) is found once by integrating that equation and
// bisecting (restitution_to_alpha); tests check e by real impacts at several speeds.
// A wall (triangle mesh) is a body of infinite radius and mass with its own E and nu:
// K = 4/3 E* sqrt(R), m* = m (the Hertz convention for a sphere on a half-space, the one
// Chung and Ooi's analytic solutions use; the paper's eq. 17 instead treats the wall as a
// mirror sphere and is softer by a factor 2 sqrt(2)).
#pragma once

#include <cmath>

namespace swarf {

struct HertzLaw {
  double stiffness = 0;  ///< K, N/m^1.5
  double damping = 0;    ///< alpha sqrt(m* K), N s/m^1.25

  /// Normal force (positive = repulsive), N, for overlap delta > 0 (m) and its rate (m/s,
  /// positive when approaching).
  double force(double delta, double delta_rate) const {
    const double root = std::sqrt(delta);
    return force(delta, root, std::sqrt(root), delta_rate);
  }
  /// The same with the roots delta^(1/2) and delta^(1/4) given (the contact kernels reuse them).
  double force(double delta, double root, double root4, double delta_rate) const {
    const double f = stiffness * delta * root + damping * root4 * delta_rate;
    return f > 0.0 ? f : 0.0;
  }
};

/// 1/E* of two materials (E in Pa); E = inf makes a rigid body.
inline double inverse_effective_modulus(double E1, double nu1, double E2, double nu2) {
  return (1.0 - nu1 * nu1) / E1 + (std::isfinite(E2) ? (1.0 - nu2 * nu2) / E2 : 0.0);
}

/// The damping coefficient alpha (1) that gives restitution e in [0.01, 1] for the law above.
double restitution_to_alpha(double e);

/// The restitution of a dimensionless impact with damping alpha (integrated with RK4).
double alpha_to_restitution(double alpha);

}  // namespace swarf

// rotation.h: rigid rotation of a particle with unit quaternions (paper eqs. 2-7, 12-13;
// docs/physics.md sections 9, 7 and 8).
//
// State per particle: orientation q = [q0 q1 q2 q3] (body to world), body-frame angular
// velocity w and acceleration dw, principal inertia I = (Ix, Iy, Iz). Kinematics:
//     dq/dt   = 1/2 q (x) [0, w]                                   (5)-(6)
//     d2q/dt2 = 1/2 (dq/dt (x) [0, w] + q (x) [0, dw])             (7)
// and Euler's equations in the principal frame, with the torque l rotated into the body:
//     dwx = (lx + wy wz (Iy - Iz)) / Ix,  dwy = (ly + wz wx (Iz - Ix)) / Iy,
//     dwz = (lz + wx wy (Ix - Iy)) / Iz        (the paper's third row divides by Ix: a typo)
// The Newmark update (12)-(13) is applied to the four quaternion coefficients; the unit norm
// is restored by scaling q (the paper's variant). Because dw depends on w (gyroscopic terms)
// and w on dq/dt, the update is implicit even for a given torque: an inner fixed-point loop
// makes q, dq/dt, w, dw consistent. beta = 0, gamma = 1/2 is the explicit (velocity-Verlet
// form) variant that the explicit scheme uses, with the same inner loop for the velocity.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "swarf/core/quat.h"
#include "swarf/core/vec3.h"

namespace swarf {

/// Euler's equations (4) solved for dw (body frame); 'torque_body' in N m, inertia in kg m^2.
inline Vec3 euler_acceleration(const Vec3& torque_body, const Vec3& w, const Vec3& I) {
  return Vec3((torque_body[0] + w[1] * w[2] * (I[1] - I[2])) / I[0],
              (torque_body[1] + w[2] * w[0] * (I[2] - I[0])) / I[1],
              (torque_body[2] + w[0] * w[1] * (I[0] - I[1])) / I[2]);
}

/// dq/dt and d2q/dt2 from q, w, dw (eqs. 6, 7).
inline Quat qdot(const Quat& q, const Vec3& w) { return 0.5 * qmul(q, pure(w)); }
inline Quat qddot(const Quat& q, const Vec3& w, const Vec3& dw) {
  return 0.5 * (qmul(qdot(q, w), pure(w)) + qmul(q, pure(dw)));
}
/// Body angular velocity from q and dq/dt: [0, w] = 2 q* (x) dq/dt (for unit q).
inline Vec3 body_rate(const Quat& q, const Quat& dq) { return 2.0 * vec(qmul(qconj(q), dq)); }

/// One particle's rotational state.
struct RotState {
  Quat q{1.0, 0.0, 0.0, 0.0};
  Vec3 w = Vec3::Zero();   ///< body frame, rad/s
  Vec3 dw = Vec3::Zero();  ///< body frame, rad/s^2
};

struct RotationSettings {
  double beta = 0.25;
  double gamma = 0.5;
  double tolerance = 1e-12;  ///< relative change of d2q/dt2 at which the inner loop stops
  int max_iterations = 50;
};

/// Result of the inner loop: the new state and how many sweeps it took (converged or not).
struct RotStepResult {
  RotState state;
  int iterations = 0;
  bool converged = false;
};

/// Advances one particle's rotation by dt under a torque given in the WORLD frame and held
/// fixed over the inner loop (the outer, force loop re-evaluates torques).
RotStepResult rotation_step(const RotState& s, const Vec3& torque_world, const Vec3& inertia, double dt,
                            const RotationSettings& rs);

/// The same update for a body with isotropic inertia I = 1/inv_I (a sphere), in the WORLD frame:
/// there dw/dt = l/I holds in any frame, so no inner loop is needed. w and dw are world-frame;
/// the orientation turns by the mean rate over the step (second order). 'turn' false leaves q
/// as it is: nothing in a sphere's dynamics depends on its orientation.
inline void sphere_rotation_step(Quat& q, Vec3& w, Vec3& dw, const Vec3& torque_world, double inv_I, double h,
                                 double gamma, bool turn = true) {
  const Vec3 dw_new = inv_I * torque_world;
  const Vec3 w_new = w + h * ((1.0 - gamma) * dw + gamma * dw_new);
  const Vec3 mid = 0.5 * (w + w_new);
  const double t2 = 0.25 * h * h * mid.squaredNorm();  // (half the turn angle)^2
  if (turn && t2 > 0.0) {
    double c, s_over_rate;  // cos(half), sin(half)/|mid|
    if (t2 < 1e-4) {
      // Small turns (the usual case) by their Taylor series, no division or root: the
      // truncation is below half^6/5040 < 2e-16.
      // (Products with the reciprocals instead of divisions: validation/bench/README.md.)
      c = 1.0 - t2 * (0.5 - t2 * (1.0 / 24.0));
      s_over_rate = 0.5 * h * (1.0 - t2 * (1.0 / 6.0 - t2 * (1.0 / 120.0)));
    } else {
      const double half = std::sqrt(t2);
      c = std::cos(half);
      s_over_rate = 0.5 * h * std::sin(half) / half;
    }
    const Vec3 axis = s_over_rate * mid;
    q = qmul(Quat(c, axis[0], axis[1], axis[2]), q);
    // |q|^2 = 1 + e with e at rounding level; one Newton step for 1/sqrt restores |q| = 1
    // to O(e^2) without a root.
    q *= 0.5 * (3.0 - q.squaredNorm());
  }
  w = w_new;
  dw = dw_new;
}

/// Kinetic energy of rotation, J, and angular momentum in the world frame, N m s.
inline double rotational_energy(const RotState& s, const Vec3& I) {
  return 0.5 * (I[0] * s.w[0] * s.w[0] + I[1] * s.w[1] * s.w[1] + I[2] * s.w[2] * s.w[2]);
}
inline Vec3 angular_momentum_world(const RotState& s, const Vec3& I) { return to_world(s.q, I.cwiseProduct(s.w)); }

}  // namespace swarf

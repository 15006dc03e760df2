// rotation.cpp: the rotational Newmark update with its inner fixed-point loop (see rotation.h).
#include "swarf/laws/rotation.h"

#include <cmath>

namespace swarf {

RotStepResult rotation_step(const RotState& s, const Vec3& torque_world, const Vec3& inertia, double dt,
                            const RotationSettings& rs) {
  const double b = rs.beta, g = rs.gamma;
  const Quat dq_n = qdot(s.q, s.w);
  const Quat ddq_n = qddot(s.q, s.w, s.dw);
  // Parts of the update that do not depend on the new d2q/dt2.
  const Quat q_pred = s.q + dt * dq_n + (dt * dt * (0.5 - b)) * ddq_n;
  const Quat dq_pred = dq_n + (dt * (1.0 - g)) * ddq_n;
  RotStepResult out;
  Quat ddq = ddq_n;  // initial guess: the old second derivative
  for (int it = 1; it <= rs.max_iterations; ++it) {
    const Quat q = q_pred + (b * dt * dt) * ddq;
    const Quat dq = dq_pred + (g * dt) * ddq;
    const Quat qu = q / q.norm();  // unit orientation for the frame change
    const Vec3 w = body_rate(qu, dq);
    const Vec3 dw = euler_acceleration(to_body(qu, torque_world), w, inertia);
    const Quat ddq_new = qddot(qu, w, dw);
    const double change = (ddq_new - ddq).norm();
    const double scale = ddq_new.norm() + dq.norm() / dt * 1e-12;  // guards the torque-free rest state
    ddq = ddq_new;
    out.iterations = it;
    out.state.q = qu;  // the paper's variant: restore |q| = 1 by scaling
    out.state.w = w;
    out.state.dw = dw;
    if (change <= rs.tolerance * scale || change == 0.0) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace swarf

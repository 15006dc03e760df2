// friction.h: the tangential contact law, a pure function of the relative tangential
// velocity, the committed history and the normal force (docs/physics.md section 5).
//
// Three laws: none; Cundall-Strack (a tangential spring with a dashpot, capped by Coulomb,
// whose stretch is the contact's history, committed with the step); regularized Coulomb
// (mu fn tanh(|vt|/v0), no history).
#pragma once

#include <algorithm>
#include <cmath>

#include "swarf/core/vec3.h"
#include "swarf/laws/speed_friction.h"

namespace swarf {

enum class FrictionLaw { None, Spring, Regularized };

struct FrictionRule {
  FrictionLaw law;
  double mu;  // 1
  double v0;  // regularization speed, m/s
  double h;   // step, s
};

// The rule with the tool's mu at the sliding speed |vt| when a table is given (speed_friction.h);
// the rule itself otherwise (no square root then).
[[gnu::always_inline]] inline FrictionRule at_sliding_speed(const FrictionRule& r, const SpeedFriction& table,
                                                            const Vec3& vt) {
  FrictionRule out = r;
  if (table.points > 0) out.mu = friction_at_speed(table, r.mu, vt.norm());
  return out;
}

// Tangential force on body j from the relative tangential velocity vt (j relative to i, m/s),
// the committed history 'hist' (m) and the normal force fn (N), with the tangential stiffness
// kt (N/m) and dashpot eta (N s/m); returns the trial history through 'hist'. 'stick' (N)
// caps the force below Coulomb's mu fn where it is smaller (the sticking cap, sticking.h).
[[gnu::always_inline]] inline Vec3 friction_force(const FrictionRule& r, const Vec3& n, const Vec3& vt, double fn,
                                                  double kt, double eta, Vec3& hist, double stick = HUGE_VAL) {
  if (r.law == FrictionLaw::None || r.mu == 0.0) {
    hist = Vec3::Zero();
    return Vec3::Zero();
  }
  if (r.law == FrictionLaw::Regularized) {
    hist = Vec3::Zero();
    const double s = vt.norm();
    if (s == 0.0) return Vec3::Zero();
    return (-std::min(r.mu * fn, stick) * std::tanh(s / r.v0) / s) * vt;
  }
  // Cundall-Strack spring with a dashpot: the history, kept in the tangent plane, grows
  // with the slip; when the force exceeds Coulomb's cap the spring is reset to it.
  Vec3 xi = hist - hist.dot(n) * n + r.h * vt;
  Vec3 ft = -kt * xi - eta * vt;
  const double cap = std::min(r.mu * fn, stick), f2 = ft.squaredNorm();
  if (f2 > cap * cap) {
    ft *= cap / std::sqrt(f2);
    xi = kt > 0.0 ? Vec3(-(ft + eta * vt) / kt) : Vec3::Zero();
  }
  hist = xi;
  return ft;
}

// The tangent of friction_force for the Newton solver: the scalar t of d(ft on i)/d(v_j - v_i)
// = t (I - n n^T), in N s/m, at the same state as friction_force. Spring law while the spring
// sticks: the slip h vt stretches it, t = kt h + eta; once Coulomb's cap binds the force no
// longer grows with the slip in its own direction, and t = 0 (the turn of its direction and
// its growth with fn are left out: an approximate tangent, which Newton's residual test
// corrects). Regularized law: the secant mu fn tanh(s/v0) / s, its limit mu fn / v0 at s = 0.
[[gnu::always_inline]] inline double friction_tangent(const FrictionRule& r, const Vec3& n, const Vec3& vt, double fn,
                                                      double kt, double eta, const Vec3& hist,
                                                      double stick = HUGE_VAL) {
  if (r.law == FrictionLaw::None || r.mu == 0.0 || fn <= 0.0) return 0.0;
  if (r.law == FrictionLaw::Regularized) {
    const double s = vt.norm(), u = s / r.v0;
    return std::min(r.mu * fn, stick) * (u > 1e-8 ? std::tanh(u) / s : 1.0 / r.v0);
  }
  const Vec3 xi = hist - hist.dot(n) * n + r.h * vt;
  const Vec3 ft = -kt * xi - eta * vt;
  const double cap = std::min(r.mu * fn, stick);
  return ft.squaredNorm() > cap * cap ? 0.0 : kt * r.h + eta;
}

}  // namespace swarf

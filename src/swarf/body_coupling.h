// body_coupling.h: co-simulation of one rigid body with an outside (multibody) code.
//
// The outside code owns the body's motion; swarf owns the particles. Each exchange (a macro
// step of the outside code, H) goes:
//   1. the outside code says where the body's centre of mass is at the end of the macro step;
//   2. swarf moves the body there at the constant (secant) velocity (end - start) / H, taking
//      as many of its own steps as its step control needs (sub-cycling: Verlet takes
//      round(H / dt) steps of dt and sets the velocity so that they land on the end point;
//      Newmark steps until the end time, its last step shortened);
//   3. swarf returns the impulse and the angular impulse (about the centre of mass) the
//      particles gave the body over the macro step: per step h (F + F+) / 2, the trapezoid of
//      the body's contact force at the step's start and end, which is exactly what both
//      schemes (gamma = 1/2) give the particles with the opposite sign.
// The outside code applies the mean force impulse / H over its next macro step (the exchanged
// force is held, the position interpolated linearly). So momentum crosses the interface
// exactly: the particles' momentum plus the outside body's plus the impulse not yet applied is
// constant to rounding. Energy does not, exactly: the particles receive the work F.dX of the
// macro step in which the force acted, the outside body the same force over the next step's
// displacement; the difference per exchange is F . (dX_{n+1} - dX_n), about F a H^2, so the
// interface's energy error over a fixed time is first order in H (tests/test_body_coupling.cpp
// measures it). A body driven so is held: its translation fixed ("xyz") and its rotation
// prescribed at zero (the outside code's body translates; a turning body would need the
// orientation handed over too, which this interface does not do yet).
#pragma once

#include <cstddef>

#include "swarf/core/vec3.h"

namespace swarf {

class Simulation;

/// What one exchange returns.
struct BodyExchange {
  double duration = 0;                  ///< the macro step swarf took, s (Verlet: a whole number of steps)
  int steps = 0;                        ///< swarf's steps in it
  Vec3 impulse = Vec3::Zero();          ///< the particles' impulse on the body, N s
  Vec3 angular_impulse = Vec3::Zero();  ///< about the body's centre of mass, N m s
  Vec3 work = Vec3::Zero();             ///< per component: sum of h (F + F+)/2 . dx over the steps, J
  /// The force to hold over the outside code's next macro step, N.
  Vec3 mean_force() const { return duration > 0 ? Vec3(impulse / duration) : Vec3::Zero(); }
};

class BodyCoupling {
 public:
  /// Couples body 'body' of the simulation's World (held by reference). Refuses (InputError) a
  /// body that is not held: translation fixed in x, y and z and rotation prescribed at zero.
  BodyCoupling(Simulation& sim, std::size_t body);

  /// Moves the body to 'position_end' (m, its centre of mass) over 'duration' (s) and steps
  /// the particles with it. Throws InputError for a duration that is not finite and positive.
  BodyExchange advance(const Vec3& position_end, double duration);

 private:
  Simulation& sim_;
  std::size_t body_;
};

}  // namespace swarf

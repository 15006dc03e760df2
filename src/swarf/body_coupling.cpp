// body_coupling.cpp: one exchange of the co-simulation (see body_coupling.h).
#include "swarf/body_coupling.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"
#include "swarf/simulation.h"

namespace swarf {

BodyCoupling::BodyCoupling(Simulation& sim, std::size_t body) : sim_(sim), body_(body) {
  const auto& bodies = sim.world().bodies;
  if (body >= bodies.size())
    throw InputError(fmt::format("co-simulation: body {} of {} does not exist", body, bodies.size()));
  const RigidBody& rb = bodies[body];
  const std::string& name = sim.world().meshes[rb.mesh].name;
  if (rb.fixed != 7 || rb.rotation != BodyRotation::Prescribed || rb.state.omega.norm() != 0.0)
    throw InputError(
        fmt::format("co-simulation: rigid body '{}' must be held for an outside code to drive it: fixed = \"xyz\" and "
                    "rotation = \"prescribed\" with no angular velocity",
                    name));
}

BodyExchange BodyCoupling::advance(const Vec3& position_end, double duration) {
  // (the bit test first: an ordered comparison with a NaN raises FE_INVALID)
  if (!finite_bits(duration) || !(duration > 0.0))
    throw InputError(
        fmt::format("co-simulation: a macro step of {} s; it must be a finite positive time", nan_safe(duration)));
  if (!all_finite(position_end))
    throw InputError(fmt::format("co-simulation: the body's end position ({}, {}, {}) m is not finite", position_end[0],
                                 position_end[1], position_end[2]));
  RigidBody& rb = sim_.world().bodies[body_];
  const Vec3 start = rb.state.position;
  BodyExchange ex;
  const double t0 = sim_.time();
  // Verlet's step is fixed: a whole number of them, the velocity chosen to land on the end.
  const bool fixed_step = !sim_.implicit();
  const long n = fixed_step ? std::max(1L, std::lround(duration / sim_.dt())) : 0;
  const double span = fixed_step ? double(n) * sim_.dt() : duration;  // s
  rb.state.velocity = (position_end - start) / span;
  Vec3 f = rb.contact_force, tq = rb.contact_torque;  // the last evaluation's: the step's start
  const double t_end = t0 + span;
  // (Newmark: until the end time to rounding; a last step of a millionth of the macro step
  // would only be rounding's)
  for (long k = 0; fixed_step ? k < n : t_end - sim_.time() > 1e-9 * span; ++k) {
    const Vec3 x = rb.state.position;
    const double before = sim_.time();
    sim_.step(fixed_step ? std::numeric_limits<double>::infinity() : t_end - before);
    const double h = sim_.time() - before;
    ex.impulse += 0.5 * h * (f + rb.contact_force);
    ex.angular_impulse += 0.5 * h * (tq + rb.contact_torque);
    ex.work += (0.5 * (f + rb.contact_force)).cwiseProduct(rb.state.position - x);
    f = rb.contact_force;
    tq = rb.contact_torque;
    ++ex.steps;
  }
  // (the secant velocity lands on the end to rounding; the next exchange starts from where the
  // body is, so the rounding does not add up over exchanges)
  ex.duration = sim_.time() - t0;
  return ex;
}

}  // namespace swarf

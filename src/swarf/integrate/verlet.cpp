// verlet.cpp: the explicit step, velocity Verlet (Newmark's beta 0, gamma 1/2): one evaluation
// per step, the kick fused with the gather (see integration.h).
#include <fmt/format.h>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/integrate/integration.h"

namespace swarf::integrate {

namespace {

// Names the particle that moved too far (or the first non-finite one) and the step.
[[noreturn]] void throw_too_far(const Integration& it, double h) {
  const World& world = it.world;
  const auto& p = world.particles;
  const double limit = it.set.max_step_displacement;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 v = p.velocity[i];
    const double moved = v.norm() * h / p.radius[i];
    if (!(moved <= limit) || !all_finite(p.position[i]))
      throw SimulationError(fmt::format(
          "unstable: particle {} (at {:.6g}, {:.6g}, {:.6g} m) moved {:.3g} radii in step {} at t = {:.6g} s "
          "(limit integrator.max_step_displacement = {}); speed {:.4g} m/s. The step dt = {:.4g} s may be "
          "too large for the loads, or the input drives the lattice too hard",
          i, p.position[i][0], p.position[i][1], p.position[i][2], moved, it.stats.accepted + 1, it.t + h, limit,
          v.norm(), h));
  }
  throw SimulationError(
      fmt::format("unstable: non-finite state in step {} at t = {:.6g} s", it.stats.accepted + 1, it.t + h));
}

}  // namespace

void verlet_step(Integration& it, double h) {
  World& world = it.world;
  it.clock.start();
  if (!prescribe(it, h))
    it.sys.bodies.throw_mesh_too_far(world, it.t, h, it.stats.accepted + 1, it.set.max_step_displacement);
  if (!world.bodies.empty() && !it.sys.bodies.drift(world, it.t, h))
    throw SimulationError(fmt::format(
        "a rigid body moves more than integrator.max_step_displacement = {} radii of the smallest particle in "
        "step {} at t = {:.6g} s (dt = {:.4g} s): lower the step",
        it.set.max_step_displacement, it.stats.accepted + 1, it.t, h));
  it.clock.lap(Stage::Prescribe);
  if (!kick_drift(it, h)) throw_too_far(it, h);
  it.clock.lap(Stage::Integrate);
  rod_forces(it);
  it.clock.lap(Stage::Rods);
  contact_forces(it, h, true);
  gather_kick(it, h);  // (rotations included: the explicit update needs only this step's torque)
  it.clock.lap(Stage::Gather);
  commit(it, h);
  it.clock.lap(Stage::Commit);
  account(it, h);
  it.clock.lap(Stage::Account);
  it.stats.last_iterations = 1;
  it.stats.iterations += 1;
  it.stats.max_iterations = 1;
}

}  // namespace swarf::integrate

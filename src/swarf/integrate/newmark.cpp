// newmark.cpp: the implicit Newmark step (beta 1/4, gamma 1/2 by default) solved by fixed-point
// sweeps: repeat { place (x, v and the rotations from the latest a+), rod_forces, contact_forces,
// gather } until the sweep's change is below the tolerance; then place once more with the final
// a+. The caller commits, or restores and retries shorter (paper section 3.4; integration.h).
#include <algorithm>
#include <cmath>

#include "swarf/integrate/integration.h"

namespace swarf::integrate {

bool newmark_try(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  const StepSettings& g = it.set;
  ms.mesh_rejected = !prescribe(it, h);
  if (ms.mesh_rejected) return false;  // (a mesh would move too far: a shorter step)
  it.clock.lap(Stage::Prescribe);
  int sweep = 0, growing = 0;
  bool converged = false;
  double previous = HUGE_VAL;
  // Relaxation w < 1: the next sweep places with (1 - w) a_guess + w a_swept. The sweep maps
  // a guess to new accelerations with eigenvalues in [-(dt/dt_stable)^2, 0] (docs/physics.md
  // section 7); relaxed, they become 1 - w + w lambda: at dt_max (0.8 dt_stable, L = 0.64 the
  // spectrum's extent) the contraction per sweep drops from 0.64 to 0.25 with w = 0.75 (optimal:
  // w = 2 / (2 + L)), and the iteration converges up to dt/dt_stable = sqrt(2/w - 1).
  const double w = g.relaxation;
  auto& acc = world.particles.acceleration;
  for (sweep = 1; sweep <= g.max_iterations; ++sweep) {
    if (w != 1.0 && sweep == 1) ms.a_guess = acc;  // (later sweeps: the blend below)
    if (!place(it, h)) return false;
    it.clock.lap(Stage::Integrate);
    rod_forces(it);
    it.clock.lap(Stage::Rods);
    contact_forces(it, h);
    const double change = gather(it);
    it.clock.lap(Stage::Gather);
    if (!std::isfinite(change)) return false;
    if (change <= g.tolerance) {
      converged = true;
      break;
    }
    // A contraction shrinks the change every sweep; two growing sweeps in a row mean the
    // step is beyond the fixed-point limit: give up early instead of sweeping on.
    // (Changes within a decade of the tolerance may fluctuate at the rounding level.)
    growing = change > previous && change > 10.0 * g.tolerance ? growing + 1 : 0;
    if (growing >= 2) return false;
    previous = change;
    if (w != 1.0) {
      const std::size_t n = acc.size();
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) acc[i] = ms.a_guess[i] = (1.0 - w) * ms.a_guess[i] + w * acc[i];
    }
  }
  if (!converged) return false;
  if (!place(it, h)) return false;  // x+, v+ (and rotations) from the converged accelerations
  it.clock.lap(Stage::Integrate);
  it.stats.last_iterations = sweep;
  it.stats.iterations += sweep;
  it.stats.max_iterations = std::max(it.stats.max_iterations, sweep);
  return true;
}

}  // namespace swarf::integrate

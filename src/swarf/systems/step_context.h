// step_context.h: what a system's stage needs of the step now, rebuilt for every try.
//
// The systems (systems/*.h) take their stages' inputs from it instead of from the Simulation's
// members, so a stage is a function of the World, the context and the system's own state.
#pragma once

#include "swarf/state/world.h"
#include "swarf/systems/energy_ledger.h"

namespace swarf {

struct StepContext {
  World& world;
  double t = 0;           ///< time at the start of the step, s
  double h = 0;           ///< the step's size, s
  double beta = 0;        ///< Newmark's beta of the scheme, 1
  double gamma = 0;       ///< Newmark's gamma, 1
  bool implicit = false;  ///< the Newmark step (its sweeps) rather than Verlet's
  EnergyLedger& ledger;   ///< where the account stage books its energies
};

/// How a system's own state is shared when the particles are split over domains (MPI ranks,
/// issue 38): what the decomposition must migrate, ghost or reduce for it.
enum class Sharing {
  PerRod,      ///< per-rod (and per-block) values: owned with the rod, by the owner of its first particle
  Replicated,  ///< small per-object state held whole on every rank (bodies, groups, regions); sums over
               ///< the ranks' particles (wrenches, reactions) are reduced in a fixed rank order
};

}  // namespace swarf

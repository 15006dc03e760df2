// flow_system.h: inflow and outflow regions (state/particle_flows.h) after each accepted step.
//
// Outflows remove the particles whose centres lie in them, then inflows create theirs: each
// region owes rate x h particles more, and each due particle draws up to 'attempts' places
// (centre and radius) and takes the first that overlaps nothing beyond the tolerance, the ones
// created this step included. The system decides who leaves and who comes; the Simulation's
// door (remove_particles, append_particles) carries it out, so that every per-particle array,
// rod and contact follows. The energy that crosses the boundary goes to
// EnergyLedger::flow_energy. The regions' counters (owed, draws, created, removed) are the
// World's (Inflow, Outflow) and are visited here.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/state/world.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/step_context.h"

namespace swarf {

class StateArchive;

class FlowSystem {
 public:
  /// Checks the regions (finite boxes, rates, radii, densities); InputError naming the region.
  static void setup(const World& w);
  /// The particles in an outflow region (mask; empty if none), their kinetic and potential
  /// energy 'out', J, and the same with the potential energy's size, 'gross', J (for
  /// EnergyLedger::flow_through). Counts them in their regions.
  static std::vector<std::uint8_t> outflow(World& w, double& out, double& gross);
  /// The particles the inflows create after a step of h, s (their kinetic energy booked).
  static Particles inflow(World& w, double h, EnergyLedger& ledger);
  /// The regions' counters and the flow energy (nothing without regions).
  void visit_state(StateArchive& ar, World& w, EnergyLedger& ledger);

  // Domains (issue 38): the regions and their counters are held whole on every rank; a new
  // particle must not overlap one near the box, on whichever rank it lies.
  static constexpr Sharing sharing = Sharing::Replicated;
  /// How far beyond its region a rank needs copies of particles for the inflows' overlap
  /// check: the largest radius_max of the inflows plus the largest radius there is, m.
  double ghost_reach(const World& w) const;
};

}  // namespace swarf

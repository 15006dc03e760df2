// plastic_strain_system.h: the accumulated equivalent plastic strain per particle (PEEQ), as FEM
// codes define it: the time integral of the equivalent plastic strain rate (docs/outputs.md).
//
// Stages (integrate/integration.h), after a step has converged, after the rods' commit:
//   accumulate  every rod that flowed in the step (the list the rods' commit hands over) adds its
//               logarithmic plastic increment de = de_p L0 / L (de_p the law's plastic strain
//               increment, of the rest length L0; L the rod's length now) to both ends' windows as
//               g(n) de (n its direction now, g the normal-strain row: measure/strain_fit.h), in
//               list order (rod order: the same bits for any thread count); a rod shorter than
//               L0 / 2, whose pair has collapsed, adds nothing
//   fit         every 'window' steps, each particle with a non-zero window solves the normal
//               equations of its intact rods' current directions with the window as right-hand
//               side: the deviatoric plastic strain increment tensor dE_p of the window (the
//               least squares of the plastic strain the rods hold, particle_fields.h, over the
//               trace-free tensors: strain_fit.h, fit_deviatoric_strain); PEEQ grows by
//               sqrt(2/3 dE_p:dE_p) and the rate is that over the window's time
// The fit is linear in the window, so a window's sum is the sum of per-step fits but for the
// rods' turning within the window (in a simple shear of 0.01 per window: +0.2 % of PEEQ, +1.5 %
// of the rate; tests/test_peeq.cpp). Summing tensor increments before taking their norm, the
// window also undercounts a strain path that reverses within it. Outputs see PEEQ as of the last
// full window. The window (StepSettings::plastic_strain_window) is 32 steps: cheap against the
// step, and short in strain where the step is small (the cut's).
// The same pass adds half of each such rod's plastic work (what the commit booked in the ledger)
// to each end's Particles::plastic_work, J: where the plastic work went, including that of rods
// that broke or were given up since (whose plastic strain no particle holds any more).
// Rods that break or are given up in a neighbour exchange have already given their increments,
// and formed rods start from no plastic strain, so the sum carries over bond formation; the
// per-particle arrays are the World's (Particles::peeq, peeq_rate, window_normal, window_shear)
// and follow the door and the state visit.
#pragma once

#include <cstdint>

#include "swarf/state/world.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/rod_system.h"
#include "swarf/systems/step_context.h"

namespace swarf {

class StateArchive;

class PlasticStrainSystem {
 public:
  /// 'window': committed steps between fits; 0 turns the system off (the arrays stay zero).
  void setup(World& w, int window);
  bool enabled() const { return window_ > 0; }

  /// After a converged step of size h: adds the rods that flowed (RodSystem::commit's list) to
  /// their ends' windows, then fits the particles' increments when the window is full.
  void accumulate(World& w, const RodSystem::WorkList& flowed, double h);
  /// Folds every particle's window into PEEQ now (also called by accumulate when it is full).
  void fit(World& w);

  void visit_state(StateArchive& ar, World& w, EnergyLedger& ledger);
  /// After the door changed the particles: a particle that came with a non-zero window (a
  /// domain's migrant, swarf/domains/domain_run.h) makes the next fit fold it in.
  void resize(const World& w);

  // Domains (issue 38): the per-particle arrays migrate with the particles; a rod's increment is
  // added to both ends, and a domain holds every rod of the particles it owns, so an owned
  // particle's window is its serial one (a ghost's is its own partial one, never read; a migrant
  // arriving as owned brings its old owner's).
  static constexpr Sharing sharing = Sharing::Replicated;
  double ghost_reach(const World&) const { return 0.0; }

 private:
  int window_ = 0;            // steps per fit (StepSettings::plastic_strain_window)
  std::int64_t steps_ = 0;    // state: committed steps in the current window
  double window_time_ = 0.0;  // state: their time, s
  bool pending_ = false;      // state: some particle's window is non-zero
};

}  // namespace swarf

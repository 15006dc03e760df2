// thermal_system.h: the heat in the workpiece and at the tools (issue 33; docs/physics.md,
// "Heat"): a temperature per particle (Particles::temperature), its sources and conduction.
//
// Stages (integrate/integration.h), after a step has converged, after the rods' commit and before the
// contacts':
//   sources    the Taylor-Quinney fraction of each rod's plastic work of the step (the list
//              the rods' commit hands over: what it booked as plastic work), half to each end; the frictional power of
//              every touching contact over the step, half to each body (a mesh's half to the tool)
//   conduction through the intact rods and the touching contacts (laws/heat_conduction.h),
//              forward Euler, when the time since the last conduction reaches the interval
//              set by the explicit limit (C_i / sum_j G_ij times heat.stability_fraction):
//              about 10^4 mechanical steps at the default resolution, so the conduction runs
//              rarely and the sources every step; if contacts have raised the conductance
//              since, the pass is split into sub-steps within the limit
// The temperature is staggered with the mechanics: a step's rod law reads the temperatures of
// the step's start (the thermal rod law: laws/johnson_cook_rod_law.h), and the heat of the
// step is added after it converged, so a rejected try changes no temperature.
//
// The tools (the World's meshes) have one temperature each: held at heat.tool_temperature
// (a heat sink) or, with heat.tool_heat_capacity, warmed by what flows in (lumped: the
// tool's own conduction is not resolved).
//
// The particles of the groups in heat.held keep the temperature they start with (a clamp
// that is a heat sink; from a case file, the initial temperature); what reaches them is booked as heat_to_clamps.
//
// Ledger (EnergyLedger, J): heat_plastic + heat_friction = stored + heat_to_tools +
// heat_outflow + heat_to_clamps, stored = sum_i m_i c (T_i - T_initial) (stored_heat()).
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/contacts/contacts.h"
#include "swarf/state/world.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/rod_system.h"
#include "swarf/systems/step_context.h"
#include "swarf/systems/step_exchange.h"

namespace swarf {

class StateArchive;

class ThermalSystem {
 public:
  /// Checks the parameters (InputError naming the value), gives every particle without a
  /// temperature the initial one and the tools theirs, and sets the first conduction interval.
  void setup(World& w);
  /// After the door changed the particles: the new ones (temperature 0) at the initial temperature.
  void resize(World& w);
  bool enabled() const { return enabled_; }

  /// The heat of a converged step of size c.h: 'plastic' is the rods' commit's list of the rods
  /// that flowed and their plastic work (RodSystem::commit); before the contacts' commit (it
  /// reads their step's friction).
  void heat(const StepContext& c, const ContactSystem& contacts, const RodSystem::WorkList& plastic);
  /// The heat the particles flagged in 'remove' carry out of the workpiece, J (relative to the
  /// initial temperature); booked by the caller before it removes them.
  double carried(const World& w, const std::vector<std::uint8_t>& remove) const;

  /// Heat stored in the workpiece, sum m c (T - T_initial), J.
  double stored_heat(const World& w) const;
  /// The meshes' temperatures, K (empty without heat).
  const std::vector<double>& tool_temperature() const { return tool_t_; }
  /// The time step the conduction last ran with and its explicit limit, s.
  double conduction_step() const { return last_step_; }
  double conduction_limit() const { return limit_; }
  std::int64_t conductions() const { return conductions_; }

  void visit_state(StateArchive& ar, World& w, EnergyLedger& ledger);

  // Domains (issue 38): the temperature is a particle field and migrates with it; the tools'
  // temperatures and the conduction's clock are held whole on every rank (their sums reduced
  // in a fixed rank order). Conduction reaches along rods and contacts only, which those
  // systems' reaches cover.
  static constexpr Sharing sharing = Sharing::Replicated;
  double ghost_reach(const World&) const { return 0.0; }
  /// A domain's link to the others (null: a run in one process). With it the conduction reads
  /// the ghosts' temperatures after this step's sources (and after each sub-step), its explicit
  /// limit is the smallest over the domains, and the heat's ledger lines are also counted by
  /// owner, each term added exactly (exact_share()): the same sums over the domains for any
  /// partition. The tools then must keep their temperature (no tool heat capacity or conductivity).
  void set_exchange(StepExchange* x) { x_ = x; }
  struct ExactShare {
    ExactSum plastic, friction, to_tools, to_clamps;  ///< the ledger's heat_plastic, ..., J
  };
  const ExactShare& exact_share() const { return exact_; }

 private:
  // One conduction over dt (sub-stepped within the limit); updates limit_ and the interval.
  void conduct(World& w, const ContactSystem& contacts, double dt, EnergyLedger& ledger);
  // Heat flowing into each particle by conduction (W) and its total conductance (W/K), the
  // rods' and the contacts' (and the meshes'), into out_.
  void fluxes(const World& w, const ContactSystem& contacts, double ds);  // ds: the (sub-)step, s

  bool enabled_ = false;
  std::vector<double> tool_t_;           // state: per mesh, K
  double pending_ = 0.0;                 // state: time since the last conduction, s
  double interval_ = 0.0;                // state: time between conductions, s (0: at the next step)
  double limit_ = 0.0;                   // the last conduction's explicit limit, s
  double last_step_ = 0.0;               // the last conduction's (sub-)step, s
  std::int64_t conductions_ = 0;         // state: conduction passes so far
  std::vector<std::uint8_t> held_;       // per particle: 1 = held at the initial temperature (heat.held)
  std::vector<std::int32_t> held_list_;  // the held particles' indices, ascending (the clamps' heat sum)
  std::vector<double> plastic_;          // scratch per particle: the step's plastic heat, J
  ContactSystem::HeatOutput out_;        // scratch: friction, conduction and conductance per particle and mesh
  StepExchange* x_ = nullptr;            // a domain's link to the others (not owned)
  ExactShare exact_;                     // with x_: this domain's exact share of the heat's ledger lines
};

}  // namespace swarf

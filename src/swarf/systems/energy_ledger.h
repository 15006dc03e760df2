// energy_ledger.h: the step's energy bookkeeping, which every system adds its part to.
//
// external = kinetic + elastic + plastic + viscous + fracture + contact (+ flow) (+ error): the
// balance a run checks (app/observers/energy_balance). Each system books what it does in the
// account stage (rods: plastic, viscous, fracture; groups and meshes: external work; contacts:
// what they take up; flows: what crosses the boundary), so a new system adds its own line.
#pragma once

namespace swarf {

/// Energy bookkeeping, J. external = kinetic + elastic + plastic + viscous + fracture (+ error).
struct EnergyLedger {
  double external_work = 0;    ///< work done by the prescribed motions
  double plastic_work = 0;     ///< sum of sigma d(eps_p) A L0 over commits
  double viscous_work = 0;     ///< dissipated by the rods' viscous part
  double fracture_energy = 0;  ///< elastic energy lost with broken rods
  double contact_work = 0;     ///< taken up by the contacts: -integral of the contact forces' power on
                               ///< particles (and their torques) and meshes; stored Hertz energy + dissipation
  double flow_energy = 0;      ///< carried out by removed particles (kinetic, potential, their rods' elastic
                               ///< energy) minus brought in by created ones (kinetic)
  double flow_through = 0;     ///< the gross energy that crossed the flows' boundaries: the kinetic energy
                               ///< brought in plus the kinetic, |potential| and rods' elastic energy carried
                               ///< out. The energy check's scale and round-off floor: flow_energy is a
                               ///< difference of such terms, which cancel when a particle leaves as it came
  // The heat (systems/thermal_system.h), apart from the mechanical balance above: what the
  // dissipation turned into heat and where it went. heat_plastic + heat_friction = stored +
  // heat_to_tools + heat_outflow + heat_to_clamps.
  double heat_plastic = 0;    ///< the Taylor-Quinney fraction of the plastic work, J
  double heat_friction = 0;   ///< the frictional work of the contacts, J
  double heat_to_tools = 0;   ///< into the tools (meshes): their half of the friction and the conduction, J
  double heat_outflow = 0;    ///< carried out by removed particles, above the initial temperature, J
  double heat_to_clamps = 0;  ///< into particles held at the initial temperature (heat.held_groups), J
};

}  // namespace swarf

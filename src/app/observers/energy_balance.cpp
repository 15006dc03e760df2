// energy_balance.cpp: the energy balance (see energy_balance.h).
#include "app/observers/energy_balance.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/console.h"
#include "postprocess/cut_report.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"
#include "swarf/simulation.h"

namespace swarf {

EnergyBalanceNow EnergyBalance::measure(const Simulation& sim) const {
  EnergyBalanceNow b;
  const EnergyLedger& L = sim.ledger();
  b.kinetic = sim.kinetic_energy();
  b.rotational = sim.rotational_energy();
  b.elastic = sim.elastic_energy();
  b.contact = sim.contact_energy();
  b.contact_work = L.contact_work;
  b.potential = sim.potential_energy();
  b.external_work = L.external_work;
  b.plastic_work = L.plastic_work;
  b.viscous_work = L.viscous_work;
  b.fracture_energy = L.fracture_energy;
  b.flow_through = L.flow_through;
  b.error = L.external_work - (b.kinetic + b.elastic + b.potential - initial_ + L.plastic_work + L.viscous_work +
                               L.fracture_energy + L.contact_work + L.flow_energy);
  return b;
}

void check_energy_balance(const EnergyBalanceNow& b, double t) {
  const double held = b.kinetic + b.elastic + b.contact;
  // (what the flows carried counts as held: a particle's energy was in the scale while it was
  // there, and its leaving must not turn the same error into a blow-up; with an outflow that
  // holds the inflow's box, or one that removes everything, nothing is held at a row and the
  // error is the round-off of flow_energy's cancelling terms)
  const double scale = std::max({std::abs(b.external_work), held, b.flow_through});
  // (the round-off floor: a body at rest has every term 0 J, and a balance kept to the last
  // digits of its largest term is kept whatever the scale)
  const double roundoff = 1e-12 * (std::abs(b.external_work) + held + std::abs(b.potential) + b.plastic_work +
                                   b.viscous_work + b.fracture_energy + std::abs(b.contact_work) + b.flow_through);
  // (a NaN error is lost too; std::isgreater is the comparison that does not raise FE_INVALID
  // on a NaN, and the numbers are printed through nan_safe for the same reason)
  if (!std::isfinite(b.error) || std::isgreater(std::abs(b.error), std::max(kMaxEnergyErrorRatio * scale, roundoff)))
    throw SimulationError(fmt::format(
        "energy balance lost at t = {:.6g} s: energy error {:.4g} J against external work {:.4g} J and "
        "kinetic + elastic + contact energy {:.4g} J{} (the error may be at most {:g} times the larger); plastic "
        "{:.4g} J, viscous {:.4g} J, fracture {:.4g} J, contact work {:.4g} J. The step is probably "
        "beyond its stable size (integrator.dt with allow_unstable_dt) or too large for the loads: a "
        "smaller integrator.dt_safety shortens it (a chip sheared without bond formation crowds its "
        "damped rods and needs about 0.7; swarf run --no-energy-check runs on)",
        nan_safe(t), nan_safe(b.error), nan_safe(b.external_work), nan_safe(held),
        b.flow_through > 0.0 ? fmt::format(" and energy through the flows {:.4g} J", nan_safe(b.flow_through)) : "",
        kMaxEnergyErrorRatio, nan_safe(b.plastic_work), nan_safe(b.viscous_work), nan_safe(b.fracture_energy),
        nan_safe(b.contact_work)));
}

void EnergyBalance::columns(std::vector<Column>& out) const {
  out.insert(out.end(),
             {{"kinetic_energy", "J", "translational and rotational kinetic energy of all particles and rigid bodies"},
              {"rotational_energy", "J", "the rotational part of kinetic_energy"},
              {"elastic_energy", "J", "energy stored in the intact rods"},
              {"contact_energy", "J", "elastic energy in the touching contacts now (information only)"},
              {"contact_work", "J", "energy taken up by the contacts since the start, stored and dissipated"},
              {"potential_energy", "J", "energy in gravity relative to the initial positions"},
              {"external_work", "J", "work of the groups' prescribed motions"},
              {"plastic_work", "J", "plastic work of the rods, booked at commit"},
              {"viscous_work", "J", "energy dissipated by the rods' viscous part"},
              {"fracture_energy", "J", "elastic energy of each rod when it broke"},
              {"energy_error", "J", "external work minus the energy held and dissipated (the balance's error)"}});
}

void EnergyBalance::row(const Simulation& sim, std::vector<double>& values) {
  const EnergyBalanceNow b = measure(sim);
  if (check_) check_energy_balance(b, sim.time());
  values.insert(values.end(), {b.kinetic, b.rotational, b.elastic, b.contact, b.contact_work, b.potential,
                               b.external_work, b.plastic_work, b.viscous_work, b.fracture_energy, b.error});
}

void EnergyBalance::begin(const Simulation& sim) {
  initial_ = sim.kinetic_energy() + sim.elastic_energy() + sim.potential_energy();
}

void EnergyBalance::visit_state(StateArchive& ar) { ar.scalar("initial_energy_J", initial_); }

void EnergyBalance::finish(const RunEnd& end, nlohmann::json& summary) {
  const EnergyBalanceNow b = measure(end.sim);
  nlohmann::json& r = summary["results"];
  r["kinetic_energy_J"] = b.kinetic;
  r["elastic_energy_J"] = b.elastic;
  r["external_work_J"] = b.external_work;
  r["plastic_work_J"] = b.plastic_work;
  r["viscous_work_J"] = b.viscous_work;
  r["fracture_energy_J"] = b.fracture_energy;
  r["potential_energy_J"] = b.potential;
  r["contact_energy_J"] = b.contact;
  r["contact_work_J"] = b.contact_work;
  r["energy_error_J"] = b.error;
  // The report's health line: the breakage beside the balance that its fracture energy enters.
  const Rods& rods = end.sim.world().rods;
  say("  broken rods {} of {} ({:.4g} %), energy error {:.3g} J of external work {:.4g} J\n", end.sim.broken_rods(),
      rods.original_count(), 100.0 * broken_rod_fraction(rods.intact, rods.formed), b.error, b.external_work);
}

}  // namespace swarf

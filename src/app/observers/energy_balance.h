// energy_balance.h: where the external work went, per row and at the end.
//
// external work = (kinetic + elastic + potential now - the same at the start) + plastic work
// + viscous work + fracture energy + contact work + error: the error is what the balance does
// not account for (the step's own dissipation and round-off), the run's health check. The
// start's energy is this observer's checkpoint state: free particles may start moving, and
// the balance counts changes from the initial state.
#pragma once

#include "app/observers/observer.h"

namespace swarf {

struct EnergyLedger;

/// The balance at one moment, J.
struct EnergyBalanceNow {
  double kinetic = 0, rotational = 0, elastic = 0, contact = 0, contact_work = 0, potential = 0;
  double external_work = 0, plastic_work = 0, viscous_work = 0, fracture_energy = 0;
  double error = 0;  ///< external work minus all the rest
};

class EnergyBalance final : public Observer {
 public:
  /// 'rods' for the broken-rod count the report prints beside the balance.
  explicit EnergyBalance(std::size_t rods) : rods_(rods) {}
  std::string_view name() const override { return "energy"; }
  void columns(std::vector<std::string>& names) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;
  void begin(const Simulation& sim) override;
  void visit_state(StateArchive& ar) override;
  void finish(const RunEnd& end, nlohmann::json& summary) override;

  /// The balance of 'sim' now, against the initial energy this observer holds.
  EnergyBalanceNow measure(const Simulation& sim) const;

 private:
  std::size_t rods_;
  double initial_ = 0;  ///< kinetic + elastic + potential energy at the start, J
};

}  // namespace swarf

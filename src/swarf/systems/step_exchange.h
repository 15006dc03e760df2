// step_exchange.h: what a system's stage needs from the other domains in the middle of a step
// (issue 38). A run over domains (domains/domain_run.h) sets it on its domain's Simulation; a
// run in one process has none. The engine stays free of MPI: the domains talk through core/comm.h.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace swarf {

class ContactSystem;
class RodSystem;
struct EnergyLedger;
struct World;

class StepExchange {
 public:
  virtual ~StepExchange() = default;
  /// Overwrites every ghost's Particles::temperature with its owner's. Collective.
  virtual void temperatures() = 0;
  /// Overwrites every ghost's motion (position, velocity, acceleration, angular velocity) and
  /// temperature with its owner's: after the kick a ghost's velocity is its own, made from its
  /// partial force, and the contacts' frictional heat reads both ends' velocities. Collective.
  virtual void motions() = 0;
  /// The smallest of 'v' over the domains. Collective.
  virtual double min_all(double v) = 0;
  /// Per particle: 1 for one this domain owns (every particle is counted by one domain).
  virtual const std::uint8_t* counted() const = 0;
  /// Bond formation (RodSystem::form hands it over): decided for the whole run from every
  /// domain's pressed pairs, in the serial run's order, and applied to this domain's rods and
  /// contacts. Returns the pairs of local particles whose rods changed. Collective.
  virtual std::vector<std::array<std::int32_t, 2>> form_rods(RodSystem& rods, World& w, ContactSystem& contacts) = 0;
};

}  // namespace swarf

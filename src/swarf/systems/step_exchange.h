// step_exchange.h: what a system's stage needs from the other domains in the middle of a step
// (issue 38). A run over domains (domains/domain_run.h) sets it on its domain's Simulation; a
// run in one process has none. The engine stays free of MPI: the domains talk through core/comm.h.
#pragma once

#include <cstdint>

namespace swarf {

class StepExchange {
 public:
  virtual ~StepExchange() = default;
  /// Overwrites every ghost's Particles::temperature with its owner's. Collective.
  virtual void temperatures() = 0;
  /// The smallest of 'v' over the domains. Collective.
  virtual double min_all(double v) = 0;
  /// Per particle: 1 for one this domain owns (every particle is counted by one domain).
  virtual const std::uint8_t* counted() const = 0;
};

}  // namespace swarf

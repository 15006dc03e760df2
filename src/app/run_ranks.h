// run_ranks.h: the steps of 'mpirun -n N swarf run': one run over the ranks by domain
// decomposition (issue 38; swarf/domains/domain_run.h).
//
// Every rank builds the case and a serial Simulation of it, the mirror (setup is deterministic,
// so every rank has the same one); the run then steps the domains. Rank 0 alone writes: its
// observers and outputs read the mirror, which takes the run's gathered state (particles in id
// order, the rods in the serial order, the sums reduced exactly over the ranks) when an output is
// due. Whether one is due is rank 0's to say (its RunOutputs keeps the schedule); the ranks agree
// on it after every step in one small collective, which carries the interrupt signals too, so
// that all ranks gather, stop or write a checkpoint after the same step. The observers' step
// listeners are called with rank 0's domain Simulation (its time, counters and settings are the
// run's; its particles are not all of them).
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "swarf/core/comm.h"
#include "swarf/domains/domain_run.h"

namespace swarf {

class ExactLedger;

/// The ranks agree that each has set its part up (read the case, built the model, prepared the
/// outputs) before the first collective of the steps. A rank whose setup threw meets the others
/// in the destructor, so that nobody waits forever: when every rank failed (an error in the case,
/// met by all alike) they all end normally with rank 0's message (setup_failed_everywhere());
/// when only some did, the others throw too and the run ends through MpiSession::abort.
class SetupAgreement {
 public:
  explicit SetupAgreement(Comm* comm) : comm_(comm) {}
  SetupAgreement(const SetupAgreement&) = delete;
  SetupAgreement& operator=(const SetupAgreement&) = delete;
  ~SetupAgreement();
  /// This rank's setup is done. Collective. Throws std::runtime_error if another rank failed.
  void passed();
  /// True after a setup that threw on every rank (this process's last agreement).
  static bool failed_everywhere();

 private:
  Comm* comm_;
  bool done_ = false;
};
class Simulation;
class StepListener;

class RankSteps {
 public:
  /// The run's domains, starting where 'mirror' is (a fresh run or a restored checkpoint, with
  /// the ledger's exact sums in 'ledger' if it had them). 'listeners' are rank 0's (not owned);
  /// 'ledger' (not owned) takes the exact sums at every gather, for the checkpoints. Collective.
  RankSteps(Comm& comm, Simulation& mirror, const std::vector<StepListener*>& listeners, ExactLedger& ledger,
            const DomainSettings& settings);
  RankSteps(const RankSteps&) = delete;
  RankSteps& operator=(const RankSteps&) = delete;

  /// One step of at most max_dt (s). Collective.
  void step(double max_dt) { run_->step(max_dt); }
  double time() const { return run_->time(); }          ///< s
  std::int64_t steps() const { return run_->steps(); }  ///< accepted steps

  struct After {
    bool output = false;  ///< rank 0's outputs are due: gather()
    int signal = 0;       ///< a signal reached one of the ranks (the largest number of those that did)
  };
  /// Collective: what all ranks do after this step; 'output_due' is read on rank 0 only.
  After agree(bool output_due, int signal);
  /// Collective: the mirror takes the run's state now.
  void gather();
  /// Collective: what the decomposition cost, for run.log (rank 0's string; "" elsewhere): the
  /// migrations, the time each rank spent after its steps exchanging (halo, stray checks,
  /// migrations: what waits on the other ranks) against its wall time since the first step, the
  /// halo's bytes per step and the owned particles' balance.
  std::string cost_report();

  bool root() const { return comm_.rank() == 0; }

 private:
  Comm& comm_;
  Simulation& mirror_;
  ExactLedger& ledger_;
  std::unique_ptr<DomainRun> run_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::int64_t steps_at_start_ = 0;
};

}  // namespace swarf

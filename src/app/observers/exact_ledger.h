// exact_ledger.h: a run over MPI ranks keeps its ledger's exact sums in its checkpoints.
//
// The ranks book the ledger lines (plastic, viscous and fracture work, the groups' external
// work) into exact accumulators and reduce them (swarf/domains/domain_run.h); the rows read
// them rounded. A checkpoint holding only the rounded doubles would make a restart go on from
// a rounded sum, and its later rows differ from the uninterrupted run's in the last bit. This
// observer has no columns: it carries the accumulators' digits through the checkpoint
// (/run/exact_ledger/digits), for a restart on any rank count. A checkpoint of a one-process
// run has none (its ledger is plain sums): the ranks go on from its doubles.
#pragma once

#include <cstdint>
#include <vector>

#include "app/observers/observer.h"

namespace swarf {

class ExactLedger final : public Observer {
 public:
  std::string_view name() const override { return "exact_ledger"; }
  void columns(std::vector<Column>&) const override {}
  void row(const Simulation&, std::vector<double>&) override {}
  void visit_state(StateArchive& ar) override;

  /// The digits (DomainRun::ledger_digits()): set before a checkpoint is written; after a
  /// restart, those read from it (empty if it had none).
  std::vector<std::int64_t> digits;
};

}  // namespace swarf

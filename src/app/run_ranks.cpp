// run_ranks.cpp: the steps of a run over MPI ranks (see run_ranks.h).
#include "app/run_ranks.h"

#include <fmt/format.h>

#include <stdexcept>

#include "app/observers/exact_ledger.h"
#include "swarf/simulation.h"

namespace swarf {

namespace {
bool g_failed_everywhere = false;  // (process-wide: the last SetupAgreement's verdict)
}  // namespace

SetupAgreement::~SetupAgreement() {
  if (!comm_ || done_) return;
  try {  // (unwinding from this rank's setup error: meet the others' passed())
    g_failed_everywhere = comm_->sum_all(1) == comm_->size();
  } catch (...) {
  }
}

void SetupAgreement::passed() {
  if (!comm_) return;
  done_ = true;
  if (const std::int64_t failed = comm_->sum_all(0); failed > 0)
    throw std::runtime_error(fmt::format("{} of the {} ranks failed to set the run up", failed, comm_->size()));
}

bool SetupAgreement::failed_everywhere() { return g_failed_everywhere; }

RankSteps::RankSteps(Comm& comm, Simulation& mirror, const std::vector<StepListener*>& listeners, ExactLedger& ledger,
                     const DomainSettings& settings)
    : comm_(comm),
      mirror_(mirror),
      ledger_(ledger),
      run_(std::make_unique<DomainRun>(comm, mirror, settings, ledger.digits.empty() ? nullptr : &ledger.digits)) {
  if (root())
    for (StepListener* l : listeners) run_->add_listener(l);
  steps_at_start_ = run_->steps();
  start_ = std::chrono::steady_clock::now();
}

std::string RankSteps::cost_report() {
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double xs = run_->exchange_seconds();
  const auto owned = static_cast<double>(run_->owned_count());
  const auto max_all = [&](double v) { return comm_.max_all(v); };
  const double xs_max = max_all(xs), xs_min = -max_all(-xs), wall_max = max_all(wall);
  const double owned_max = max_all(owned), owned_min = -max_all(-owned);
  const std::int64_t halo = comm_.sum_all(static_cast<std::int64_t>(run_->halo_bytes()));
  if (!root()) return "";
  const std::int64_t steps = run_->steps() - steps_at_start_, migrations = run_->migrations();
  return fmt::format(
      "over {} rank{}: {} migrations in {} steps{}; after the steps (halo, stray checks, migrations) {:.2f}-{:.2f} s "
      "of {:.2f} s wall per rank; halo {:.1f} kB per step; owned particles {:.0f}-{:.0f} per rank",
      comm_.size(), comm_.size() == 1 ? "" : "s", migrations, steps,
      migrations > 0 ? fmt::format(" (one every {:.0f})", static_cast<double>(steps) / static_cast<double>(migrations))
                     : std::string(),
      xs_min, xs_max, wall_max, static_cast<double>(halo) / 1e3, owned_min, owned_max);
}

RankSteps::After RankSteps::agree(bool output_due, int signal) {
  const std::vector<std::int64_t> s = comm_.sum_all({root() && output_due ? 1 : 0, signal != 0 ? 1 : 0});
  After a;
  a.output = s[0] > 0;
  // (rare: a second collective only when a signal came, on every rank alike)
  if (s[1] > 0) a.signal = static_cast<int>(comm_.max_all(static_cast<double>(signal)));
  return a;
}

void RankSteps::gather() {
  run_->gather_into(mirror_);
  ledger_.digits = run_->ledger_digits();
}

}  // namespace swarf

// exact_ledger.cpp: the ledger's exact sums through a checkpoint (see exact_ledger.h).
#include "app/observers/exact_ledger.h"

#include <fmt/format.h>

#include "swarf/core/errors.h"
#include "swarf/core/exact_sum.h"
#include "swarf/core/state_archive.h"
#include "swarf/domains/domain_run.h"

namespace swarf {

void ExactLedger::visit_state(StateArchive& ar) {
  constexpr std::size_t words = DomainRun::kLedgerLines * ExactSum::kWords;
  if (!ar.loading()) {
    ar.array("digits", digits, StateArchive::kAnySize);
    return;
  }
  try {
    ar.array("digits", digits, StateArchive::kAnySize);
  } catch (const InputError&) {
    digits.clear();  // (a checkpoint of a run in one process: plain sums only)
    return;
  }
  // (a checkpoint written before the contacts' and the heat's lines joined holds the first four)
  bool ok = digits.size() == words || digits.size() == 4 * ExactSum::kWords;
  for (std::size_t k = 0; ok && k < digits.size() / ExactSum::kWords; ++k)
    ok = ExactSum::canonical(digits, k * ExactSum::kWords);
  if (!ok)
    throw InputError(
        fmt::format("checkpoint: dataset '/run/exact_ledger/digits' ({} words) does not hold {} exact sums of {} words",
                    digits.size(), DomainRun::kLedgerLines, ExactSum::kWords));
}

}  // namespace swarf

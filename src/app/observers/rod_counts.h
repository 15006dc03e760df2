// rod_counts.h: what holds the particles together, counted per row: rods broken (and their
// fraction of the lattice's own rods, broken_rod_fraction in cut_report.h) and contacts
// touching; the breakage in summary.json "results".
#pragma once

#include "app/observers/observer.h"

namespace swarf {

class RodCounts final : public Observer {
 public:
  RodCounts() = default;
  // "bonds": the checkpoint group of this observer, named before "rod" was chosen (kept so that
  // checkpoints written by earlier versions restart).
  std::string_view name() const override { return "bonds"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;
  void finish(const RunEnd& end, nlohmann::json& summary) override;

 private:
  double broken_fraction(const Simulation& sim) const;
};

}  // namespace swarf

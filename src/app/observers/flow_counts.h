// flow_counts.h: a run with inflow or outflow regions (swarf/state/particle_flows.h), per row:
// the particle count, what the inflows created and missed and the outflows removed, and the
// energy the flows carried (the energy balance's flow term); the totals in summary.json
// "flows".
#pragma once

#include "app/observers/observer.h"

namespace swarf {

class FlowCounts final : public Observer {
 public:
  std::string_view name() const override { return "flows"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;
  void finish(const RunEnd& end, nlohmann::json& summary) override;
};

}  // namespace swarf

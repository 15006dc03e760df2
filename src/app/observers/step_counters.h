// step_counters.h: the integrator's counters: the step number, the last step's size and its
// fixed-point sweeps per row; the step control's totals and the run's speed in summary.json
// "run" and in the report's first lines.
#pragma once

#include "app/observers/observer.h"

namespace swarf {

class StepCounters final : public Observer {
 public:
  /// 'end_time' (s) as the case sets it; 'particles' for the cost per particle-step.
  StepCounters(double end_time, std::size_t particles) : end_time_(end_time), particles_(particles) {}
  std::string_view name() const override { return "steps"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;
  void finish(const RunEnd& end, nlohmann::json& summary) override;

 private:
  double end_time_;
  std::size_t particles_;
};

}  // namespace swarf

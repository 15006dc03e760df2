// heat_probe.h: a run with [heat] (swarf/systems/thermal_system.h), per row: the heat ledger
// (what the plastic and frictional work turned into heat and where it went: stored in the
// workpiece, to the tools, carried out, to the clamps), its closure error, the workpiece's
// hottest particle and each tool's temperature; at the end summary.json "heat" and one line
// of the report.
#pragma once

#include <string>
#include <vector>

#include "app/observers/observer.h"

namespace swarf {

struct Model;

class HeatProbe final : public Observer {
 public:
  explicit HeatProbe(const Model& model);
  std::string_view name() const override { return "heat"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;
  void finish(const RunEnd& end, nlohmann::json& summary) override;

 private:
  std::vector<std::string> meshes_;  // the World's mesh names, for the tool temperature columns
};

}  // namespace swarf

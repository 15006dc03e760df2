// heat_probe.cpp: the heat's columns (see heat_probe.h).
#include "app/observers/heat_probe.h"

#include <algorithm>
#include <cmath>

#include "io/console.h"
#include "setup/model.h"
#include "swarf/simulation.h"

namespace swarf {

namespace {

struct HeatNow {
  double plastic = 0, friction = 0, stored = 0, tools = 0, outflow = 0, clamps = 0;
  double error = 0;  // sources minus where the heat is, J
  double max_t = 0;  // K
};

HeatNow measure(const Simulation& sim) {
  const EnergyLedger& L = sim.ledger();
  HeatNow h;
  h.plastic = L.heat_plastic;
  h.friction = L.heat_friction;
  h.stored = sim.thermal().stored_heat(sim.world());
  h.tools = L.heat_to_tools;
  h.outflow = L.heat_outflow;
  h.clamps = L.heat_to_clamps;
  h.error = h.plastic + h.friction - (h.stored + h.tools + h.outflow + h.clamps);
  for (double t : sim.world().particles.temperature) h.max_t = std::max(h.max_t, t);
  return h;
}

}  // namespace

HeatProbe::HeatProbe(const Model& model) {
  for (const auto& m : model.meshes) meshes_.push_back(m.name);
}

void HeatProbe::columns(std::vector<Column>& out) const {
  out.insert(out.end(),
             {{"heat_plastic", "J", "the Taylor-Quinney fraction of the rods' plastic work, since the start"},
              {"heat_friction", "J", "the contacts' frictional work, since the start"},
              {"heat_stored", "J", "heat in the workpiece: sum of m c (T - T_initial)"},
              {"heat_to_tools", "J", "heat into the tools (meshes): their half of the friction and the conduction"},
              {"heat_outflow", "J", "heat carried out by removed particles"},
              {"heat_to_clamps", "J", "heat into the particles held at the initial temperature (heat.held_groups)"},
              {"heat_error", "J", "heat_plastic + heat_friction - stored - to tools - outflow - to clamps"},
              {"temperature_max", "K", "the hottest particle's temperature"}});
  for (const auto& m : meshes_) out.push_back({"tool_temperature_" + m, "K", "temperature of the mesh '" + m + "'"});
}

void HeatProbe::row(const Simulation& sim, std::vector<double>& values) {
  const HeatNow h = measure(sim);
  values.insert(values.end(), {h.plastic, h.friction, h.stored, h.tools, h.outflow, h.clamps, h.error, h.max_t});
  const auto& tt = sim.thermal().tool_temperature();
  for (std::size_t k = 0; k < meshes_.size(); ++k) values.push_back(k < tt.size() ? tt[k] : 0.0);
}

void HeatProbe::finish(const RunEnd& end, nlohmann::json& summary) {
  const HeatNow h = measure(end.sim);
  const ThermalSystem& th = end.sim.thermal();
  nlohmann::json& j = summary["heat"];
  j["heat_plastic_J"] = h.plastic;
  j["heat_friction_J"] = h.friction;
  j["heat_stored_J"] = h.stored;
  j["heat_to_tools_J"] = h.tools;
  j["heat_outflow_J"] = h.outflow;
  j["heat_to_clamps_J"] = h.clamps;
  j["heat_error_J"] = h.error;
  j["temperature_max_K"] = h.max_t;
  j["conductions"] = th.conductions();
  j["conduction_step_s"] = th.conduction_step();
  j["conduction_limit_s"] = th.conduction_limit();
  const auto& tt = th.tool_temperature();
  for (std::size_t k = 0; k < meshes_.size() && k < tt.size(); ++k) j["tool_temperature_K"][meshes_[k]] = tt[k];
  say("  heat: plastic {:.4g} J + friction {:.4g} J = stored {:.4g} J + tools {:.4g} J + out {:.4g} J + clamps {:.4g} "
      "J (error {:.3g} J); hottest particle {:.0f} K\n",
      h.plastic, h.friction, h.stored, h.tools, h.outflow, h.clamps, h.error, h.max_t);
}

}  // namespace swarf

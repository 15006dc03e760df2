// flow_counts.cpp: the flows' columns (see flow_counts.h).
#include "app/observers/flow_counts.h"

#include "swarf/simulation.h"

namespace swarf {

namespace {

struct Totals {
  std::int64_t created = 0, missed = 0, removed = 0;
};

Totals totals(const Simulation& sim) {
  Totals t;
  for (const Inflow& f : sim.world().inflows) {
    t.created += f.created;
    t.missed += f.missed;
  }
  for (const Outflow& o : sim.world().outflows) t.removed += o.removed;
  return t;
}

}  // namespace

void FlowCounts::columns(std::vector<Column>& out) const {
  out.insert(out.end(),
             {{"particles", "1", "particles in the run now"},
              {"inflow_created", "1", "particles the inflow regions created since the start"},
              {"inflow_missed", "1", "particles due from the inflow regions that found no free place"},
              {"outflow_removed", "1", "particles the outflow regions removed since the start"},
              {"flow_energy", "J",
               "energy carried out by removed particles minus that brought in by created ones (in the balance)"}});
}

void FlowCounts::row(const Simulation& sim, std::vector<double>& values) {
  const Totals t = totals(sim);
  values.insert(values.end(), {double(sim.world().particles.size()), double(t.created), double(t.missed),
                               double(t.removed), sim.ledger().flow_energy});
}

void FlowCounts::finish(const RunEnd& end, nlohmann::json& summary) {
  const Totals t = totals(end.sim);
  summary["flows"] = {{"particles_at_end", end.sim.world().particles.size()},
                      {"inflow_created", t.created},
                      {"inflow_missed", t.missed},
                      {"outflow_removed", t.removed},
                      {"flow_energy_J", end.sim.ledger().flow_energy}};
}

}  // namespace swarf

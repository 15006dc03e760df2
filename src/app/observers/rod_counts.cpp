// rod_counts.cpp: broken rods and touching contacts (see rod_counts.h).
#include "app/observers/rod_counts.h"

#include "postprocess/cut_report.h"
#include "swarf/simulation.h"

namespace swarf {

double RodCounts::broken_fraction(const Simulation& sim) const {
  const Rods& r = sim.world().rods;
  return broken_rod_fraction(r.intact, r.formed);
}

void RodCounts::columns(std::vector<Column>& out) const {
  out.insert(out.end(),
             {{"broken_rods", "1", "the lattice's own rods broken now"},
              {"broken_fraction", "1", "broken_rods / the lattice's own rods (formed rods are in neither)"},
              {"contacts", "1", "contacts touching in the last evaluation (sphere-sphere and sphere-triangle)"}});
}

void RodCounts::row(const Simulation& sim, std::vector<double>& values) {
  values.insert(values.end(), {double(sim.broken_rods()), broken_fraction(sim),
                               double(sim.contacts().enabled() ? sim.contacts().touching() : 0)});
}

void RodCounts::finish(const RunEnd& end, nlohmann::json& summary) {
  summary["results"]["broken_rods"] = end.sim.broken_rods();
  summary["results"]["broken_fraction"] = broken_fraction(end.sim);
  if (end.sim.world().rods.formation.enabled()) summary["results"]["formed_rods"] = end.sim.formed_rods();
}

}  // namespace swarf

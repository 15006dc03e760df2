// case_observers.cpp: the observers of a case (see case_observers.h).
#include "app/observers/case_observers.h"

#include "app/observers/body_states.h"
#include "app/observers/cut_probe.h"
#include "app/observers/energy_balance.h"
#include "app/observers/flow_counts.h"
#include "app/observers/group_reactions.h"
#include "app/observers/heat_probe.h"
#include "app/observers/mesh_forces.h"
#include "app/observers/rod_counts.h"
#include "app/observers/step_counters.h"
#include "app/observers/uniaxial_probe.h"
#include "setup/model.h"

namespace swarf {

std::vector<std::unique_ptr<Observer>> observers_for(const Model& model, bool energy_check) {
  std::vector<std::unique_ptr<Observer>> obs;
  if (model.uniaxial.enabled) obs.push_back(std::make_unique<UniaxialProbe>(model));
  obs.push_back(std::make_unique<StepCounters>(model.settings.integrator.end_time, model.particles.size()));
  obs.push_back(std::make_unique<EnergyBalance>(energy_check));
  obs.push_back(std::make_unique<RodCounts>());
  obs.push_back(std::make_unique<GroupReactions>(model.groups));
  obs.push_back(std::make_unique<MeshForces>(model.meshes));
  if (!model.bodies.empty()) obs.push_back(std::make_unique<BodyStates>(model.bodies, model.meshes));
  if (!model.inflows.empty() || !model.outflows.empty()) obs.push_back(std::make_unique<FlowCounts>());
  if (model.heat.enabled) obs.push_back(std::make_unique<HeatProbe>(model));
  if (auto cut = CutProbe::of(model)) obs.push_back(std::move(cut));
  return obs;
}

}  // namespace swarf

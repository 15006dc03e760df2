// systems.h: the engine's systems held together, in the fixed order their common stages run.
//
// A stage that several systems have (prescribe, account, resize after the door, visit_state) is
// one call per system in the order of tuple(), found at compile time (no virtual call, no empty
// stage). A new system is a member and an entry in tuple(). The contacts stand apart: the rods'
// commit and bond formation hand them pairs, the integrators time their lists and evaluation
// apart, and their state visit comes after the step's counters (state_visit.cpp).
#pragma once

#include <tuple>

#include "swarf/contacts/contacts.h"
#include "swarf/systems/body_system.h"
#include "swarf/systems/flow_system.h"
#include "swarf/systems/group_system.h"
#include "swarf/systems/plastic_strain_system.h"
#include "swarf/systems/rod_system.h"
#include "swarf/systems/thermal_system.h"

namespace swarf {

struct Systems {
  BodySystem bodies;
  RodSystem rods;
  GroupSystem groups;
  FlowSystem flows;
  ThermalSystem thermal;
  PlasticStrainSystem plastic;
  ContactSystem contacts;

  auto tuple() { return std::tie(bodies, rods, groups, flows, thermal, plastic); }
  auto tuple() const { return std::tie(bodies, rods, groups, flows, thermal, plastic); }
  template <class F>
  void for_each(F&& f) {
    std::apply([&](auto&... s) { (f(s), ...); }, tuple());
  }
  template <class F>
  void for_each(F&& f) const {
    std::apply([&](const auto&... s) { (f(s), ...); }, tuple());
  }
};

}  // namespace swarf

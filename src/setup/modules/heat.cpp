// heat.cpp: the heat's module of setup (see heat.h).
#include "setup/modules/heat.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "setup/case_tables.h"
#include "setup/material_presets.h"
#include "setup/model.h"

namespace swarf {

const std::vector<Key<HeatSettings>>& heat_keys() {
  using S = HeatSettings;
  // (Temperature ranges: above absolute zero and below 10^4 K, beyond every solid's melting point.)
  static const std::vector<Key<S>> keys{
      {.name = "enabled",
       .field = &S::enabled,
       .doc = "Heat on (the table's presence turns it on; false turns it off)."},
      {.name = "heat_capacity",
       .field = &S::heat_capacity,
       .unit = "J/(kg K)",
       .no_default = true,
       .default_note = "the material preset's",
       .range = in(1, 1e5, "[]"),
       .doc = "Specific heat capacity c of the workpiece: a particle holds m c per kelvin."},
      {.name = "conductivity",
       .field = &S::conductivity,
       .unit = "W/(m K)",
       .no_default = true,
       .default_note = "the material preset's",
       .range = in(1e-3, 1e4, "[]"),
       .doc = "Thermal conductivity k of the workpiece: a rod of rest length d conducts k d / (2 sqrt 2) W/K, "
              "which gives k on the FCC lattice."},
      {.name = "taylor_quinney",
       .field = &S::taylor_quinney,
       .unit = "1",
       .range = in(0, 1, "[]"),
       .doc = "Fraction beta of the rods' plastic work that becomes heat (Taylor-Quinney)."},
      {.name = "initial_temperature",
       .field = &S::initial_temperature,
       .unit = "K",
       .range = in(1, 1e4, "[]"),
       .doc = "Temperature of the workpiece at the start and of new (inflow) particles."},
      {.name = "contact_conduction",
       .field = &S::contact_conduction,
       .doc = "Heat also flows through touching contacts between particles, 4 a / (1/k + 1/k) W/K for a contact "
              "circle of radius a."},
      {.name = "tool_temperature",
       .field = &S::tool_temperature,
       .unit = "K",
       .range = in(1, 1e4, "[]"),
       .doc = "Temperature of the meshes (tools) at the start; held there when `tool_heat_capacity` is 0."},
      {.name = "tool_heat_capacity",
       .field = &S::tool_heat_capacity,
       .unit = "J/K",
       .range = or_zero(in(1e-6, 1e9, "[]", "0, or 1e-6 to 1e9 J/K")),
       .doc = "Heat capacity of each mesh (lumped: one temperature per tool). 0 means a heat sink at "
              "`tool_temperature`. (1e-6 J/K is a cube of tool steel 0.1 mm across; a smaller tool would "
              "need a conduction step far below the mechanical one.)"},
      {.name = "tool_conductivity",
       .field = &S::tool_conductivity,
       .unit = "W/(m K)",
       .range = in(0, 1e4, "[]"),
       .doc = "Conductivity of the meshes for the contact conductance with the particles. 0 means no conduction "
              "into the tools: they get only their share of the frictional heat (`tool_friction_share`)."},
      {.name = "tool_friction_share",
       .field = &S::tool_friction_share,
       .unit = "1",
       .range = in(0, 1, "[]"),
       .doc = "Share of the frictional heat of a contact between a particle and a mesh (tool) that goes into the "
              "mesh; the particle takes the rest (the heat partition coefficient of FE cutting codes; 0.5 splits "
              "it evenly, 0 heats only the chip, as Oxley's theory assumes)."},
      {.name = "stability_fraction",
       .field = &S::stability_fraction,
       .unit = "1",
       .range = in(0, 1, "(]"),
       .doc = "Conduction step as a fraction of its explicit limit min m c / sum G (forward Euler). The "
              "conduction runs when that much time has passed, and the sources every step."},
      {.name = "held_groups",
       .field = &S::held_groups,
       .rule = "names of [[group]] tables",
       .doc = "Groups whose particles are held at `initial_temperature` (a clamp that is a heat sink); what flows "
              "into them is booked as heat to the clamps."},
  };
  return keys;
}

void read_heat(const CaseInput& in, CaseSettings& cs) {
  if (const toml::table* t = in.table("heat")) {
    TableReader r = in.reader(t, "heat");
    cs.heat.present = true;
    r.read(heat_keys(), cs.heat);
    r.finish();
    for (const std::string& g : cs.heat.held_groups)
      if (std::none_of(cs.groups.begin(), cs.groups.end(), [&](const GroupSettings& s) { return s.name == g; }))
        r.fail("held_groups", r.get("held_groups"), fmt::format("names no [[group]]: '{}'", g));
    // The material preset fills what the table does not give.
    const MaterialPreset* preset = cs.material.preset.empty() ? nullptr : find_material_preset(cs.material.preset);
    if (preset && !r.has("heat_capacity")) cs.heat.heat_capacity = preset->heat_capacity;
    if (preset && !r.has("conductivity")) cs.heat.conductivity = preset->conductivity;
    if (cs.heat.enabled)
      for (const char* key : {"heat_capacity", "conductivity"})
        if (!r.has(key) && !preset)
          r.fail(key, nullptr,
                 "the workpiece's heat capacity (J/(kg K)) and conductivity (W/(m K)) are needed: give them or "
                 "material.preset");
  }
}

void build_heat(const CaseSettings& cs, World& world) {
  if (cs.heat.present && cs.heat.enabled) {
    HeatParams& h = world.heat;
    const HeatSettings& s = cs.heat;
    h.enabled = true;
    h.heat_capacity = s.heat_capacity;
    h.conductivity = s.conductivity;
    h.taylor_quinney = s.taylor_quinney;
    h.initial_temperature = s.initial_temperature;
    h.contact_conduction = s.contact_conduction;
    h.tool_temperature = s.tool_temperature;
    h.tool_heat_capacity = s.tool_heat_capacity;
    h.tool_conductivity = s.tool_conductivity;
    h.tool_friction_share = s.tool_friction_share;
    h.stability_fraction = s.stability_fraction;
    h.held.assign(world.groups.size(), 0);
    for (std::size_t g = 0; g < world.groups.size(); ++g)
      h.held[g] = std::find(s.held_groups.begin(), s.held_groups.end(), world.groups[g].name) != s.held_groups.end();
  }
}

std::string heat_echo(const Model& m) {
  if (!m.heat.enabled) return {};
  const Derived& d = m.derived;
  const HeatParams& h = m.heat;
  std::string held;
  for (std::size_t g = 0; g < m.groups.size() && g < h.held.size(); ++g)
    if (h.held[g]) held += (held.empty() ? "" : ", ") + m.groups[g].name;
  return fmt::format(
      "  heat: c = {:.4g} J/(kg K), k = {:.4g} W/(m K) (rod conductance k d/(2 sqrt 2) = {:.4g} W/K), "
      "Taylor-Quinney {:.3g}, start {:.5g} K; tools at {:.5g} K{}, taking {:.3g} of their contacts' friction heat; "
      "held at the start temperature: {}\n",
      h.heat_capacity, h.conductivity, h.conductivity * d.nn_distance / (2.0 * std::sqrt(2.0)), h.taylor_quinney,
      h.initial_temperature, h.tool_temperature,
      h.tool_heat_capacity > 0 ? fmt::format(" (lumped, {:.4g} J/K)", h.tool_heat_capacity) : std::string(" (held)"),
      h.tool_friction_share, held.empty() ? std::string("none") : held);
}

}  // namespace swarf

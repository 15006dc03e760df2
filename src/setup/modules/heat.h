// heat.h: the heat's module of setup: [heat]'s settings, key table, rules (held groups, what the
// material preset fills) and build into the World's HeatParams. Listed once in each central list:
// parse_case (case_config.cpp), the key rows (case_key_text.cpp), build_model (model.cpp) and the
// setup printout (app/setup_report.cpp).
#pragma once

#include <string>
#include <vector>

#include "setup/key.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Model;
struct World;

/// [heat]: temperatures, heat from plastic and frictional work, conduction (issue 33;
/// swarf/laws/heat_params.h). On when the table is present and `enabled` is true.
struct HeatSettings {
  bool present = false;                  ///< the table was given
  bool enabled = true;                   ///< heat.enabled (with the table)
  double heat_capacity = 0.0;            ///< c, J/(kg K); 0 = not given (the material preset's)
  double conductivity = 0.0;             ///< k, W/(m K); 0 = not given (the material preset's)
  double taylor_quinney = 0.9;           ///< 1
  double initial_temperature = 293.15;   ///< K
  bool contact_conduction = true;        ///< conduction through touching contacts too
  double tool_temperature = 293.15;      ///< K
  double tool_heat_capacity = 0.0;       ///< J/K per mesh; 0 = held at tool_temperature
  double tool_conductivity = 0.0;        ///< W/(m K); 0 = no conduction into the tools
  double tool_friction_share = 0.5;      ///< 1: share of a tool contact's frictional heat into the tool
  double stability_fraction = 0.5;       ///< 1
  std::vector<std::string> held_groups;  ///< [[group]] names held at the initial temperature (clamps)
};

const std::vector<Key<HeatSettings>>& heat_keys();

/// Reads [heat] when present and checks its rules; after [[group]] and [material] (its preset).
void read_heat(const CaseInput& in, CaseSettings& cs);

/// The World's HeatParams (on with the table and heat.enabled); after the groups are built.
void build_heat(const CaseSettings& cs, World& world);

/// The setup printout's line on the heat (empty without heat).
std::string heat_echo(const Model& m);

}  // namespace swarf

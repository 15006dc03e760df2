// heat_params.h: the parameters of the heat in the workpiece and at the tools (issue 33),
// derived once from [heat] and [material]; plain data that the World holds, like ContactParams.
//
// The thermal system (systems/thermal_system.h) reads them; the rod law reads only the
// particles' temperatures (Particles::temperature).
#pragma once

#include <cstdint>
#include <vector>

namespace swarf {

struct HeatParams {
  bool enabled = false;                 ///< temperatures, heat sources and conduction
  double heat_capacity = 0.0;           ///< specific heat capacity c of the workpiece, J/(kg K)
  double conductivity = 0.0;            ///< thermal conductivity k of the workpiece, W/(m K)
  double taylor_quinney = 0.9;          ///< fraction of the plastic work that becomes heat, 1
  double initial_temperature = 293.15;  ///< of the workpiece and of new particles, K
  bool contact_conduction = true;       ///< heat also flows through touching contacts (not only rods)
  double tool_temperature = 293.15;     ///< the meshes' (tools') temperature at the start, K
  double tool_heat_capacity = 0.0;      ///< of each mesh, J/K; 0: held at tool_temperature (a heat sink)
  double tool_conductivity = 0.0;       ///< of the meshes, W/(m K); 0: no conduction into them (friction heat only)
  /// Share of a tool contact's frictional heat that goes into the tool, 1, [0, 1]; the particle
  /// takes the rest (the heat partition coefficient of FE cutting codes).
  double tool_friction_share = 0.5;
  double stability_fraction = 0.5;  ///< conduction step as a fraction of its explicit limit, 1, (0, 1]
  std::vector<std::uint8_t> held;   ///< per World group: 1 = its particles keep their starting temperature (a
                                    ///< clamp that is a heat sink); may be shorter than the groups
};

}  // namespace swarf

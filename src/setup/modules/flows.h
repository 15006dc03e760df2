// flows.h: the particle flows' module of setup: [[inflow]]'s and [[outflow]]'s settings, key tables,
// rules and build into the World's Inflow and Outflow (swarf/state/particle_flows.h). Listed once in
// each central list: parse_case (case_config.cpp), the key rows (case_key_text.cpp), the case echo
// (app/case_echo.cpp) and build_model (model.cpp). (An outflow with a cutting run is parse_case's
// rule: it needs the meshes.)
#pragma once

#include <array>
#include <string>
#include <vector>

#include "setup/key.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct World;

/// [[inflow]]: a box that creates free spheres during the run (swarf/state/particle_flows.h);
/// they are made of the [material] density, as [[particle]]s are.
struct InflowSettings {
  std::array<double, 3> box_min{0, 0, 0};   ///< m
  std::array<double, 3> box_max{0, 0, 0};   ///< m
  double rate = 0.0;                        ///< particles per second
  double mass_rate = 0.0;                   ///< kg/s (instead of rate)
  double radius_min = 0.0;                  ///< m
  double radius_max = 0.0;                  ///< m; 0 = radius_min
  std::array<double, 3> velocity{0, 0, 0};  ///< m/s
  int seed = 1;                             ///< 1
  double overlap = 0.0;                     ///< largest relative overlap with any particle at creation, 1
  int attempts = 20;                        ///< placement draws per particle, 1
};

/// [[outflow]]: a box that removes the particles whose centres enter it.
struct OutflowSettings {
  std::array<double, 3> box_min{0, 0, 0};       ///< m
  std::array<double, 3> box_max{0, 0, 0};       ///< m
  std::array<double, 3> plane_point{0, 0, 0};   ///< m (a plane instead of a box)
  std::array<double, 3> plane_normal{0, 0, 0};  ///< 1, towards the side removed
};

const std::vector<Key<InflowSettings>>& inflow_keys();
const std::vector<Key<OutflowSettings>>& outflow_keys();

/// Reads the [[inflow]] and [[outflow]] tables and checks their rules.
void read_flows(const CaseInput& in, CaseSettings& cs);

/// The World's inflows (their particles of [material]'s density) and outflows.
void build_flows(const CaseSettings& cs, World& world);

}  // namespace swarf

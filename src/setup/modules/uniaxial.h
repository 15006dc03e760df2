// uniaxial.h: the uniaxial test's module of setup: [uniaxial]'s settings, key table, rules (the strain
// path; the grips' reserved group names), its build (the grips as two groups moving along the path, the
// bar's gauge length and cross-section, the rods through its mid-plane: Model::uniaxial) and its line of
// the setup printout. Listed once in each central list: parse_case (case_config.cpp), the key rows
// (case_key_text.cpp), the case echo (app/case_echo.cpp), build_model (model.cpp) and the setup
// printout (app/setup_report.cpp). (It needs a [workpiece]: parse_case's rule.)
#pragma once

#include <string>
#include <vector>

#include "setup/key.h"
#include "swarf/core/vec3.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Model;

/// [uniaxial]: a bar between two grips driven along a strain path (hysteresis test).
struct UniaxialSettings {
  bool enabled = false;    ///< true when the table is present
  std::string axis = "x";  ///< bar axis: "x", "y" or "z"
  int grip_layers = 1;     ///< lattice layers held by each grip
  std::string
      grip_dofs = "axis";  ///< "axis": grips hold only the axial component (free lateral contraction); "xyz": clamped
  std::vector<double> strain_path{0.0};  ///< turning points of the nominal strain, 1, first 0
  double strain_rate = 10.0;             ///< |d strain/dt| of the grips, 1/s
};

const std::vector<Key<UniaxialSettings>>& uniaxial_keys();

/// Reads [uniaxial] when present and checks its rules, after [[group]].
void read_uniaxial(const CaseInput& in, CaseSettings& cs);

/// The grips and the bar's geometry, on the ordered 'sites' with layers 'h' apart; sets
/// integrator.end_time to the path's end when it is not given.
void build_uniaxial(const CaseSettings& cs, const std::vector<Vec3>& sites, double h, Model& model);

/// The setup printout's line on the bar (empty without [uniaxial]).
std::string uniaxial_echo(const Model& m);

}  // namespace swarf

// membrane.h: the membrane's module of setup: [membrane]'s settings, key table, rules (its own and
// those on the tables it replaces: no [workpiece], no [rod], only density in [material]), its build
// (the triangular lattice of sites) and its lines of the setup printout. Listed once in each central
// list: parse_case (case_config.cpp), the key rows (case_key_text.cpp), the case echo
// (app/case_echo.cpp), build_model (model.cpp) and the setup printout (app/setup_report.cpp). Its rods'
// parameters are derived (membrane_relations_of, derived.h); the clamped edge is a group that
// build_model adds after the rods.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "setup/key.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Lattice;
struct Model;

/// [membrane]: a sheet of bonded spheres on a triangular lattice (membrane_lattice.h), in place
/// of [workpiece], with its own material ([rod] and [material] do not apply to it).
struct MembraneSettings {
  bool enabled = false;                   ///< true when the table is present
  double length = 0.0;                    ///< extent along x, m
  double width = 0.0;                     ///< extent along y, m
  std::array<double, 3> origin{0, 0, 0};  ///< corner of the sheet (it lies in the plane z = origin z), m
  double radius = 0.5e-3;                 ///< particle radius R, m (site spacing 2R)
  double thickness = 0.0;                 ///< t, m
  double youngs_modulus = 0.0;            ///< E of the sheet's material, Pa (in-plane modulus E t)
  double poisson_ratio = 1.0 / 3.0;       ///< only checked: the triangular lattice has 1/3
  double density = 1000.0;                ///< rho, kg/m^3 (areal density rho t)
  double areal_density = 0.0;             ///< kg/m^2, replaces density x thickness when > 0
  double pre_tension = 0.0;               ///< isotropic in-plane tension of the sheet as generated, N/m
  double damping_ratio = 0.0;             ///< rod dashpot as a fraction of critical for two particles, 1
  bool clamp_edges = false;               ///< hold every edge site (fewer than 6 rods) fixed
};

const std::vector<Key<MembraneSettings>>& membrane_keys();

/// Reads [membrane] when present and checks its rules, after [workpiece] and before [material].
void read_membrane(const CaseInput& in, CaseSettings& cs);

/// The sheet's lattice of sites (with [membrane]).
Lattice membrane_lattice(const CaseSettings& cs);

/// The setup printout's lines on the sheet (its moduli, tension and waves).
std::string membrane_echo(const Model& m);

}  // namespace swarf

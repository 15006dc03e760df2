// material.h: the material's module of setup: [material]'s settings, key table and rules (what a
// preset fills, the flow curve as a table or Johnson-Cook) and its lines of the setup printout. The
// presets are in material_presets.h; [material] has no build of its own: compute_derived (derived.cpp)
// turns it into the rod law, build_model the particles' masses. Listed once in each central list:
// parse_case (case_config.cpp), the key rows (case_key_text.cpp), the case echo (app/case_echo.cpp) and
// the setup printout (app/setup_report.cpp).
#pragma once

#include <string>
#include <vector>

#include "setup/key.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Model;

/// [material]: what the particles are made of.
struct MaterialSettings {
  double density = 7800.0;          ///< kg/m^3
  std::string mass_basis = "cell";  ///< "cell": m = rho a^3/4 (bulk density right); "sphere": m = rho 4/3 pi R^3
  // Macroscopic properties along a cube axis [100]; when youngs_modulus is given, swarf
  // derives the rod parameters from them through the FCC lattice relations (derived.h).
  bool macroscopic = false;        ///< true when youngs_modulus is given here
  double youngs_modulus = 0.0;     ///< E along [100], Pa
  double yield_stress = kInf;      ///< uniaxial yield stress along [100], Pa; inf = elastic
  double hardening_modulus = 0.0;  ///< tangent after yield, Pa
  double tensile_strength = kInf;  ///< uniaxial stress along [100] at which rods break, Pa; inf = unbreakable
  double poisson_ratio = -1.0;     ///< only checked: the lattice has 1/3 along [100] (-1 = not given)
  // A metal's flow curve and failure (calibration.h turns them into the rod law).
  std::string preset;     ///< a named material (material_presets.h); "" = none
  std::string reference;  ///< the named material hand-written rods stand for (Oxley's reference only); "" = none
  std::vector<double> flow_plastic_strain;  ///< equivalent plastic strain of the flow curve's points, 1
  std::vector<double> flow_stress;          ///< true flow stress at those points, Pa
  double johnson_cook_a = 0.0;              ///< Johnson-Cook A, Pa (0 = not given)
  double johnson_cook_b = 0.0;              ///< Johnson-Cook B, Pa
  double johnson_cook_n = 0.0;              ///< Johnson-Cook n, 1
  double failure_strain = kInf;             ///< equivalent strain at failure in simple shear, 1; inf = never
  std::string calibration = "shear";        ///< the mode the flow curve is matched in: "shear" or "tension"
  bool flow_curve = false;                  ///< true when a table, Johnson-Cook or a preset gives the flow curve
  // Johnson-Cook's rate and temperature factors (rod.law = "johnson_cook"); the preset's when it has them.
  double johnson_cook_c = 0.0;                       ///< C, 1
  double johnson_cook_m = 1.0;                       ///< m, 1
  double reference_rate = 1.0;                       ///< equivalent plastic strain rate of the flow curve, 1/s
  double melt_temperature = kInf;                    ///< T_melt, K; inf = no softening
  double reference_temperature = 293.15;             ///< T_ref (the flow curve's), K
  std::vector<std::string> johnson_cook_keys_given;  ///< which of the five the table gave (a rule in read_rod)
};

const std::vector<Key<MaterialSettings>>& material_keys();

/// Reads [material] (absent: the defaults) and checks its rules; the preset fills what it does not give.
void read_material(const CaseInput& in, CaseSettings& cs);

/// The setup printout's lines on the material the rod law was derived from (empty when the rods'
/// law was given in [rod]).
std::string material_echo(const Model& m);

}  // namespace swarf

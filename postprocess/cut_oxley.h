// cut_oxley.h: Oxley's machining theory (oxley.h) beside a cut's own result: the same work
// material (the case's Johnson-Cook curve, density, heat capacity and conductivity), the same
// cutting speed, depth of cut, rake angle and width, solved once at the end of a run and
// reported in summary.json ("oxley") and in the printed table, swarf's figure, Oxley's and their
// ratio side by side. A physics cross-check, not a measurement: Oxley's model assumes a
// continuous chip, a sharp tool and a sticking rake-face zone (docs/outputs.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "postprocess/oxley.h"

namespace swarf {

/// The work material as the cut's reference reads it. known = false: the case has no
/// Johnson-Cook flow curve or no thermal properties, and 'note' says which.
struct CutMaterial {
  bool known = false;
  std::string name;                     ///< the preset's name, or "Johnson-Cook (case)"; for the reader
  OxleyMaterial oxley;                  ///< the case's Johnson-Cook constants, rho, c and k (constant in T)
  double initial_temperature = 293.15;  ///< T_0 of the workpiece, K
  std::string note;                     ///< why the material is unknown (empty when known)
};

/// The conditions of the reference: speed (m/s, 0 when the tool's path has no constant speed),
/// depth of cut h (m), rake angle (deg), width (m).
struct CutConditions {
  double speed = 0;           ///< m/s
  double depth_of_cut = 0;    ///< m
  double rake_angle_deg = 0;  ///< deg
  double width = 0;           ///< m
};

/// summary.json "oxley": {"solved": bool, "reason" (when not), the conditions with units, and
/// when solved cutting_force_per_width_N_per_m, thrust_force_per_width_N_per_m,
/// thrust_to_cutting_force_ratio, shear_angle_deg, chip_thickness_m, compression_ratio,
/// contact_length_m, primary_zone_temperature_K, rake_face_temperature_K}. Never throws: a
/// material or a condition Oxley cannot take gives solved = false with the reason.
nlohmann::json oxley_beside(const CutMaterial& material, const CutConditions& cut);

/// The printed comparison: swarf's steady figures (summary.json "cutting" and "chip") beside
/// Oxley's and their ratio; one line saying why when there is no solution.
std::string oxley_table(const nlohmann::json& oxley, const nlohmann::json& cutting, const nlohmann::json& chip);

}  // namespace swarf

// calibration.h: the rod law from a material's macroscopic description ([material] keys or a
// preset): Young's modulus, a flow curve (yield and hardening, a table, or Johnson-Cook's
// A + B eps_p^n) and a strain at failure.
//
// The elastic part follows the FCC lattice relations along [100] (docs/physics.md section 1).
// The plastic part is matched in the mode that forms a chip, simple shear, taken as von Mises
// equivalent (tau = sigma_eq / sqrt 3, gamma_p = sqrt 3 eps_p): on the cube plane only the two
// (1,0,+-1) rods carry, each at strain +-gamma/2, and tau = (3/2) (E100/E_rod) s with s their
// stress. So the rod's flow curve is s(p) = sigma(2 p / sqrt 3) E_rod / ((3 sqrt 3 / 2) E100).
// calibration = "tension" matches uniaxial tension along [100] instead (every rod at eps/3:
// s(p) = sigma(3 p) E_rod / (3 E100)). The failure strain is an equivalent strain in that
// same simple shear; the rod breaks at the strain its stretched rod reaches there, exactly
// (simple shear prescribes the deformation: sqrt(((1 + gamma)^2 + 1) / 2) - 1).
// The small-strain relations are then corrected at finite strain (correct_in_shear).
// The lattice's own response to both modes, at finite strain and in other orientations, is
// what `swarf material` measures (docs/material-lab.md).
#pragma once

#include <string>
#include <vector>

#include "swarf/laws/rod_law.h"

namespace swarf {

struct MacroscopicMaterial {
  double youngs_modulus = 0;                ///< along [100], Pa
  std::vector<double> flow_plastic_strain;  ///< equivalent plastic strain of the points, 1, first 0
  std::vector<double> flow_stress;          ///< true equivalent flow stress there, Pa
  double failure_strain = 0;                ///< equivalent strain at failure (inf: never), 1
  std::string calibration = "shear";        ///< "shear" or "tension"
  bool finite_strain = true;                ///< shear: correct the rods for the lattice's finite-strain response
};

struct RodCalibration {
  double youngs_modulus = 0;                ///< E_rod, Pa
  std::vector<double> flow_plastic_strain;  ///< rod plastic strain, 1
  std::vector<double> flow_stress;          ///< rod flow stress, Pa
  double failure_strain = 0;                ///< rod strain in tension at failure, 1
  double shear_mismatch = 0;                ///< largest |lattice / target - 1| left at the points reached, 1
  int shear_points_reached = 0;             ///< points of the curve (beyond the yield) the shear test reached
};

/// A rod hardening curve from its points (at most FlowCurve::kMaxPoints; the readers check).
FlowCurve make_flow_curve(const std::vector<double>& plastic_strain, const std::vector<double>& stress);

/// The calibrated rod law alone: elastic-plastic with its curve and failure strain, no viscosity,
/// no stress criterion.
RodLaw calibrated_law(const RodCalibration& c);

/// The finite-strain correction of a shear calibration: the rod stresses rescaled until the
/// lattice's cube-plane simple shear (lattice_gen/lattice_material.h, exact at finite strain
/// for the periodic crystal) follows the flow curve where non-decreasing rods can make it.
void correct_in_shear(RodCalibration& c, const MacroscopicMaterial& m, double cell_edge, double rod_area);

/// The plastic strains at which a Johnson-Cook curve is tabulated (8 points, denser where it
/// bends: n < 1 makes it steep at 0).
std::vector<double> johnson_cook_points();

/// sigma = A + B eps_p^n at those points, Pa.
std::vector<double> johnson_cook_stress(double a, double b, double n, const std::vector<double>& eps_p);

/// The rod law that gives the lattice (cell edge a, rod area A, rest length l0) the material's
/// response in the calibration mode (see above).
RodCalibration calibrate_rods(const MacroscopicMaterial& m, double cell_edge, double rod_area, double rest_length);

}  // namespace swarf

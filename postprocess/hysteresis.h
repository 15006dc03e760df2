// hysteresis.h: the uniaxial [100] bar against the FCC lattice relations.
//
// Under uniaxial stress along a cube axis every rod of the FCC lattice carries the strain
// eps/3 in magnitude (tension for the 8 rods with an axial component, compression for the
// 4 across), so a homogeneous bar follows the rod law scaled:
//     sigma_bar(eps) = 3 (E100 / E) sigma_rod(eps / 3)         (docs/physics.md section 1).
// BarPrediction evaluates that along the strain history; analyze_loop fits the measured
// loop (elastic modulus, yield stress, hardening tangent, reverse yield stress) by straight
// lines on the first two segments of the path.
#pragma once

#include <string>
#include <vector>

#include "swarf/laws/any_rod_law.h"

namespace swarf {

/// The predicted bar stress along a strain history (call in time order).
class BarPrediction {
 public:
  // (Evaluated at rate 0: the quasi-static curve, without the viscous part or a rate factor.)
  BarPrediction(const AnyRodLaw& law, double stress_factor) : law_(law), factor_(stress_factor) {}
  double stress(double bar_strain) {
    if (broken_) return 0.0;
    const RodResponse r = evaluate(law_, bar_strain / 3.0, 0.0, shift_);
    shift_ = r.shift;
    broken_ = r.broken;
    return broken_ ? 0.0 : factor_ * r.stress;
  }
  /// The prediction's state (plastic shift, broken), for checkpoints.
  double shift() const { return shift_; }
  bool broken() const { return broken_; }
  void set_state(double shift, bool broken) {
    shift_ = shift;
    broken_ = broken;
  }

 private:
  AnyRodLaw law_;
  double factor_;
  double shift_ = 0.0;
  bool broken_ = false;
};

/// A straight-line least-squares fit stress = slope * strain + intercept.
struct LineFit {
  double slope = 0, intercept = 0;
  int points = 0;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

struct LoopMeasurement {
  bool ok = false;
  std::string note;              ///< why a quantity could not be measured
  double modulus = 0;            ///< slope of the first elastic loading, Pa
  double yield_strain = 0;       ///< intersection of the elastic and hardening lines, 1
  double yield_stress = 0;       ///< Pa
  double hardening_tangent = 0;  ///< slope of the first plastic loading, Pa
  bool reverse_ok = false;
  double turn_stress = 0;           ///< stress at the first turning point, Pa
  double reverse_yield_stress = 0;  ///< yield on the second segment (Bauschinger), Pa
  double reverse_modulus = 0;       ///< unloading slope, Pa
};

/// Measures the loop from samples (strain, stress) taken along the path; 'segment' gives the
/// path segment (0, 1, ...) of each sample; 'yield_strain_hint' (predicted bar yield strain)
/// sets the fitting windows: elastic below 0.5 of it, plastic beyond 1.5 of it from the
/// start of the segment (reversals: twice the elastic range).
LoopMeasurement analyze_loop(const std::vector<double>& strain, const std::vector<double>& stress,
                             const std::vector<int>& segment, double yield_strain_hint);

}  // namespace swarf

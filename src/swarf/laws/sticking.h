// sticking.h: the sticking cap of the tool-chip friction (Zorev's sticking and sliding zones;
// docs/physics.md section 5, "Sticking"; issue 33 item 3).
//
// Where the normal stress on the rake face is high (near the edge), Coulomb's mu sigma_n
// exceeds the chip material's shear flow strength k: the chip's bottom layer cannot transmit
// more than k, it shears within itself (sticks) instead of sliding over the tool. A particle
// on the face carries the face's area share A = a^2/2 = 4 R^2 of a (001) lattice plane (a the
// FCC cube edge, 2 particles per a^2), so its tangential force is capped at
//     F_stick = A k(T),   k(T) = k0 Theta(T),
//     Theta = max(1 - T*^m, 1e-3),  T* = clamp((T - T_ref)/(T_melt - T_ref), 0, 1),
// Johnson-Cook's thermal softening of the flow stress (the 1e-3 floor keeps a particle at the
// melting point from losing all its friction, which would make the cap discontinuous there).
// A particle without a temperature (0 K: no [heat]) is at T_ref. The cap acts on triangle
// (tool and wall) contacts, weighted by the contact's overlap weight as the normal force is.
#pragma once

#include <algorithm>
#include <cmath>

namespace swarf {

struct StickingRule {
  double shear_strength = 0.0;            ///< k0, Pa; 0 = no sticking cap
  double softening_exponent = 1.0;        ///< m, 1
  double melt_temperature = 1733.0;       ///< T_melt, K
  double reference_temperature = 293.15;  ///< T_ref, K
};

/// Theta(T): the thermal factor of the flow strength, in [1e-3, 1]; T = 0 means T_ref.
inline double sticking_softening(const StickingRule& s, double T) {
  if (!(T > s.reference_temperature)) return 1.0;
  const double t = std::min(1.0, (T - s.reference_temperature) / (s.melt_temperature - s.reference_temperature));
  return std::max(1.0 - std::pow(t, s.softening_exponent), 1e-3);
}

/// The largest tangential force a particle of radius R (m) at temperature T (K) passes to a
/// face, N; +inf without a sticking cap.
inline double sticking_cap(const StickingRule& s, double R, double T) {
  if (!(s.shear_strength > 0.0)) return HUGE_VAL;
  return 4.0 * R * R * s.shear_strength * sticking_softening(s, T);
}

}  // namespace swarf

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
//
// The flow zone (contact.sticking_flow_zone; docs/physics.md section 5, "The flow zone"): a
// steel chip's secondary shear zone is about 10 um thick, thinner than a particle, and much
// hotter than the particle's mean temperature, which is what softens it at speed (Trent's
// seizure, Oxley's interface temperature). With it the cap is read at the face's temperature
// instead of the particle's: the contact's friction heat into the chip, q = (1 - s) tau v_s
// (tau the face shear stress, v_s the slip speed, s the tool's share of the heat), crosses the
// particle to its centre, and a layer 2R thick heated through one face with the heat taken up
// inside it (quasi-steady, parabolic profile) has its face q 2R / (3 K) above its mean; Jaeger's
// half-space under a constant flux gives 0.66 q R / K once the heat has penetrated R, the same.
// So tau solves tau = k0 Theta(T + b tau), b = f R v_s, f = (1 - s) 2 / (3 K) (K m/W): one root,
// since the left side grows and the right side falls with tau. The rise vanishes with R
// (a resolved flow zone needs none) and with the slip (a stuck particle shears its rods).
#pragma once

#include <algorithm>
#include <cmath>

namespace swarf {

struct StickingRule {
  double shear_strength = 0.0;            ///< k0, Pa; 0 = no sticking cap
  double softening_exponent = 1.0;        ///< m, 1
  double melt_temperature = 1733.0;       ///< T_melt, K
  double reference_temperature = 293.15;  ///< T_ref, K
  double flow_zone = 0.0;                 ///< f = (1 - s) 2 / (3 K), K m/W; 0 = the particle's temperature
};

/// Theta(T): the thermal factor of the flow strength, in [1e-3, 1]; T = 0 means T_ref.
inline double sticking_softening(const StickingRule& s, double T) {
  if (!(T > s.reference_temperature)) return 1.0;
  const double t = std::min(1.0, (T - s.reference_temperature) / (s.melt_temperature - s.reference_temperature));
  return std::max(1.0 - std::pow(t, s.softening_exponent), 1e-3);
}

/// The face's shear strength tau (Pa) of a particle at temperature T (K) whose face is b tau
/// hotter (b in K/Pa): the root of tau = k0 Theta(T + b tau). Without a rise (b = 0) k0 Theta(T).
inline double flow_zone_strength(const StickingRule& s, double T, double b) {
  const double k0 = s.shear_strength, cold = k0 * sticking_softening(s, T);
  if (!(b > 0.0)) return cold;
  const double floor = 1e-3 * k0, span = s.melt_temperature - s.reference_temperature;
  if (s.softening_exponent == 1.0) {
    // Theta linear in T between T_ref and the floor: tau = k0 (1 - u - b tau / span) in closed form,
    // u = (T - T_ref)/span; k0 while the face stays below T_ref, the floor once Theta reaches it.
    const double u = (T - s.reference_temperature) / span;
    if (u * span + b * k0 <= 0.0) return k0;
    return std::max(k0 * (1.0 - u) / (1.0 + k0 * b / span), floor);
  }
  // Any m: bisection on [floor, cold], where g(tau) = k0 Theta(T + b tau) - tau changes sign
  // (g(floor) >= 0 as Theta >= 1e-3, g(cold) <= 0 as Theta falls with T). 60 halvings leave
  // the root to a relative 1e-18 of the bracket, below a double's resolution.
  double lo = floor, hi = cold;
  for (int it = 0; it < 60 && hi - lo > 0.0; ++it) {
    const double mid = 0.5 * (lo + hi);
    (k0 * sticking_softening(s, T + b * mid) - mid >= 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The largest tangential force a particle of radius R (m) at temperature T (K), slipping over
/// the face at v_s (m/s), passes to it, N; +inf without a sticking cap. The slip matters only
/// with the flow zone.
inline double sticking_cap(const StickingRule& s, double R, double T, double v_s = 0.0) {
  if (!(s.shear_strength > 0.0)) return HUGE_VAL;
  if (!(s.flow_zone > 0.0)) return 4.0 * R * R * s.shear_strength * sticking_softening(s, T);
  // A particle without a temperature (no [heat]) has no flow zone's rise either.
  const double b = T > 0.0 ? s.flow_zone * R * v_s : 0.0;
  return 4.0 * R * R * flow_zone_strength(s, T > 0.0 ? T : s.reference_temperature, b);
}

}  // namespace swarf

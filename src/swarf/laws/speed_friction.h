// speed_friction.h: the tool's Coulomb coefficient as a function of the sliding speed (issue 34:
// the cutting speed must reach the rake face's friction; docs/physics.md section 5, "Friction
// that falls with the sliding speed").
//
// Tribometers built for the contact conditions of a cut (pressures of a GPa, sliding speeds of
// metres per second, a fresh workpiece surface at every pass) find that the friction between a
// steel chip and a carbide tool depends strongly on the sliding speed (Rech, Claudin and D'Eramo
// 2009, Tribol. Int. 42:738, AISI 1045 on TiN-coated carbide: a friction model identified in the
// average local sliding velocity); FE codes for machining take such a model as a table. The
// default's constant mu cannot carry the cutting speed to the rake face (validation/cutting/
// README.md, "A sub-particle flow zone on the rake face against the speed trend"): this is the
// table that can.
//
// The table is (v_s, mu) points with v_s increasing from 0 (m/s), piecewise linear between them
// and constant outside (mu of the first point below the first speed, of the last beyond the last).
// It acts on the tool (triangle) contacts only, with v_s the contact's relative tangential speed
// |v_t| at the sphere's surface point; the sphere-sphere contacts keep `contact.friction`. With the
// spring law a stuck contact (v_t about 0) is capped at the table's first value, a sliding one at
// the value of its speed.
#pragma once

#include <array>

namespace swarf {

struct SpeedFriction {
  static constexpr int kMaxPoints = 8;
  int points = 0;                          ///< 0: no table (the constant coefficient)
  std::array<double, kMaxPoints> speed{};  ///< sliding speeds of the points, m/s, increasing, the first >= 0
  std::array<double, kMaxPoints> mu{};     ///< Coulomb coefficients at those speeds, 1, >= 0
};

/// The Coulomb coefficient at the sliding speed s (m/s): 'mu' without a table, else the table's
/// piecewise-linear value, constant outside its speeds.
inline double friction_at_speed(const SpeedFriction& c, double mu, double s) {
  if (c.points == 0) return mu;
  if (!(s > c.speed[0])) return c.mu[0];
  for (int i = 1; i < c.points; ++i)
    if (s <= c.speed[i]) {
      const double t = (s - c.speed[i - 1]) / (c.speed[i] - c.speed[i - 1]);
      return c.mu[i - 1] + t * (c.mu[i] - c.mu[i - 1]);
    }
  return c.mu[c.points - 1];
}

}  // namespace swarf

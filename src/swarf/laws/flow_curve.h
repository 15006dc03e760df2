// flow_curve.h: a piecewise-linear hardening curve for the rod law's kinematic shift.
//
// The rod law's band (rod_law.h) is the yield surface of 1-D kinematic hardening:
//     |sigma - alpha(eps_p)| <= s_y,   sigma = E (eps - eps_p),
// with s_y = E eps_y the initial yield stress and alpha the back stress. The paper's law has
// alpha linear (alpha = H eps_p, k = E H / (E + H)). A metal's flow curve is not linear: it
// hardens fast and then slowly (Johnson-Cook's A + B eps_p^n). FlowCurve gives alpha as a
// piecewise-linear, odd function of the plastic strain: the monotonic tension curve of the rod
// is s_y + alpha(eps_p), reversal yields at alpha(eps_p) - s_y (the band keeps its width 2 s_y,
// so the Bauschinger effect stays as in the paper), and compression mirrors tension.
//
// The points are (plastic strain, flow stress) of the monotonic tension curve, the first at
// (0, s_y); beyond the last point the last segment's slope continues. A fixed array keeps the
// law a small value type the rod kernel can copy into registers.
#pragma once

#include <array>
#include <cmath>

namespace swarf {

struct FlowCurve {
  static constexpr int kMaxPoints = 8;
  int points = 0;                                   ///< 0: no table (the linear law)
  std::array<double, kMaxPoints> plastic_strain{};  ///< eps_p of the points, increasing, first 0, 1
  std::array<double, kMaxPoints> stress{};          ///< flow stress at those points, Pa, first = s_y

  /// The back stress alpha(p) = flow(|p|) - s_y with the sign of p, Pa.
  double back_stress(double p) const {
    const double r = std::fabs(p);
    const int i = segment_at_or_above(r);
    const double a = stress[i] + slope(i) * (r - plastic_strain[i]) - stress[0];
    return p < 0 ? -a : a;
  }

  /// The plastic strain q beyond the committed p (above it when 'tension', below otherwise) at
  /// which the elastic stress E (eps - q) meets the band's edge alpha(q) + s_y (alpha(q) - s_y
  /// in compression): the return map. The edge function E (eps - q) - alpha(q) decreases
  /// strictly in q (alpha never falls), so it has one root; it is found by walking the curve's
  /// pieces from p, each solved in closed form (a few at most).
  double return_map(double youngs_modulus, double eps, double p, bool tension) const {
    // Compression mirrors tension (alpha is odd): solve for (-eps, -p) and negate.
    const double sg = tension ? 1.0 : -1.0;
    const double e = sg * eps, E = youngs_modulus, sy = stress[0];
    double q = sg * p;
    for (int guard = 0; guard <= 2 * kMaxPoints; ++guard) {
      const double H = slope_towards_larger(q);
      const double root = (E * e - sy - back_stress(q) + H * q) / (E + H);
      const double end = next_point_above(q);
      if (root <= end) return sg * root;
      q = end;
    }
    return sg * q;  // (not reached: the outermost piece is unbounded)
  }

  /// The tangent d sigma / d eps of the rod law on the plastic branch at plastic strain p,
  /// E H / (E + H) with H the back stress's slope there (of the piece a loading in the
  /// direction of p continues on), Pa.
  double plastic_tangent(double youngs_modulus, double p) const {
    const double H = slope(segment_at_or_above(std::fabs(p)));
    return youngs_modulus * H / (youngs_modulus + H);
  }

 private:
  /// Slope of segment i (points i to i+1); the last segment continues beyond the last point;
  /// one point alone is a perfectly plastic curve.
  double slope(int i) const {
    if (points < 2) return 0.0;
    if (i > points - 2) i = points - 2;
    return (stress[i + 1] - stress[i]) / (plastic_strain[i + 1] - plastic_strain[i]);
  }
  /// The segment holding r >= 0, the upper one at a point.
  int segment_at_or_above(double r) const {
    int i = 0;
    while (i + 1 < points && r >= plastic_strain[i + 1]) ++i;
    return i;
  }
  /// The segment holding values just below r > 0.
  int segment_below(double r) const {
    int i = 0;
    while (i + 1 < points && r > plastic_strain[i + 1]) ++i;
    return i;
  }
  /// d alpha / dq of the piece a step towards larger q continues on (alpha' is even).
  double slope_towards_larger(double q) const {
    return q >= 0 ? slope(segment_at_or_above(q)) : slope(segment_below(-q));
  }
  /// The next point of the odd curve strictly above q (+inf beyond the last).
  double next_point_above(double q) const {
    if (q < 0) return -plastic_strain[segment_below(-q)];
    for (int i = 0; i < points; ++i)
      if (plastic_strain[i] > q) return plastic_strain[i];
    return HUGE_VAL;
  }
};

}  // namespace swarf

// periodic.h: the optional periodic direction y (plane strain across the workpiece's width).
//
// Positions are never wrapped: particles keep continuous coordinates, and every difference
// of two positions (rods, contacts) takes the nearest image along y. A rod or contact is far
// shorter than half the period (at least 2 cells of the lattice), so the nearest image is the
// right one for every intact rod and every contact.
#pragma once

#include <cmath>

#include "swarf/core/vec3.h"

namespace swarf {

struct Periodic {
  double period = 0.0;      ///< m along y; 0 = not periodic
  double inv_period = 0.0;  ///< 1/m
  double half = HUGE_VAL;   ///< period / 2, m (inf when not periodic: the test below never fires)

  static Periodic along_y(double length) {
    return length > 0.0 ? Periodic{length, 1.0 / length, 0.5 * length} : Periodic{};
  }
  bool on() const { return period > 0.0; }
  /// The nearest image of a difference vector d = x_j - x_i. Nearly every rod and contact is
  /// shorter than half the period, so the common path is one comparison (nearbyint is a
  /// library call on the baseline x86-64 target).
  /// (An in-place branch, not d[1] = wrapped(d[1]): written so, the rod kernel rounded every
  /// rod's y and ran 30 % slower: validation/bench/README.md.)
  void wrap(Vec3& d) const {
    if (std::abs(d[1]) > half) d[1] -= period * std::nearbyint(d[1] * inv_period);
  }
  /// The same for the y component alone (a loop that keeps the components in registers).
  double wrapped(double dy) const {
    if (std::abs(dy) > half) dy -= period * std::nearbyint(dy * inv_period);
    return dy;
  }
};

}  // namespace swarf

// rod_law_fixtures.h: the two base rod laws the rate and Johnson-Cook law tests scale
// (test_rate_rod_law.cpp, test_johnson_cook_rod_law.cpp): the single slope and a hardening curve
// with the same yield stress, numbers chosen so that the closed forms are easy to write by hand.
#pragma once

#include <cmath>

#include "swarf/laws/rod_law.h"

namespace swarf::test {

constexpr double kE = 200e9, kEpsY = 1e-3, kK = 20e9;  // Pa, 1, Pa: s_y = 200 MPa, H = E k/(E - k)

/// The paper's single slope: E 200 GPa, s_y 200 MPa, k 20 GPa, unbreakable.
inline RodLaw linear_law() {
  RodLaw law;
  law.youngs_modulus = kE;
  law.yield_strain = kEpsY;
  law.hardening = kK;
  law.tensile_strength = HUGE_VAL;
  return law;
}

/// A hardening curve: flow stress 200, 400, 500 MPa at plastic strain 0, 0.01, 0.11; slope 1 GPa beyond.
inline RodLaw curve_law() {
  RodLaw law = linear_law();
  law.hardening = 0.0;
  law.flow.points = 3;
  law.flow.plastic_strain = {0.0, 0.01, 0.11};
  law.flow.stress = {200e6, 400e6, 500e6};
  return law;
}

}  // namespace swarf::test

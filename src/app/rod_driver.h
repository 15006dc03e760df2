// rod_driver.h: 'swarf rod', a single rod driven along a strain path (material point).
#pragma once

#include <ostream>
#include <vector>

#include "swarf/laws/any_rod_law.h"

namespace swarf {

struct RodSample {
  double strain = 0, stress = 0, shift = 0;
  bool broken = false;
};

/// Drives the law quasi-statically (zero strain rate) through the turning points 'path'
/// (first 0), 'steps' equal increments per segment; commits after every increment. After
/// failure the rod carries no stress. Throws InputError on a bad path. Any rod law: it only
/// calls evaluate() (a visit per increment: a material point, not a kernel).
std::vector<RodSample> drive_rod(const AnyRodLaw& law, const std::vector<double>& path, int steps);

/// The checks of the paper's law as 'swarf rod' builds it from its options (--E, --yield-strain,
/// --hardening, --tensile-strength); throws InputError naming the option.
void check_rod_options(const RodLaw& law);

/// CSV with header strain,stress,shift,broken (Pa for stress).
void write_rod_csv(std::ostream& out, const std::vector<RodSample>& samples);

}  // namespace swarf

// any_rod_law.h: the rod laws a Rods may hold, one list (a new law is one line here).
//
// A std::variant, not a base class: the kernels (forces/rod_forces.cpp, forces/rod_tangent.cpp,
// the commit and the energy sums) std::visit it ONCE per call and run their loop with the
// concrete law as a template parameter, so every per-rod call is inline and the default law's
// loop is the code it was before the variant. Each law brings the functions listed in
// rod_law.h, in its own file.
//
// The overloads below visit per call: for cold paths only (the material lab's crystal, the bar
// prediction, a rod exchanged in bond formation), never inside a loop over the rods.
#pragma once

#include <variant>

#include "swarf/laws/johnson_cook_rod_law.h"
#include "swarf/laws/rod_law.h"

namespace swarf {

using AnyRodLaw = std::variant<BilinearRodLaw, JohnsonCookRodLaw>;

inline RodResponse evaluate(const AnyRodLaw& law, double strain, double strain_rate, double shift) {
  return std::visit([&](const auto& l) { return evaluate(l, strain, strain_rate, shift); }, law);
}
inline double plastic_strain(const AnyRodLaw& law, double shift) {
  return std::visit([&](const auto& l) { return plastic_strain(l, shift); }, law);
}
inline double elastic_energy_density(const AnyRodLaw& law, double stress) {
  return std::visit([&](const auto& l) { return elastic_energy_density(l, stress); }, law);
}
inline double elastic_modulus(const AnyRodLaw& law) {
  return std::visit([](const auto& l) { return elastic_modulus(l); }, law);
}
inline double shift_modulus(const AnyRodLaw& law) {
  return std::visit([](const auto& l) { return shift_modulus(l); }, law);
}
inline RodLawDescription describe(const AnyRodLaw& law) {
  return std::visit([](const auto& l) { return describe(l); }, law);
}

}  // namespace swarf

// shear_layers.h: the [[group]] tables that shear an FCC block homogeneously: every (001) layer
// of particles (spacing sqrt(2) R) a group moving along x at a speed proportional to its height,
// x += gamma z. With every particle in a group the deformation is affine whatever the step (the
// adiabatic shear cell of test_heat.cpp, the PEEQ check of test_peeq.cpp).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "swarf/state/particles.h"

namespace swarf::test {

/// The groups for the particles 'p' (the block as built without them) of radius R, sheared at
/// 'rate' (1/s); 'layers' is set to the number of groups.
inline std::string shear_layer_groups(const Particles& p, double R, double rate, int& layers) {
  const double s = std::sqrt(2.0) * R;  // (001) layer spacing, m
  double z0 = HUGE_VAL, z1 = -HUGE_VAL;
  for (const Vec3& x : p.position) z0 = std::min(z0, x[2]), z1 = std::max(z1, x[2]);
  layers = static_cast<int>(std::lround((z1 - z0) / s)) + 1;
  std::string groups;
  for (int k = 0; k < layers; ++k)
    groups += fmt::format(R"([[group]]
name = "layer{}"
box_min = [-1.0, -1.0, {}]
box_max = [1.0, 1.0, {}]
motion = "velocity"
velocity = [{}, 0.0, 0.0]
)",
                          k, z0 + (k - 0.5) * s, z0 + (k + 0.5) * s, rate * k * s);
  return groups;
}

}  // namespace swarf::test

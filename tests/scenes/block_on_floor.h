// block_on_floor.h: the scene the friction tests share: a bonded FCC block (R = 1 mm,
// E = 5 GPa, 7800 kg/m^3) resting on a triangulated floor (a 200 mm square of 3 x 3 x 2
// triangles at z = -R), Hertz with restitution 0.2 and friction, gravity tilted by 'angle'
// about y so that it pulls the block along +x. Each test chooses the friction law, the
// block's size and the integrator.
#pragma once

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "swarf/core/vec3.h"

namespace swarf::test {

struct BlockOnFloor {
  double angle = 0.0;                       ///< rad: the floor's tilt (gravity's angle from -z)
  double mu = 0.4;                          ///< 1: Coulomb coefficient
  std::string law = "spring";               ///< contact.friction_law
  std::array<int, 3> cells{2, 2, 1};        ///< conventional cells (2 x 2 x 1: 16 particles)
  std::string integrator = "end_time = 1";  ///< the [integrator] table's lines
};

inline std::string block_on_floor_case(const BlockOnFloor& b) {
  const double g = 9.81;
  return fmt::format(R"([workpiece]
cells = [{nx}, {ny}, {nz}]
radius = 1e-3
[material]
density = 7800.0
[rod]
youngs_modulus = 5e9
[contact]
youngs_modulus = 5e9
poisson_ratio = 0.3
restitution = 0.2
friction = {mu}
friction_law = "{law}"
regularization_speed = 1e-4
[environment]
gravity = [{gx:.17g}, 0.0, {gz:.17g}]
[[mesh]]
name = "floor"
origin = [-0.1, -0.1, -0.0009999]
edge1 = [0.2, 0.0, 0.0]
edge2 = [0.0, 0.2, 0.0]
divisions = [3, 3]
[integrator]
{integrator}
)",
                     fmt::arg("nx", b.cells[0]), fmt::arg("ny", b.cells[1]), fmt::arg("nz", b.cells[2]),
                     fmt::arg("mu", b.mu), fmt::arg("law", b.law), fmt::arg("gx", g * std::sin(b.angle)),
                     fmt::arg("gz", -g * std::cos(b.angle)), fmt::arg("integrator", b.integrator));
}

/// The mean x of the positions, m.
inline double mean_x(const std::vector<Vec3>& positions) {
  double s = 0;
  for (const auto& x : positions) s += x[0];
  return s / double(positions.size());
}

}  // namespace swarf::test

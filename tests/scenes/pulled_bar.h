// pulled_bar.h: the scene several tests share: a steel-like bar on the FCC lattice (R =
// 0.5 mm, E = 200 GPa, yield strain 1e-3, hardening 20 GPa, strength 230 MPa) whose x- face
// is held and whose x+ face is pulled along x at a constant speed, so that it yields and, pulled
// far enough, breaks. Each test chooses the size, the speed, the damping and the integrator.
#pragma once

#include <fmt/format.h>

#include <array>
#include <string>

#include "scheme.h"

namespace swarf::test {

struct PulledBar {
  std::array<int, 3> cells{8, 2, 2};        ///< conventional cells
  double velocity = 20.0;                   ///< m/s of the pulled face
  double damping_ratio = 0.0;               ///< 1; 0 leaves the key out (the default, undamped)
  std::string integrator = "end_time = 1";  ///< the [integrator] table's lines
  std::string extra = {};                   ///< tables after the groups ([output], [environment], ...)
};

/// A number as a TOML float (with a decimal point, so that it stays a float).
inline std::string toml_float(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

inline std::string pulled_bar_case(const PulledBar& b) {
  return fmt::format(R"([workpiece]
cells = [{}, {}, {}]
radius = 0.5e-3
[rod]
youngs_modulus = 200e9
yield_strain = 1e-3
hardening_modulus = 20e9
tensile_strength = 2.3e8
{}[integrator]
{}
[[group]]
name = "left"
side = "x-"
[[group]]
name = "right"
side = "x+"
motion = "velocity"
velocity = [{}, 0.0, 0.0]
{})",
                     b.cells[0], b.cells[1], b.cells[2],
                     b.damping_ratio > 0 ? "damping_ratio = " + toml_float(b.damping_ratio) + "\n" : std::string(),
                     newmark_unless_named(b.integrator), toml_float(b.velocity), b.extra);
}

}  // namespace swarf::test

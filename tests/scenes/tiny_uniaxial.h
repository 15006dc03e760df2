// tiny_uniaxial.h: a uniaxial loop small enough for a test, run through the CLI: a 6 x 2 x 2-cell
// bar (R = 0.5 mm, 96 particles) strained along x to 1.2 % and back to -0.6 % at 100 /s, past
// yield both ways, with ParaView frames every 60 us.
#pragma once

namespace swarf::test {

inline constexpr const char* kTinyUniaxial = R"([workpiece]
cells = [6, 2, 2]
radius = 0.5e-3
[rod]
youngs_modulus = 200e9
yield_strain = 1e-3
hardening_modulus = 20e9
damping_ratio = 0.1
[uniaxial]
axis = "x"
strain_path = [0.0, 0.012, -0.006]
strain_rate = 100.0
[output]
frame_interval = 6e-5
)";

}  // namespace swarf::test

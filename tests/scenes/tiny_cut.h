// tiny_cut.h: a cut small enough for a test, run through the CLI: a 6 x 2 x 3-cell block
// (R = 0.1 mm) held at its base, a 10 degree rake tool at 5 m/s, contacts with friction, no
// frames or plots. Tests override end_time and the output keys they need with --set.
#pragma once

#include <string>

namespace swarf::test {

inline constexpr const char* kTinyCut = R"([workpiece]
cells = [6, 2, 3]
radius = 1e-4
[rod]
tensile_strength = 3e8
[contact]
friction = 0.3
[[group]]
name = "base"
side = "z-"
[[mesh]]
name = "tool"
rake_angle = 10.0
width = 1.2e-3
face_length = 1e-3
origin = [-0.05e-3, 0.14e-3, 0.5e-3]
motion = "velocity"
velocity = [5.0, 0.0, 0.0]
[integrator]
scheme = "newmark"
end_time = 4e-5
[output]
vtk = false
plots = false
steady_from = 2e-5
series_interval = 1e-6
)";

/// The tiny cut with a compliant tool (the rigid body on its holder's spring that [cut] makes
/// with tool_stiffness): its run writes the tool's deflection, spectrum and vibration plot too.
/// k = 1e10 N/m/m and m = 0.025 kg/m over the 0.57 mm width: f_n about 100 kHz, two periods in
/// the steady part of the 40 us cut.
inline std::string compliant_tiny_cut() {
  std::string text = kTinyCut;
  const std::string path = "motion = \"velocity\"\nvelocity = [5.0, 0.0, 0.0]";
  text.replace(text.find(path), path.size(), R"(dynamics = "rigid_body"
mass = 1.4e-5
centre_of_mass = [-0.05e-3, 0.14e-3, 0.5e-3]
inertia = [2.3e-12, 2.3e-12, 2.3e-12, 0.0, 0.0, 0.0]
rotation = "prescribed"
fixed = "y"
initial_velocity = [5.0, 0.0, 0.0]
holder_velocity = [5.0, 0.0, 0.0]
spring_stiffness = [5.7e6, 0.0, 5.7e6]
damping = 0.9)");
  return text;
}

}  // namespace swarf::test

// body_states.cpp: the rigid bodies' columns (see body_states.h).
#include "app/observers/body_states.h"

#include <fmt/format.h>

#include "swarf/simulation.h"

namespace swarf {

void BodyStates::columns(std::vector<Column>& out) const {
  for (const RigidBody& rb : bodies_) {
    const std::string& n = meshes_[rb.mesh].name;
    auto add3 = [&](const char* what, const char* unit, const char* meaning) {
      for (char c : {'x', 'y', 'z'})
        out.push_back({fmt::format("body_{}_{}_{}", n, what, c), unit,
                       fmt::format("{} component of the {} of rigid body '{}'", c, meaning, n)});
    };
    add3("position", "m", "centre of mass");
    add3("velocity", "m/s", "velocity of the centre of mass");
    for (const char* c : {"w", "x", "y", "z"})
      out.push_back({fmt::format("body_{}_q{}", n, c), "1",
                     fmt::format("{} coefficient of the orientation quaternion (principal frame to world) of rigid "
                                 "body '{}'",
                                 c, n)});
    add3("omega", "rad/s", "angular velocity (world frame)");
    add3("torque", "N m", "torque the particles exert about the centre of mass");
    add3("reaction", "N", "force the constraints (held components, the hinge's axle) exert");
  }
}

void BodyStates::row(const Simulation&, std::vector<double>& values) {
  for (const RigidBody& rb : bodies_) {
    const BodyState& s = rb.state;
    for (const Vec3* v : {&s.position, &s.velocity})
      for (int c = 0; c < 3; ++c) values.push_back((*v)[c]);
    for (int c = 0; c < 4; ++c) values.push_back(s.orientation[c]);
    const Vec3 reaction = rb.constraint_force();
    for (const Vec3* v : {&s.omega, &rb.contact_torque, &reaction})
      for (int c = 0; c < 3; ++c) values.push_back((*v)[c]);
  }
}

}  // namespace swarf

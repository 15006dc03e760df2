// body_worlds.h: a small world of spheres and a rigid body shared by the rigid-body and the
// co-simulation tests.
#pragma once

#include <cmath>
#include <numbers>

#include "swarf/geometry/mass_properties.h"
#include "swarf/geometry/shapes.h"
#include "swarf/laws/hertz.h"
#include "swarf/state/world.h"

namespace swarf::test {

// Eight spheres fly at a free box (no gravity) and hit it off its centre, with friction: the
// box is pushed and set turning.
inline World spheres_and_box(FrictionLaw law, double restitution = 0.7) {
  World world;
  const double R = 1e-3, rho = 2500;
  auto& p = world.particles;
  const int n = 8;
  p.resize(n);
  for (int k = 0; k < n; ++k) {
    p.position[k] = Vec3(-3e-3 + 1.1e-3 * (k % 4) * 2, 1e-3 * (k / 4 * 2 - 1) + 2e-4 * k, 1.02e-3 + 3e-4 * (k % 3));
    p.initial_position[k] = p.position[k];
    p.velocity[k] = Vec3(0.1 * (k % 2), 0.0, -1.0 - 0.05 * k);
    p.radius[k] = R;
    p.mass[k] = rho * 4.0 / 3.0 * std::numbers::pi * R * R * R;
    p.inv_mass[k] = 1.0 / p.mass[k];
    p.inertia[k] = Vec3::Constant(0.4 * p.mass[k] * R * R);
    p.inv_inertia[k] = 1.0 / p.inertia[k][0];
  }
  world.rods.build_rows(n);  // (no rods: the gather's rows are empty)
  MeshBody mb;
  mb.name = "plate";
  mb.mesh = box_mesh(Vec3(1e-3, 0.0, -1e-3), Vec3(1.2e-2, 6e-3, 2e-3));
  mb.youngs_modulus = HUGE_VAL;
  world.meshes.push_back(mb);
  world.mesh_motion.push_back(Motion{});
  world.bodies.push_back(rigid_body_of(0, mb.mesh, 500));  // ~1.5x the spheres' mass
  world.contacts = true;
  world.contact.youngs_modulus = 1e9;
  world.contact.poisson_ratio = 0.3;
  world.contact.alpha = restitution_to_alpha(restitution);
  world.contact.friction = law == FrictionLaw::None ? 0.0 : 0.4;
  world.contact.law = law;
  world.contact.skin = 2e-4;
  return world;
}

}  // namespace swarf::test

// test_systems.cpp: the systems' declared interface for domains (issue 38): how far beyond a
// region a rank needs copies of particles, against the closed forms of small worlds built in
// code (systems/*.h, Simulation::ghost_reach). The stages themselves are covered by every
// physics test and gated bit for bit by tests/test_golden.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "swarf/simulation.h"
#include "swarf/systems/rod_system.h"

namespace swarf {
namespace {

// Three steel spheres of radius R on the x axis, joined by rods (0,1) and (1,2) at rest.
World three_on_a_line(double R, double x1, double x2) {
  World w;
  Particles& p = w.particles;
  p.resize(3);
  const double xs[3] = {0.0, x1, x2};
  for (std::size_t i = 0; i < 3; ++i) {
    p.position[i] = p.initial_position[i] = Vec3(xs[i], 0.0, 0.0);
    p.radius[i] = R;
    p.mass[i] = 7850.0 * 4.0 / 3.0 * M_PI * R * R * R;
    p.inv_mass[i] = 1.0 / p.mass[i];
    p.inertia[i] = Vec3::Constant(0.4 * p.mass[i] * R * R);
    p.inv_inertia[i] = 1.0 / p.inertia[i][0];
    p.id[i] = static_cast<std::int64_t>(i);
  }
  p.next_id = 3;
  Rods& r = w.rods;
  RodLaw law;
  law.youngs_modulus = 2e11;
  law.yield_strain = HUGE_VAL;
  law.tensile_strength = HUGE_VAL;
  r.law = law;
  r.area = R * R;
  r.ends = {{0, 1}, {1, 2}};
  r.rest_length = {x1, x2 - x1};
  r.reset_state();
  r.build_rows(3);
  return w;
}

// A rod is computed by the owner of its first particle, which needs the other end: the reach is
// the longest intact rod's current length (exact: the same squared norm, one square root).
TEST(Systems, TheRodsReachIsTheLongestIntactRod) {
  World w = three_on_a_line(1e-4, 1e-3, 2.5e-3);
  RodSystem rods;
  rods.setup(w);
  EXPECT_DOUBLE_EQ(rods.ghost_reach(w), 1.5e-3);
  w.particles.position[2][0] = 3e-3;  // stretched: the current length counts, not the rest length
  EXPECT_DOUBLE_EQ(rods.ghost_reach(w), 2e-3);
  w.rods.intact[1] = 0;  // a broken rod needs no ghost
  EXPECT_DOUBLE_EQ(rods.ghost_reach(w), 1e-3);
}

// Across a periodic width the nearest image counts: a rod from y = 0 to y = W - d is d long.
TEST(Systems, TheRodsReachTakesTheNearestPeriodicImage) {
  World w = three_on_a_line(1e-4, 1e-3, 2.5e-3);
  const double W = 1e-2, d = 4e-4;
  w.periodic = Periodic::along_y(W);
  w.particles.position[1] = Vec3(0.0, W - d, 0.0);
  w.particles.position[2] = Vec3(0.0, W - 2 * d, 0.0);
  RodSystem rods;
  rods.setup(w);
  EXPECT_NEAR(rods.ghost_reach(w), d, 1e-15);  // (W - d - 0 wrapped: one rounding of W)
}

// The step's reach is the largest of its systems': with contacts, 2 R_max + skin when that
// exceeds the rods.
TEST(Systems, TheStepsReachIsTheLargestOfItsSystems) {
  const double R = 1e-4;
  World w = three_on_a_line(R, 2.1 * R, 4.2 * R);
  w.contacts = true;
  w.contact.youngs_modulus = 2e11;
  w.contact.poisson_ratio = 0.3;
  w.contact.skin = 0.5 * R;
  StepSettings s;
  s.dt = 1e-9;
  {
    World a = w;
    Simulation sim(a, s);
    EXPECT_DOUBLE_EQ(sim.ghost_reach(), 2.0 * R + 0.5 * R);  // contacts: 2.5 R > the rods' 2.1 R
  }
  w.contact.skin = 0.01 * R;
  Simulation sim(w, s);
  EXPECT_NEAR(sim.ghost_reach(), 2.1 * R, 1e-18);  // rods: 2.1 R > 2.01 R
}

}  // namespace
}  // namespace swarf

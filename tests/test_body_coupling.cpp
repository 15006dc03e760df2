// test_body_coupling.cpp: co-simulation of a rigid body with an outside code
// (swarf/body_coupling.h). The outside code here is the smallest multibody model: a free mass
// M integrated by the trapezoid (V+ = V + J/M with the impulse J handed over at the last
// exchange, X+ = X + H (V + V+)/2). Spheres fly at the body; the exchanges carry the body's
// position one way and the particles' impulse the other.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "body_worlds.h"
#include "swarf/body_coupling.h"
#include "swarf/core/errors.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

// The spheres of test::spheres_and_box fly at its plate, here held for the outside code (no
// gravity); no friction, and no contact damping when 'elastic' (then only the scheme and the
// interface lose energy).
World spheres_and_held_plate(bool elastic) {
  World world = test::spheres_and_box(FrictionLaw::None, elastic ? 1.0 : 0.7);
  world.bodies[0].fixed = 7;
  world.bodies[0].rotation = BodyRotation::Prescribed;
  return world;
}

StepSettings scheme(bool implicit, double dt) {
  StepSettings s;
  s.dt = dt;
  if (implicit) {
    s.scheme = Scheme::Newmark;
    s.dt_max = dt;
    s.dt_min = 1e-6 * dt;
    s.tolerance = 1e-12;
    s.length_scale = 1e-3;
    s.stiffness_scale = 1.0;
  }
  return s;
}

struct Coupled {
  Vec3 p_particles, p_outside, in_flight;  // N s
  double e_particles = 0, e_outside = 0;   // J (particles: kinetic and contact)
  double e0 = 0;                           // J, at the start
  double p_scale = 0;                      // N s: sum of |m v| at the start
  int steps = 0, exchanges = 0;
};

// Runs the coupled system for 'time' s in exchanges of 'steps_per_exchange' swarf steps of dt.
Coupled run_coupled(bool implicit, bool elastic, int steps_per_exchange, double time) {
  const double dt = 2.5e-8;
  World world = spheres_and_held_plate(elastic);
  Simulation sim(world, scheme(implicit, dt));
  const double M = world.bodies[0].mass;  // kg: the outside body (the plate's own mass)
  BodyCoupling coupling(sim, 0);
  const auto& p = world.particles;
  auto particle_momentum = [&] {
    Vec3 s = Vec3::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) s += p.mass[i] * p.velocity[i];
    return s;
  };
  auto particle_energy = [&] { return sim.kinetic_energy() - sim.body_kinetic_energy() + sim.contact_energy(); };
  Coupled c;
  for (std::size_t i = 0; i < p.size(); ++i) c.p_scale += p.mass[i] * p.velocity[i].norm();
  c.e0 = particle_energy();
  const double H = steps_per_exchange * dt;
  Vec3 X = world.bodies[0].state.position, V = Vec3::Zero(), J = Vec3::Zero();
  while (sim.time() < time) {
    const Vec3 Vn = V + J / M;  // the outside code's step with the impulse of the last exchange
    const Vec3 Xn = X + H * 0.5 * (V + Vn);
    const BodyExchange ex = coupling.advance(Xn, H);
    c.steps += ex.steps;
    ++c.exchanges;
    X = Xn;
    V = Vn;
    J = ex.impulse;
  }
  c.p_particles = particle_momentum();
  c.p_outside = M * V;
  c.in_flight = J;
  c.e_particles = particle_energy();
  c.e_outside = 0.5 * M * V.squaredNorm();
  return c;
}

// Momentum crosses the interface exactly: each exchange hands the outside code the impulse
// that the scheme gave the particles (opposite), so the particles' momentum, the outside
// body's and the impulse handed over but not yet applied add up to the initial momentum, to
// rounding (1e-13 of the momenta's scale), with sub-cycling in both schemes.
TEST(BodyCoupling, MomentumCrossesTheInterfaceExactly) {
  for (const bool implicit : {false, true}) {
    const Coupled c = run_coupled(implicit, false, 20, 6e-5);
    Vec3 initial = Vec3::Zero();
    const World w = spheres_and_held_plate(false);
    for (std::size_t i = 0; i < w.particles.size(); ++i) initial += w.particles.mass[i] * w.particles.velocity[i];
    if (!implicit) EXPECT_EQ(c.steps, 20 * c.exchanges);         // (Newmark: as many as its control takes)
    EXPECT_GT(c.p_outside.norm(), 0.2 * c.p_scale) << implicit;  // the outside body took a large share
    EXPECT_NEAR((c.p_particles + c.p_outside + c.in_flight - initial).norm(), 0.0, 1e-13 * c.p_scale) << implicit;
  }
}

// Energy does not cross exactly: the outside body gets the force of one exchange over the
// next one's displacement. With elastic contacts the total energy after the impacts differs
// from the start by the interface's error (Verlet's own at dt is far smaller: checked by the
// shortest exchange), which is first order in the exchange interval: halving it halves the
// error (ratio within [1.5, 2.7]).
TEST(BodyCoupling, TheInterfacesEnergyErrorIsFirstOrderInTheExchangeInterval) {
  double err[3];
  int k = 0;
  for (int steps : {40, 20, 10}) {
    const Coupled c = run_coupled(false, true, steps, 1.2e-4);
    err[k++] = std::abs(c.e_particles + c.e_outside - c.e0) / c.e0;
  }
  std::printf("interface energy error / initial energy at 40, 20, 10 steps per exchange: %.3e %.3e %.3e\n", err[0],
              err[1], err[2]);
  EXPECT_LT(err[0], 0.05);
  EXPECT_GT(err[0] / err[1], 1.5) << err[0] << " " << err[1] << " " << err[2];
  EXPECT_LT(err[0] / err[1], 2.7) << err[0] << " " << err[1];
  EXPECT_GT(err[1] / err[2], 1.5) << err[1] << " " << err[2];
  EXPECT_LT(err[1] / err[2], 2.7) << err[1] << " " << err[2];
}

// A body that is not held cannot be driven from outside; a macro step must be a positive time.
TEST(BodyCoupling, RefusesAFreeBodyAndABadMacroStep) {
  World free_plate = spheres_and_held_plate(false);
  free_plate.bodies[0].fixed = 0;
  Simulation a(free_plate, scheme(false, 2.5e-8));
  EXPECT_THROW(BodyCoupling(a, 0), InputError);
  EXPECT_THROW(BodyCoupling(a, 1), InputError);
  World held = spheres_and_held_plate(false);
  Simulation b(held, scheme(false, 2.5e-8));
  BodyCoupling coupling(b, 0);
  EXPECT_THROW(coupling.advance(held.bodies[0].state.position, 0.0), InputError);
  EXPECT_THROW(coupling.advance(held.bodies[0].state.position, NAN), InputError);
  EXPECT_THROW(coupling.advance(Vec3(NAN, 0, 0), 1e-6), InputError);
}

}  // namespace
}  // namespace swarf

// test_verlet.cpp: velocity Verlet against its own discrete recurrence (two particles on a
// rod), second-order convergence, and energy conservation of an undamped vibrating bar.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lattice_gen/lattice_file.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/simulation.h"
#include "test_helpers.h"

namespace swarf {
namespace {

constexpr double kE = 200e9, kRadius = 0.5e-3;

// Two particles 2R apart along x, one rod; particle 1 starts with velocity v0 along x.
Model two_particles(const test::TempDir& dir, double dt) {
  Lattice lat;
  lat.position = {Vec3(0, 0, 0), Vec3(2 * kRadius, 0, 0)};
  lat.radius = {kRadius, kRadius};
  lat.rods = {{0, 1}};
  lat.rest_length = {2 * kRadius};
  write_lattice(dir / "two.h5", lat);
  const std::string toml = "[workpiece]\nlattice_file = \"" + (dir / "two.h5") +
                           "\"\n[rod]\nyoungs_modulus = 200e9\n[integrator]\nend_time = 1\ndt = " +
                           fmt::format("{:.17g}", dt) + "\n";
  return build_model(parse_case(toml, "two", {}));
}

TEST(Verlet, TwoParticleSpringFollowsTheDiscreteRecurrence) {
  test::TempDir dir("verlet2");
  Model m0 = two_particles(dir, 1e-9);
  const double dt = 0.3 * m0.derived.dt_stable;
  Model m = two_particles(dir, dt);
  const double v0 = 0.01;  // m/s
  m.particles.velocity[1] = Vec3(v0, 0, 0);
  Simulation sim(m, m.step);
  // The recurrence of the scheme, run by hand with the same force expression.
  const double l0 = 2 * kRadius, A = m.derived.rod_area, mass = m.particles.mass[0];
  double x1 = 0, x2 = l0, u1 = 0, u2 = v0, a1 = 0, a2 = 0;
  auto force = [&](double p1, double p2) {
    const double len = p2 - p1;
    return (kE * ((len - l0) * (1.0 / l0))) * A * (1.0 / len) * len;  // on particle 1, along +x
  };
  double max_dev = 0;
  for (int n = 1; n <= 3000; ++n) {
    u1 += 0.5 * dt * a1;
    u2 += 0.5 * dt * a2;
    x1 += dt * u1;
    x2 += dt * u2;
    const double f = force(x1, x2);
    a1 = (1.0 / mass) * f;
    a2 = (1.0 / mass) * -f;
    u1 += 0.5 * dt * a1;
    u2 += 0.5 * dt * a2;
    sim.step();
    max_dev = std::max({max_dev, std::abs(m.particles.position[0][0] - x1), std::abs(m.particles.position[1][0] - x2)});
  }
  // Same operations in nearly the same order: agreement to rounding. The amplitude is
  // v0/omega ~ 1e-7 m; rounding of positions ~1e-3 m * 1e-16 per step over 3000 steps.
  EXPECT_LT(max_dev, 1e-15);
  EXPECT_EQ(m.particles.position[0][1], 0.0);
  EXPECT_EQ(m.particles.position[1][2], 0.0);
}

// The separation s_n - L0 obeys the Stormer recurrence u_{n+1} = 2 u_n - u_{n-1} - (w dt)^2 u_n
// with w^2 = 2 kb/m, whose exact solution from u_0 = 0, u_1 = dt v0 is
// u_n = dt v0 sin(n theta)/sin(theta), cos(theta) = 1 - (w dt)^2/2.
TEST(Verlet, SeparationMatchesTheClosedFormOfTheRecurrence) {
  test::TempDir dir("verlet_cf");
  Model m0 = two_particles(dir, 1e-9);
  const double dt = 0.5 * m0.derived.dt_stable;
  Model m = two_particles(dir, dt);
  const double v0 = 1.0;  // amplitude ~1.3e-7 m, rod strain ~1.3e-4
  m.particles.velocity[1] = Vec3(v0, 0, 0);
  Simulation sim(m, m.step);
  const double w = std::sqrt(2 * m.derived.rod_stiffness / m.particles.mass[0]);
  const double theta = std::acos(1 - 0.5 * w * w * dt * dt);
  const double amp = dt * v0 / std::sin(theta);
  double max_err = 0;
  for (int n = 1; n <= 2000; ++n) {
    sim.step();
    const double u = m.particles.position[1][0] - m.particles.position[0][0] - 2 * kRadius;
    max_err = std::max(max_err, std::abs(u - amp * std::sin(n * theta)));
  }
  // In 1-D the rod force is exactly linear in the separation, so only rounding is left: each
  // step rounds positions near 1e-3 m by up to one ulp (2.2e-19 m); 2000 steps accumulate at
  // most 2000 ulps = 4.4e-16 m (3e-9 of the amplitude).
  EXPECT_LT(max_err, 2000 * 2.2e-19);
  EXPECT_GT(amp, 1e-7);
}

TEST(Verlet, SecondOrderConvergenceToTheExactOscillation) {
  test::TempDir dir("verlet_conv");
  Model m0 = two_particles(dir, 1e-9);
  const double w = std::sqrt(2 * m0.derived.rod_stiffness / m0.particles.mass[0]);
  const double T = 2 * M_PI / w * 3.25;  // a little over three periods
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const double dt = T / (400.0 * (1 << k));
    Model m = two_particles(dir, dt);
    m.particles.velocity[1] = Vec3(0.01, 0, 0);
    Simulation sim(m, m.step);
    for (int n = 0; n < 400 * (1 << k); ++n) sim.step();
    // Exact: separation (v0/w) sin(w t) (centre of mass drifts at v0/2).
    const double u = m.particles.position[1][0] - m.particles.position[0][0] - 2 * kRadius;
    err[k] = std::abs(u - 0.01 / w * std::sin(w * sim.time()));
  }
  // Global error O(dt^2): halving dt divides it by 4 (3.5..4.5 allows for the O(dt^4) term).
  EXPECT_GT(err[0] / err[1], 3.5);
  EXPECT_LT(err[0] / err[1], 4.5);
}

// An undamped bar, free, given a stretching velocity field: kinetic + elastic energy is
// conserved to the scheme's O(dt^2) bounded error, which falls by 4 when dt halves.
double energy_drift(double dt_fraction, int periods_steps_factor) {
  const char* toml = R"(
[workpiece]
cells = [8, 2, 2]
radius = 0.5e-3
[rod]
youngs_modulus = 200e9
[integrator]
end_time = 1
)";
  Model m = build_model(parse_case(toml, "bar", {"integrator.dt_safety=" + std::to_string(dt_fraction)}));
  double xc = 0;
  for (const auto& x : m.particles.initial_position) xc += x[0];
  xc /= double(m.particles.size());
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    m.particles.velocity[i] = Vec3(100.0 * (m.particles.initial_position[i][0] - xc), 0, 0);  // strain rate 100 /s
  Simulation sim(m, m.step);
  const double e0 = sim.kinetic_energy() + sim.elastic_energy();
  double worst = 0;
  const int steps = static_cast<int>(periods_steps_factor / dt_fraction);
  for (int n = 0; n < steps; ++n) {
    sim.step();
    if (n % 5 == 0) worst = std::max(worst, std::abs(sim.kinetic_energy() + sim.elastic_energy() - e0));
  }
  return worst / e0;
}

TEST(Verlet, UndampedBarConservesEnergy) {
  const double d1 = energy_drift(0.4, 1200), d2 = energy_drift(0.2, 1200);
  // The energy error of velocity Verlet is bounded by about (w dt)^2/8 of the energy in the
  // modes excited; w dt <= 0.8 here, so the bound is 8e-2, and the stretching field puts
  // most energy into low modes: expect well below 1e-2.
  EXPECT_LT(d1, 1e-2);
  EXPECT_GT(d1, 0.0);
  // Second order: ratio 4 within 25 %.
  EXPECT_GT(d1 / d2, 3.0);
  EXPECT_LT(d1 / d2, 5.0);
}

}  // namespace
}  // namespace swarf

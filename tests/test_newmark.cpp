// test_newmark.cpp: the implicit Newmark step against its own discrete recurrence, its
// fixed-point limit, commit after convergence, and rejection without a trace.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "lattice_gen/lattice_file.h"
#include "scenes/scheme.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/simulation.h"
#include "test_helpers.h"

namespace swarf {
namespace {

constexpr double kRadius = 0.5e-3, kL0 = 2 * kRadius;

// Two particles on one rod along x, the second at distance kL0 - compression.
Model pair_model(const test::TempDir& dir, const std::string& integrator, double compression = 0.0,
                 const std::string& rod = "") {
  Lattice lat;
  lat.position = {Vec3(0, 0, 0), Vec3(kL0 - compression, 0, 0)};
  lat.radius = {kRadius, kRadius};
  lat.rods = {{0, 1}};
  lat.rest_length = {kL0};
  write_lattice(dir / "pair.h5", lat);
  return build_model(parse_case("[workpiece]\nlattice_file = \"" + (dir / "pair.h5") +
                                    "\"\n[rod]\nyoungs_modulus = 200e9\n" + rod + "\n[integrator]\nend_time = 1\n" +
                                    integrator,
                                "pair", {}));
}

double pair_omega(const Model& m) { return std::sqrt(2 * m.derived.rod_stiffness / m.particles.mass[0]); }

std::string fixed_step(double h, double tol = 1e-11, int max_it = 200) {
  return fmt::format(
      "scheme = \"newmark\"\ndt = {:.17g}\ndt_min = {:.17g}\ndt_max = {:.17g}\ntolerance = {}\n"
      "max_iterations = {}\n",
      h, h, h, tol, max_it);
}

// Newmark beta = 1/4, gamma = 1/2 on u'' = -w^2 u, solved exactly per step:
// u+ = (u + h v + h^2 a / 4) / (1 + h^2 w^2 / 4), a+ = -w^2 u+, v+ = v + h (a + a+) / 2.
struct Recurrence {
  double u, v, a, w2, h;
  void step() {
    const double un = (u + h * v + 0.25 * h * h * a) / (1 + 0.25 * h * h * w2);
    const double an = -w2 * un;
    v += 0.5 * h * (a + an);
    u = un;
    a = an;
  }
};

TEST(Newmark, OscillatorFollowsTheDiscreteRecurrence) {
  test::TempDir dir("nm_rec");
  const Model probe = pair_model(dir, "");
  const double w = pair_omega(probe), h = 0.8 / w;  // h w = 0.8
  Model m = pair_model(dir, fixed_step(h));
  const double v0 = 1.0;
  m.particles.velocity[1] = Vec3(v0, 0, 0);
  Simulation sim(m, m.step);
  ASSERT_TRUE(sim.implicit());
  Recurrence rec{0.0, v0, 0.0, w * w, h};
  double max_dev = 0, amp = v0 / w;
  const double e0 = 0.5 * v0 * v0;  // per unit reduced mass
  double max_energy_dev = 0;
  for (int n = 0; n < 2000; ++n) {
    sim.step();
    rec.step();
    const double u = m.particles.position[1][0] - m.particles.position[0][0] - kL0;
    const double v = m.particles.velocity[1][0] - m.particles.velocity[0][0];
    max_dev = std::max(max_dev, std::abs(u - rec.u));
    max_energy_dev = std::max(max_energy_dev, std::abs(0.5 * v * v + 0.5 * w * w * u * u - e0));
  }
  // The fixed point stops at a relative change of 1e-11 (the rod strain, a difference of
  // lengths near 1e-3 m, is good to about 1e-12); each step then carries a relative error of
  // at most 1e-11 * h^2 w^2 / 4 = 1.6e-12, and 2000 steps accumulate at most 3.2e-9 of the
  // amplitude (1.3e-7 m). A wrong beta or gamma would be off by O((h w)^2) = 1e-1.
  EXPECT_LT(max_dev, 1e-8 * amp);
  // No amplitude decay: beta = 1/4 conserves the discrete energy of a linear oscillator
  // exactly; what is left is the same tolerance error.
  EXPECT_LT(max_energy_dev, 1e-8 * e0);
  EXPECT_EQ(sim.stats().rejected, 0);
}

TEST(Newmark, SecondOrderConvergence) {
  test::TempDir dir("nm_conv");
  const Model probe = pair_model(dir, "");
  const double w = pair_omega(probe), T = 2 * M_PI / w * 2.3;
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const int n = 200 << k;
    Model m = pair_model(dir, fixed_step(T / n));
    m.particles.velocity[1] = Vec3(1.0, 0, 0);
    Simulation sim(m, m.step);
    for (int s = 0; s < n; ++s) sim.step();
    const double u = m.particles.position[1][0] - m.particles.position[0][0] - kL0;
    err[k] = std::abs(u - 1.0 / w * std::sin(w * sim.time()));
  }
  EXPECT_GT(err[0] / err[1], 3.5);  // O(h^2): ratio 4
  EXPECT_LT(err[0] / err[1], 4.5);
}

// A free block with random velocities, so the highest lattice mode is present.
Model random_block(const std::string& overrides_toml, unsigned seed = 3) {
  Model m = build_model(parse_case(R"([workpiece]
cells = [3, 3, 3]
radius = 0.5e-3
[rod]
youngs_modulus = 200e9
tensile_strength = 1e12
[integrator]
end_time = 1
)" + test::newmark_unless_named(overrides_toml),
                                   "block", {}));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (auto& v : m.particles.velocity) v = Vec3(u(rng), u(rng), u(rng));
  return m;
}

TEST(Newmark, FixedPointConvergesBelowTheLimitAndDivergesAbove) {
  // docs/physics.md section 7: a sweep contracts by about beta dt^2 omega_max^2 = (dt/dt_stable)^2.
  const Model probe = random_block("");
  const double ds = probe.derived.dt_stable;
  auto first_step = [&](double factor) {
    Model m = random_block(
        fmt::format("scheme = \"newmark\"\ndt = {:.17g}\ndt_max = {:.17g}\nmax_iterations = 400\n"
                    "tolerance = 1e-6\n",
                    factor * ds, 2 * ds));
    Simulation sim(m, m.step);
    sim.step();
    return std::make_pair(sim.stats(), sim.last_dt() / ds);
  };
  const auto [below, dt_below] = first_step(0.9);
  EXPECT_EQ(below.rejected, 0);
  EXPECT_GT(below.last_iterations, 20);  // slow contraction near the limit: about log(1e-6)/log(0.81) sweeps
  EXPECT_DOUBLE_EQ(dt_below, 0.9);
  const auto [above, dt_above] = first_step(1.15);
  EXPECT_GE(above.rejected, 1);  // diverged, rejected
  EXPECT_LT(dt_above, 1.0);      // and retried below the limit
  const auto [far_below, dt_far] = first_step(0.3);
  EXPECT_LE(far_below.last_iterations, 8);  // (0.3)^2 = 0.09 per sweep
}

TEST(Newmark, RelaxationContractsFasterAndConvergesBeyondTheLimit) {
  // Relaxed sweeps a <- (1 - w) a + w G(a) have eigenvalues 1 - w + w lambda, lambda in
  // [-L, 0], L about (dt/dt_stable)^2; the stable-step estimate is conservative, and the
  // plain iteration's sweeps at 0.9 dt_stable (39 here: 0.70 per sweep) put L at 0.86 of it.
  // With w = 0.75: at 0.9 the contraction is max(0.25, |1 - 0.75 x 1.70|) = 0.28 per sweep
  // (11 sweeps; 12 here); at 1.15 (L = 1.14), where the plain iteration diverges, 0.6 (27; 30);
  // beyond L = 2/w - 1 = 1.67, at 1.5 (L = 1.94), it diverges too.
  const Model probe = random_block("");
  const double ds = probe.derived.dt_stable;
  auto first_step = [&](double factor, double w) {
    Model m = random_block(
        fmt::format("scheme = \"newmark\"\ndt = {:.17g}\ndt_max = {:.17g}\nmax_iterations = 400\n"
                    "tolerance = 1e-6\nrelaxation = {}\n",
                    factor * ds, 2 * ds, w));
    Simulation sim(m, m.step);
    sim.step();
    return std::make_tuple(sim.stats(), sim.last_dt() / ds, m.particles.position);
  };
  const auto [plain, dt_plain, x_plain] = first_step(0.9, 1.0);
  const auto [relaxed, dt_relaxed, x_relaxed] = first_step(0.9, 0.75);
  EXPECT_EQ(relaxed.rejected, 0);
  EXPECT_DOUBLE_EQ(dt_relaxed, 0.9);
  EXPECT_GT(plain.last_iterations, 20);
  EXPECT_LT(relaxed.last_iterations, 16);
  // The same step: both stop when a sweep changes the forces by less than 1e-6 of their level.
  double dx = 0.0, disp = 0.0;
  for (std::size_t i = 0; i < x_plain.size(); ++i) {
    dx = std::max(dx, (x_plain[i] - x_relaxed[i]).norm());
    disp = std::max(disp, (x_plain[i] - probe.particles.position[i]).norm());
  }
  EXPECT_LT(dx, 1e-4 * disp);
  const auto [beyond, dt_beyond, x_beyond] = first_step(1.15, 0.75);
  EXPECT_EQ(beyond.rejected, 0);
  EXPECT_DOUBLE_EQ(dt_beyond, 1.15);
  EXPECT_GT(beyond.last_iterations, 20);
  const auto [far, dt_far, x_far] = first_step(1.5, 0.75);
  EXPECT_GE(far.rejected, 1);
  EXPECT_LT(dt_far, 1.5);
}

TEST(Newmark, RodBrokenOnlyInAnUnconvergedIterateStaysIntact) {
  // Relative coordinate u (stretch), w^2 = 2 kb/m, rho = h^2 w^2/4 = 1/2. Start compressed by
  // U with relative velocity U/h. First sweep (guess a+ = a): u1 = -U(1 - 2 rho) + U = U.
  // With the rod broken (a+ = 0): u = -U(1 - rho) + U = U/2. Converged intact: u = (U/2)/(1 + rho) = U/3.
  // A rod breaking at u = 0.75 U therefore breaks in the first sweep only.
  test::TempDir dir("nm_break");
  const Model probe = pair_model(dir, "");
  const double w = pair_omega(probe), h = std::sqrt(2.0) / w;
  const double U = 1e-6;  // m
  const double sigma_max = 200e9 * 0.75 * U / kL0;
  const std::string rod = fmt::format("tensile_strength = {:.17g}", sigma_max);
  auto run = [&](const std::string& integ) {
    Model m = pair_model(dir, integ, U, rod);
    m.particles.velocity[1] = Vec3(U / h, 0, 0);
    Simulation sim(m, m.step);
    sim.step();
    const double u = m.particles.position[1][0] - m.particles.position[0][0] - kL0;
    return std::make_tuple(sim.broken_rods(), u, sim.stats().last_iterations);
  };
  const auto [broken_nm, u_nm, sweeps] = run(fixed_step(h, 1e-10));
  EXPECT_EQ(broken_nm, 0u);
  EXPECT_NEAR(u_nm, U / 3, 1e-6 * U);
  EXPECT_GT(sweeps, 3);
  // The explicit scheme evaluates once at u = U (its predictor) and breaks the rod: the
  // scenario does reach the strength in the first iterate.
  const auto [broken_vv, u_vv,
              s_vv] = run(fmt::format("scheme = \"verlet\"\ndt = {:.17g}\nallow_unstable_dt = true\n", h));
  EXPECT_EQ(broken_vv, 1u);
  (void)u_vv;
  (void)s_vv;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(Newmark, RejectedStepLeavesNoTrace) {
  // A: first try at 1.5 dt_stable diverges, is rejected and retried at 0.75 (reject_factor 0.5).
  // B: starts at 0.75 directly. If the rejection left no trace, both runs are bit-identical.
  const Model probe = random_block("");
  const double ds = probe.derived.dt_stable;
  const std::string common = fmt::format("scheme = \"newmark\"\ndt_max = {:.17g}\nmax_iterations = 60\n", 2 * ds);
  Model ma = random_block(common + fmt::format("dt = {:.17g}\n", 1.5 * ds));
  Model mb = random_block(common + fmt::format("dt = {:.17g}\n", 0.75 * ds));
  Simulation a(ma, ma.step), b(mb, mb.step);
  for (int s = 0; s < 200; ++s) {
    a.step();
    b.step();
  }
  EXPECT_GE(a.stats().rejected, 1);
  EXPECT_EQ(b.stats().rejected, 0);
  EXPECT_TRUE(same_bits(ma.particles.position, mb.particles.position));
  EXPECT_TRUE(same_bits(ma.particles.velocity, mb.particles.velocity));
  EXPECT_TRUE(same_bits(ma.particles.acceleration, mb.particles.acceleration));
  EXPECT_TRUE(same_bits(ma.rods.shift, mb.rods.shift));
  EXPECT_TRUE(same_bits(ma.rods.intact, mb.rods.intact));
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.steps(), b.steps());
  EXPECT_EQ(a.ledger().external_work, b.ledger().external_work);
  EXPECT_EQ(a.kinetic_energy(), b.kinetic_energy());
}

TEST(Newmark, StopsBelowDtMinWithAMessage) {
  // A step far beyond the limit with a dt_min that forbids shrinking enough.
  const Model probe = random_block("");
  const double ds = probe.derived.dt_stable;
  Model m = random_block(
      fmt::format("scheme = \"newmark\"\ndt = {:.17g}\ndt_max = {:.17g}\ndt_min = {:.17g}\n", 3 * ds, 4 * ds, 2 * ds));
  Simulation sim(m, m.step);
  try {
    sim.step();
    FAIL() << "expected SimulationError";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("dt_min"), std::string::npos) << e.what();
  }
}

TEST(Newmark, StepControlGrowsAQuietStep) {
  // A block at rest under a slow pull converges in one or two sweeps: the step grows to dt_max.
  Model m = random_block("scheme = \"newmark\"\ndt_safety = 0.1\n");
  for (auto& v : m.particles.velocity) v = Vec3::Zero();
  Simulation sim(m, m.step);
  for (int s = 0; s < 40; ++s) sim.step();
  EXPECT_NEAR(sim.dt(), m.derived.dt_max, 1e-12 * m.derived.dt_max);
}

}  // namespace
}  // namespace swarf

// test_newton.cpp: the Newton-Krylov solve of the Newmark step (integrate/newton_newmark.cpp)
// against the discrete Newmark recurrence, the fixed-point solver, and its own guarantees:
// rejection without a trace, the same bits for any thread count, steps beyond the explicit
// limit.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <random>
#include <string>

#include "lattice_gen/lattice_file.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/simulation.h"
#include "swarf/state_archive.h"
#include "test_helpers.h"

namespace swarf {
namespace {

constexpr double kRadius = 0.5e-3, kL0 = 2 * kRadius;

// A straight chain of n particles along x joined by n - 1 rods: its motion along x is
// exactly linear (each rod's axis stays +x, so force and viscous stress are affine in x, v).
Model chain_model(const test::TempDir& dir, int n, const std::string& rod, const std::string& integrator) {
  Lattice lat;
  for (int i = 0; i < n; ++i) {
    lat.position.push_back(Vec3(i * kL0, 0, 0));
    lat.radius.push_back(kRadius);
  }
  for (int i = 0; i + 1 < n; ++i) {
    lat.bonds.push_back({i, i + 1});
    lat.rest_length.push_back(kL0);
  }
  write_lattice(dir / "chain.h5", lat);
  return build_model(parse_case("[workpiece]\nlattice_file = \"" + (dir / "chain.h5") +
                                    "\"\n[rod]\nyoungs_modulus = 200e9\n" + rod + "\n[integrator]\nend_time = 1\n" +
                                    integrator,
                                "chain", {}));
}

std::string newton_fixed_step(double h, double tol, double krylov_tol) {
  return fmt::format(
      "scheme = \"newmark\"\nsolver = \"newton\"\ndt = {:.17g}\ndt_min = {:.17g}\ndt_max = {:.17g}\n"
      "tolerance = {}\nkrylov_tolerance = {}\n",
      h, h, h, tol, krylov_tol);
}

// The Newmark step of the linear chain by dense linear algebra: with f(x, v) affine,
// (M + beta h^2 K + gamma h C) a+ = f(x*, v*) at the predictors x* = x + h v + h^2 (1/2 - beta) a,
// v* = v + h (1 - gamma) a.
struct DenseChain {
  int n = 0;
  double kb = 0, cv = 0, beta = 0.25, gamma = 0.5;  // rod stiffness E A / L0 (N/m), viscous c = eta A / L0 (kg/s)
  Eigen::VectorXd mass, x, v, a, l0;
  Eigen::VectorXd force(const Eigen::VectorXd& xs, const Eigen::VectorXd& vs) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    for (int k = 0; k + 1 < n; ++k) {
      const double t = kb * (xs[k + 1] - xs[k] - l0[k]) + cv * (vs[k + 1] - vs[k]);  // tension, N
      f[k] += t;
      f[k + 1] -= t;
    }
    return f;
  }
  void step(double h) {
    Eigen::MatrixXd J = mass.asDiagonal();
    for (int k = 0; k + 1 < n; ++k) {
      const double s = beta * h * h * kb + gamma * h * cv;
      J(k, k) += s;
      J(k + 1, k + 1) += s;
      J(k, k + 1) -= s;
      J(k + 1, k) -= s;
    }
    const Eigen::VectorXd xs = x + h * v + h * h * (0.5 - beta) * a, vs = v + h * (1 - gamma) * a;
    const Eigen::VectorXd an = J.ldlt().solve(force(xs, vs));
    x = xs + beta * h * h * an;
    v = vs + gamma * h * an;
    a = an;
  }
};

void linear_chain_matches_the_recurrence(const std::string& rod) {
  test::TempDir dir("nt_chain");
  const int n = 8;
  const Model probe = chain_model(dir, n, rod, "");
  const double h = 5.0 * probe.derived.dt_stable;  // beyond the explicit limit (chain: 3.5 x its own)
  // tolerance 1e-9: the residual cannot drop much below the rounding of the rod strains (x
  // near 1e-2 m, stretches near 1e-8 m: 1e-10 relative); CG solves to 1e-12.
  Model m = chain_model(dir, n, rod, newton_fixed_step(h, 1e-9, 1e-12));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (auto& vel : m.particles.velocity) vel = Vec3(u(rng), 0, 0);
  Simulation sim(m, m.step);
  DenseChain ref;
  ref.n = n;
  ref.kb = m.rods.law.youngs_modulus * m.rods.area / kL0;
  ref.cv = m.rods.law.viscosity * m.rods.area / kL0;
  ref.mass.resize(n);
  ref.x.resize(n);
  ref.v.resize(n);
  ref.l0 = Eigen::VectorXd::Constant(n - 1, kL0);
  for (int i = 0; i < n; ++i) {
    ref.mass[i] = m.particles.mass[i];
    ref.x[i] = m.particles.position[i][0];
    ref.v[i] = m.particles.velocity[i][0];
  }
  ref.a = ref.force(ref.x, ref.v).cwiseQuotient(ref.mass);
  double max_dx = 0.0, max_u = 0.0, max_dv = 0.0, max_v = 0.0;
  for (int s = 0; s < 40; ++s) {
    sim.step();
    ref.step(h);
    ASSERT_EQ(sim.stats().last_iterations, 1) << "step " << s;  // linear: one Newton iteration
    for (int i = 0; i < n; ++i) {
      max_dx = std::max(max_dx, std::abs(m.particles.position[i][0] - ref.x[i]));
      max_u = std::max(max_u, std::abs(ref.x[i] - i * kL0));
      max_dv = std::max(max_dv, std::abs(m.particles.velocity[i][0] - ref.v[i]));
      max_v = std::max(max_v, std::abs(ref.v[i]));
    }
  }
  EXPECT_EQ(sim.stats().rejected, 0);
  // Both solve the same linear system per step, one by CG to 1e-12 (exact here in at most
  // 8 iterations), one by a dense LDL^T: what separates them is rounding. Positions near
  // 7e-3 m have an ulp of 8.7e-19 m; displacements reach 6e-7 m, so 1e-10 of them is about 70
  // ulps (seen: about 5). The velocities take gamma h a+, and a+ is as good as the residual
  // tolerance, 1e-9 of the force level (seen: 1.4e-10 of the largest velocity). A wrong
  // beta, gamma or tangent would be off by O(1) of the motion.
  EXPECT_LT(max_dx, 1e-10 * max_u);
  EXPECT_LT(max_dv, 1e-9 * max_v);
}

TEST(Newton, LinearChainFollowsTheDiscreteRecurrenceInOneIteration) { linear_chain_matches_the_recurrence(""); }

TEST(Newton, DampedLinearChainFollowsTheDiscreteRecurrenceInOneIteration) {
  linear_chain_matches_the_recurrence("damping_ratio = 0.05");
}

// A free block with random velocities, so that the highest lattice mode is present.
Model random_block(const std::string& integrator, int cells = 3, unsigned seed = 3) {
  Model m = build_model(parse_case(fmt::format(R"([workpiece]
cells = [{0}, {0}, {0}]
radius = 0.5e-3
[rod]
youngs_modulus = 200e9
tensile_strength = 1e12
[integrator]
end_time = 1
)",
                                               cells) +
                                       integrator,
                                   "block", {}));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (auto& v : m.particles.velocity) v = Vec3(u(rng), u(rng), u(rng));
  return m;
}

std::string newton_block(double dt, double dt_max) {
  return fmt::format("scheme = \"newmark\"\nsolver = \"newton\"\ndt = {:.17g}\ndt_max = {:.17g}\n", dt, dt_max);
}

TEST(Newton, ConvergesAtFiveAndTenTimesTheStableStepWhereSweepsDiverge) {
  const Model probe = random_block("");
  const double ds = probe.derived.dt_stable;
  for (double factor : {5.0, 10.0}) {
    Model fp = random_block(
        fmt::format("scheme = \"newmark\"\ndt = {:.17g}\ndt_max = {:.17g}\n", factor * ds, factor * ds));
    Simulation a(fp, fp.step);
    a.step();
    EXPECT_GE(a.stats().rejected, 1) << factor;  // the sweeps diverge and the step is retried shorter
    EXPECT_LT(a.last_dt(), ds) << factor;
    Model nt = random_block(newton_block(factor * ds, factor * ds));
    Simulation b(nt, nt.step);
    const double e0 = b.kinetic_energy() + b.elastic_energy();
    for (int s = 0; s < 10; ++s) b.step();
    EXPECT_EQ(b.stats().rejected, 0) << factor;
    EXPECT_DOUBLE_EQ(b.last_dt(), factor * ds) << factor;
    EXPECT_LE(b.stats().max_iterations, 4) << factor;  // (linear up to the geometric nonlinearity)
    // Newmark beta = 1/4 conserves the energy of the linear motion; what is left is the
    // rods' geometric nonlinearity (strains near 1e-5 here) and the tolerance 1e-6: 1e-3 is
    // far above both and far below a blow-up or an O(1) numerical damping.
    const double e1 = b.kinetic_energy() + b.elastic_energy();
    EXPECT_NEAR(e1, e0, 1e-3 * e0) << factor;
  }
}

}  // namespace
}  // namespace swarf

// test_newton.cpp: the Newton-Krylov solve of the Newmark step (integrate/newton.cpp)
// against the discrete Newmark recurrence, the fixed-point solver, and its own guarantees:
// rejection without a trace, the same bits for any thread count, steps beyond the explicit
// limit.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <map>
#include <random>
#include <string>

#include "lattice_gen/lattice_file.h"
#include "scenes/block_on_floor.h"
#include "scenes/scheme.h"
#include "scenes/tiny_cut.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "study/hypre_amg.h"
#include "swarf/core/errors.h"
#include "swarf/core/state_archive.h"
#include "swarf/simulation.h"
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
    lat.rods.push_back({i, i + 1});
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
  ref.kb = std::get<RodLaw>(m.rods.law).youngs_modulus * m.rods.area / kL0;
  ref.cv = std::get<RodLaw>(m.rods.law).viscosity * m.rods.area / kL0;
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
                                       test::newmark_unless_named(integrator),
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

// A small bar pulled along x into yield (bar yield strain 3e-3) to 6e-3, between grips that
// hold the axial component of their end layers.
Model yield_bar(const std::string& integrator) {
  return build_model(parse_case(R"([workpiece]
cells = [4, 2, 2]
radius = 0.5e-3
[material]
density = 7800.0
mass_basis = "cell"
[rod]
youngs_modulus = 200e9
yield_strain = 1.0e-3
hardening_modulus = 20e9
tensile_strength = 1.0e10
damping_ratio = 0.1
[uniaxial]
axis = "x"
grip_layers = 1
grip_dofs = "axis"
strain_path = [0.0, 0.006]
strain_rate = 200.0
[integrator]
)" + test::newmark_unless_named(integrator),
                                "bar", {}));
}

struct BarEnd {
  double reaction;      // N: axial force of the far grip at the end of the path
  double plastic_work;  // J
  std::vector<double> shift;
  StepStats stats;
  NewtonStats newton;
};

BarEnd pull(const std::string& integrator) {
  Model m = yield_bar(integrator);
  Simulation sim(m, m.step);
  const double T = 0.006 / 200.0;  // s
  while (sim.time() < T * (1 - 1e-12)) sim.step(T - sim.time());
  double fx = 0.0;
  for (std::size_t g = 0; g < m.groups.size(); ++g) fx = std::max(fx, std::abs(sim.group_reaction(g)[0]));
  return {fx, sim.ledger().plastic_work, m.rods.shift, sim.stats(), sim.newton_stats()};
}

TEST(Newton, BarPulledIntoYieldAgreesWithSmallFixedPointSteps) {
  const double ds = yield_bar("").derived.dt_stable;
  // Reference: fixed-point sweeps at 0.2 of the stable step, tolerance 1e-9; and at 0.4, to
  // see how far the time discretisation alone moves the result.
  auto fixed = [&](double f) {
    return pull(
        fmt::format("scheme = \"newmark\"\ndt = {0:.17g}\ndt_max = {0:.17g}\ntolerance = 1e-9\n"
                    "max_iterations = 200\niterations_shrink = 150\n",
                    f * ds));
  };
  const BarEnd ref = fixed(0.2), ref2 = fixed(0.4);
  const BarEnd nt = pull(
      fmt::format("scheme = \"newmark\"\nsolver = \"newton\"\ndt = {0:.17g}\ndt_max = {1:.17g}\ntolerance = 1e-8\n",
                  0.5 * ds, 8 * ds));
  ASSERT_GT(ref.plastic_work, 0.0);  // the bar yielded
  EXPECT_GT(nt.stats.accepted, 0);
  EXPECT_LT(nt.stats.accepted, ref.stats.accepted / 10);  // far longer steps
  const double spread = std::abs(ref2.reaction - ref.reaction) / ref.reaction;
  const double dev = std::abs(nt.reaction - ref.reaction) / ref.reaction;
  const double dev_w = std::abs(nt.plastic_work - ref.plastic_work) / ref.plastic_work;
  double dshift = 0.0, smax = 0.0;
  for (std::size_t k = 0; k < ref.shift.size(); ++k) {
    dshift = std::max(dshift, std::abs(nt.shift[k] - ref.shift[k]));
    smax = std::max(smax, std::abs(ref.shift[k]));
  }
  // The path is quasi-static (the load takes 30 us, the wave crosses the bar in about 1 us),
  // so the end force is set by the rods' states, not by the step; what separates the runs is
  // the ringing sampled at different steps and Newmark's O(h^2) error on it. Seen at 8 x the
  // stable step (40 x the reference's): end force 9e-5, shifts 1.6e-3 of the largest, plastic
  // work 5.6e-3 (the ledger's sigma d(eps0) takes the end-of-step stress, first order in the
  // step: hardening between a step's start and end shows up there, not in the state). The
  // bounds: 1e-3 on the force (the issue's 1 % of the peak stress, with room), 1e-2 on the
  // shifts and on the plastic work.
  RecordProperty("reaction_spread_0.2_0.4", fmt::format("{:.3g}", spread));
  RecordProperty("reaction_dev_newton", fmt::format("{:.3g}", dev));
  EXPECT_LT(dev, 1e-3) << "fixed-point spread " << spread;
  EXPECT_LT(dshift, 1e-2 * smax);
  EXPECT_LT(dev_w, 1e-2);
}

TEST(Newton, RodYieldingInsideAStepCommitsTheSameStateAsTheSweeps) {
  // One rod between two particles, set stretching at a speed whose elastic amplitude would
  // be twice the yield strain: it yields at omega t = 0.52, inside the second step of
  // 0.3/omega (below the fixed-point limit, so both solvers take the same steps), goes on
  // hardening and unloads elastically: Newton meets both branch switches inside its
  // iterations. Both solve the same discrete equations, to 1e-11 (sweeps) and
  // 1e-11 (Newton), so the committed shifts agree to about that relative to the strain.
  test::TempDir dir("nt_yield");
  auto run = [&](const std::string& solver) {
    const std::string rod = "yield_strain = 1e-3\nhardening_modulus = 20e9\n";
    Model probe = chain_model(dir, 2, rod, "");
    const double w = std::sqrt(2 * probe.derived.rod_stiffness / probe.particles.mass[0]), h = 0.3 / w;
    Model m = chain_model(dir, 2, rod,
                          fmt::format("scheme = \"newmark\"\nsolver = \"{}\"\ndt = {:.17g}\ndt_min = {:.17g}\n"
                                      "dt_max = {:.17g}\ntolerance = 1e-11\nkrylov_tolerance = 1e-12\n"
                                      "max_iterations = 200\n",
                                      solver, h, h, h));
    const double v_rel = 2e-3 * kL0 * w;  // elastic amplitude: twice the yield strain
    m.particles.velocity[0] = Vec3(-0.5 * v_rel, 0, 0);
    m.particles.velocity[1] = Vec3(0.5 * v_rel, 0, 0);
    Simulation sim(m, m.step);
    std::vector<double> shifts;
    int yielded_at = -1;
    for (int s = 0; s < 20; ++s) {
      sim.step();
      shifts.push_back(m.rods.shift[0]);
      if (yielded_at < 0 && m.rods.shift[0] != 0.0) yielded_at = s;
    }
    return std::make_tuple(shifts, yielded_at, sim.stats().max_iterations, sim.ledger().plastic_work);
  };
  const auto [s_fp, y_fp, it_fp, w_fp] = run("fixed_point");
  const auto [s_nt, y_nt, it_nt, w_nt] = run("newton");
  ASSERT_GT(y_fp, 0);     // elastic at first, then yielding inside a step
  EXPECT_EQ(y_nt, y_fp);  // the same step
  // (Newton's first iterate is placed with a_n, the same predictor as the sweeps'; when
  // that already lies on the plastic branch, the tangent is the hardening slope from the
  // start and the step, linear on the branch, converges in one iteration.)
  for (std::size_t k = 0; k < s_fp.size(); ++k) EXPECT_NEAR(s_nt[k], s_fp[k], 1e-9 * std::abs(s_fp.back())) << k;
  EXPECT_NEAR(w_nt, w_fp, 1e-8 * w_fp);
  (void)it_fp;
  (void)it_nt;
}

// The whole state as named fields' bytes (the state visit), to compare two states field by field.
class RecordArchive final : public StateArchive {
 public:
  bool loading() const override { return false; }
  void array(std::string_view n, std::vector<double>& v, std::size_t) override { put(n, v); }
  void array(std::string_view n, std::vector<Vec3>& v, std::size_t) override { put(n, v); }
  void array(std::string_view n, std::vector<Quat>& v, std::size_t) override { put(n, v); }
  void array(std::string_view n, std::vector<std::uint8_t>& v, std::size_t) override { put(n, v); }
  void array(std::string_view n, std::vector<std::int32_t>& v, std::size_t) override { put(n, v); }
  void array(std::string_view n, std::vector<std::int64_t>& v, std::size_t) override { put(n, v); }
  void scalar(std::string_view n, double& v) override { put_bytes(n, &v, sizeof v); }
  void scalar(std::string_view n, std::int64_t& v) override { put_bytes(n, &v, sizeof v); }
  std::map<std::string, std::string> fields;

 private:
  template <class T>
  void put(std::string_view n, const std::vector<T>& v) {
    put_bytes(n, v.data(), v.size() * sizeof(T));
  }
  void put_bytes(std::string_view n, const void* p, std::size_t bytes) {
    fields[std::string(n)] = std::string(static_cast<const char*>(p), bytes);
  }
};

TEST(Newton, RejectedStepLeavesNoTrace) {
  // A block with random velocities at 5 x the stable step, asked for a residual below the
  // rounding (1e-15) within 3 Newton iterations: the try is rejected after its solves have
  // moved the particles and the rods' trial state, and the retry (at half the step) would be
  // below dt_min, so the step stops there. Everything but the rejection's own counters and
  // the next step size must be as before the try, bit for bit.
  const Model probe = random_block("");
  const double ds = probe.derived.dt_stable;
  Model m = random_block(
      fmt::format("scheme = \"newmark\"\nsolver = \"newton\"\ndt = {0:.17g}\ndt_max = {0:.17g}\n"
                  "dt_min = {1:.17g}\ntolerance = 1e-15\nmax_iterations = 3\n"
                  "iterations_grow = 1\niterations_shrink = 2\n",
                  5 * ds, 4 * ds));
  Simulation sim(m, m.step);
  RecordArchive before, after;
  const std::uint64_t hash_before = sim.state_hash();
  sim.visit_state(before);
  EXPECT_THROW(sim.step(), SimulationError);
  sim.visit_state(after);
  EXPECT_EQ(sim.stats().rejected, 1);
  EXPECT_EQ(sim.newton_stats().solves, 3);  // the try did solve (and move things) before it was rejected
  ASSERT_EQ(before.fields.size(), after.fields.size());
  for (const auto& [name, bytes] : before.fields) {
    if (name == "dt" || name == "stats/rejected" || name == "stats/force_evaluations") continue;
    EXPECT_TRUE(after.fields.at(name) == bytes) << name;
  }
  EXPECT_NE(sim.state_hash(), hash_before);  // (only through the counters listed above)
}

// Runs the Model that 'make' builds for 'steps' steps on 1 and on 2 threads: the state hashes
// and the Krylov iteration counts must be equal.
template <class Make>
void expect_same_bits_for_one_and_two_threads(Make&& make, int steps) {
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    Model m = make();
    Simulation sim(m, m.step);
    for (int s = 0; s < steps; ++s) sim.step();
    return std::make_pair(sim.state_hash(), sim.newton_stats().krylov_iterations);
  };
  const int saved = omp_get_max_threads();
  const auto one = run(1), two = run(2);
  omp_set_num_threads(saved);
  EXPECT_GT(one.second, 0);
  EXPECT_EQ(one.first, two.first);
  EXPECT_EQ(one.second, two.second);
}

TEST(Newton, SameBitsForOneAndTwoThreads) {
  // 8^3 cells: 2,457 particles and 14,000 rods, more than one fixed block (2048) of each, so
  // that the block sums and the static partition differ between 1 and 2 threads.
  const Model probe = random_block("", 8);
  const double ds = probe.derived.dt_stable;
  expect_same_bits_for_one_and_two_threads([&] { return random_block(newton_block(2 * ds, 6 * ds), 8); }, 6);
}

TEST(Newton, RefusesTheExplicitScheme) {
  EXPECT_THROW(random_block("scheme = \"verlet\"\nsolver = \"newton\"\n"), InputError);
}

// ---- Johnson-Cook's rate factor --------------------------------------------------------------

// A chain of 5 particles (4 rods) along x, the left end fixed and the right pulled at v, with the
// Johnson-Cook law on the rod route (C45's rate sensitivity 0.0134, rate_ref 1/s, the paper's
// single slope, damping 0.1): the 3 free particles are Newton's unknowns. Pulled slowly (the load
// takes 1 ms, the wave crosses the chain in about 1 us), every rod strains at the chain's rate
// v / (4 L0), 3/s here, and flows on the law's monotonic curve at S = 1 + C ln(3):
//     sigma = E eps - (E - k) q,  q = (E eps - S s_y) / (E - k + S k)   (johnson_cook_rod_law.h).
Model jc_chain(const test::TempDir& dir, double rate, const std::string& integrator) {
  const int n = 5;
  const double v = rate * (n - 1) * kL0;
  return chain_model(dir, n,
                     "law = \"johnson_cook\"\nrate_sensitivity = 0.0134\nreference_rate = 1.0\n"
                     "yield_strain = 1e-3\nhardening_modulus = 20e9\ntensile_strength = 1e12\ndamping_ratio = 0.1\n",
                     test::newmark_unless_named(integrator) +
                         fmt::format("\n[[group]]\nname = \"left\"\nside = \"x-\"\n"
                                     "[[group]]\nname = \"right\"\nside = \"x+\"\nmotion = \"velocity\"\n"
                                     "velocity = [{:.17g}, 0.0, 0.0]\n",
                                     v));
}

TEST(Newton, JohnsonCookChainPulledAtConstantRateTakesFullStepsWithTheLaggedRateFactor) {
  // Newton reads Johnson-Cook's rate factor at each rod's rate at the step's start (newton.cpp),
  // so its residual is the piecewise-linear law at a fixed scale and its tangent has no rate
  // term: full steps (10 stable steps), no rejection, 1-2 iterations per step. The price: the
  // held factor is an explicit dashpot of slope C sigma / rate, far stiffer at these rates than
  // a step of 10 stable steps can carry explicitly; the rods' rates and R then ring
  // in a bounded cycle (R is flat below rate_ref and logarithmic above) instead of settling at
  // the chain's rate. Seen: the stress within 0.038 S s_y of the closed form at every step (and
  // 0.025, 0.031, 0.048 at 1, 2 and 10/s); 921 steps, 1761 iterations. With R read at the iterate's rate (before the
  // lag) it was exact to 1e-6 here, and it is the cut (validation/integrators/README.md) where that form failed, not
  // this chain: this test does not reproduce that failure. The bound 0.05 S s_y holds the cycle's amplitude. Its mean
  // over the flowing rods and steps is what says that R is read at the right rate: seen +0.0034 S s_y; R = 1, or R at a
  // rate off by a factor e, would shift it by C ln 3 / S = 0.0145 or C / S = 0.013, so the bound is 0.007.
  test::TempDir dir("nt_jc");
  const double rate = 3.0, C = 0.0134, E = 200e9, k = 20e9, sy = E * 1e-3;
  const double S = 1.0 + C * std::log(rate);
  const double ds = jc_chain(dir, rate, "").derived.dt_stable;
  Model m = jc_chain(
      dir, rate, fmt::format("scheme = \"newmark\"\nsolver = \"newton\"\ndt = {0:.17g}\ndt_max = {0:.17g}\n", 10 * ds));
  Simulation sim(m, m.step);
  const double T = 3e-3 / rate;  // s: to three times the yield strain
  double deviation = 0.0, longest = 0.0, bias = 0.0;
  int flowing = 0;
  auto closed = [&](std::size_t r) {
    const auto& x = m.particles.position;
    const double eps = (x[m.rods.ends[r][1]][0] - x[m.rods.ends[r][0]][0] - kL0) / kL0;
    const double q = (E * eps - S * sy) / (E - k + S * k);
    return q > 0.0 ? E * eps - (E - k) * q : E * eps;
  };
  while (sim.time() < T * (1 - 1e-12)) {
    sim.step(T - sim.time());
    longest = std::max(longest, sim.last_dt());
    for (std::size_t r = 0; r < m.rods.size(); ++r) {
      deviation = std::max(deviation, std::abs(m.rods.stress[r] - closed(r)) / (S * sy));
      if (m.rods.shift[r] != 0.0) {
        ++flowing;
        bias += (m.rods.stress[r] - closed(r)) / (S * sy);
      }
    }
  }
  bias /= std::max(flowing, 1);
  RecordProperty("deviation", fmt::format("{:.3g}", deviation));
  RecordProperty("mean_deviation", fmt::format("{:.3g}", bias));
  EXPECT_GT(flowing, 0);
  EXPECT_EQ(sim.stats().rejected, 0);
  EXPECT_GT(longest, 9.9 * ds);
  EXPECT_LE(sim.stats().max_iterations, 4);
  EXPECT_LT(double(sim.stats().iterations) / double(sim.stats().accepted), 2.5);
  EXPECT_LT(deviation, 0.05);
  EXPECT_LT(std::abs(bias), 0.007);
}

// ---- contacts ------------------------------------------------------------------------------

// The block on a tilted floor of the friction tests (tests/scenes/block_on_floor.h), solved
// by Newton with steps up to 'dt_max_factor' x the explicit stable step.
Model newton_block_on_floor(double angle, double mu, double dt_max_factor, std::array<int, 3> cells = {2, 2, 1}) {
  test::BlockOnFloor b;
  b.cells = cells;
  const Model probe = build_model(parse_case(test::block_on_floor_case(b), "probe", {}));
  b.angle = angle;
  b.mu = mu;
  b.integrator = fmt::format("scheme = \"newmark\"\nsolver = \"newton\"\ndt_max = {:.17g}\nend_time = 1",
                             dt_max_factor * probe.derived.dt_stable);
  return build_model(parse_case(test::block_on_floor_case(b), "block", {}));
}

double mean_x(const Model& m) { return test::mean_x(m.particles.position); }

TEST(Newton, WithContactsABlockSticksBelowTheFrictionAngleAndSlidesAboveAtTenTimesTheStableStep) {
  // The friction test of test_contacts.cpp (explicit there), solved by Newton with the
  // contacts' tangent at steps of up to 10 x the explicit stable step, where the fixed-point
  // sweeps diverge. Closed forms: at rest the floor carries the block's weight, m g cos(angle)
  // normal to it and m g sin(angle) along it (sticking); sliding, x = a t^2 / 2 with
  // a = g (sin - mu cos).
  const double mu = 0.4, g = 9.81, T = 0.02;
  for (const double ratio : {0.5, 1.6}) {
    const double angle = std::atan(ratio * mu);
    Model m = newton_block_on_floor(angle, mu, 10.0);
    Simulation sim(m, m.step);
    const double x0 = mean_x(m), dt_stable = m.derived.dt_stable;
    double longest = 0.0;
    while (sim.time() < T) {
      sim.step(T - sim.time());
      longest = std::max(longest, sim.last_dt());
    }
    // The step grew to its cap, far beyond the explicit limit, and few were rejected.
    EXPECT_GT(longest, 9.9 * dt_stable);
    EXPECT_LT(sim.stats().rejected, sim.stats().accepted / 20);
    // Newton iterations per step: the contacts' tangent is what keeps them few. Seen: 2.9
    // (sticking) and 4.0 (sliding) with it; 7.1 and 6.1 with the contacts left out of J (the
    // rods' tangent alone), where the floor's stiffness is met by the residual check only.
    EXPECT_LT(double(sim.stats().iterations) / double(sim.stats().accepted), 5.0);
    const double moved = mean_x(m) - x0;
    double mass = 0;
    for (double mi : m.particles.mass) mass += mi;
    const Vec3 on_floor = sim.mesh_force(0);  // the force the particles exert on the floor
    if (ratio < 1) {
      // Sticking: only the elastic tangential springs give (micrometres at most).
      EXPECT_LT(std::abs(moved), 2e-6) << "moved " << moved;
      // At rest (restitution 0.2 and the rods' damping have ended the settling long before
      // 20 ms): 0.5 % covers what is left of it; a contact force missing from the residual
      // or a wrong tangent that stopped short of equilibrium would be off by its whole size.
      EXPECT_NEAR(-on_floor[2], mass * g * std::cos(angle), 5e-3 * mass * g);
      EXPECT_NEAR(on_floor[0], mass * g * std::sin(angle), 5e-3 * mass * g);
    } else {
      // Sliding: the block settles onto the floor in the first milliseconds, so allow 10 % (as
      // the explicit test does).
      const double a = g * (std::sin(angle) - mu * std::cos(angle));
      EXPECT_NEAR(moved, 0.5 * a * T * T, 0.1 * 0.5 * a * T * T);
    }
  }
}

TEST(Newton, WithContactsSameBitsForOneAndTwoThreads) {
  // A 12 x 12 x 4 cell block (more particles than one fixed block of the sums, 2048) sliding
  // down the floor, its bottom layer in contact: the block sums and the static partitions of
  // the particles and the contact pairs differ between 1 and 2 threads.
  expect_same_bits_for_one_and_two_threads(
      [] {
        return newton_block_on_floor(std::atan(1.6 * 0.4), 0.4, 10.0, {12, 12, 4});
      },
      40);
}

// ---- an assembled tangent and a preconditioner handed in (integrate/tangent_matrix.h) --------

// Preconditions CG with J^-1 itself, from the assembled J (a sparse LDL^T): if the assembly is
// J (the matrix-free product's operator), CG converges in one iteration per Newton iteration,
// to round-off. Also records how far the assembled J is from symmetric.
class ExactTangentSolve final : public LinearPreconditioner {
 public:
  std::string name() const override { return "exact"; }
  bool wants_tangent(std::size_t) override { return true; }
  void setup(const TangentMatrix& J) override {
    const int n = static_cast<int>(J.rows());
    std::vector<Eigen::Triplet<double>> t;
    for (int r = 0; r < n; ++r)
      for (std::int64_t e = J.row_start[r]; e < J.row_start[r + 1]; ++e) t.emplace_back(r, J.column[e], J.value[e]);
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(t.begin(), t.end());
    const Eigen::SparseMatrix<double> at = a.transpose();
    asymmetry = std::max(asymmetry, (a - at).norm() / a.norm());
    solver.compute(a);
    ASSERT_EQ(solver.info(), Eigen::Success);  // (J symmetric positive definite)
    ++setups;
  }
  void apply(const double* r, double* z) override {
    const int n = static_cast<int>(solver.rows());
    Eigen::Map<Eigen::VectorXd>(z, n) = solver.solve(Eigen::Map<const Eigen::VectorXd>(r, n));
  }
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  double asymmetry = 0.0;
  int setups = 0;
};

// The tiny cut (tests/scenes/tiny_cut.h) solved by Newton: rods that yield and break, the tool's
// triangles and, once rods have broken, sphere-sphere contacts.
Model newton_tiny_cut() {
  std::string text = test::kTinyCut;
  const std::string scheme = "scheme = \"newmark\"\n";
  text.insert(text.find(scheme) + scheme.size(), "solver = \"newton\"\n");
  return build_model(parse_case(text, "tiny_cut", {}));
}

TEST(Newton, AnAssembledTangentSolvedExactlyNeedsOneCgIterationPerNewtonIteration) {
  // Each CG solve preconditioned by the assembled J's own inverse stops after one iteration,
  // its residual at round-off (1e-12 of the first against the 1e-2 it asks): so the assembly
  // holds every block the matrix-free product applies (rods, grips' removed components, tool
  // triangles, sphere-sphere contacts). A block left out leaves CG a residual of that block's
  // size and a second iteration. The assembled J is symmetric to round-off.
  {
    Model m = yield_bar(newton_fixed_step(2.0 * yield_bar("").derived.dt_stable, 1e-6, 1e-2));
    Simulation sim(m, m.step);
    auto exact = std::make_shared<ExactTangentSolve>();
    sim.set_newton_preconditioner(exact);
    for (int s = 0; s < 60; ++s) sim.step();
    EXPECT_GT(sim.newton_stats().solves, 60);
    EXPECT_EQ(sim.newton_stats().krylov_iterations, sim.newton_stats().solves);
    EXPECT_EQ(exact->setups, sim.newton_stats().solves);
    EXPECT_LT(exact->asymmetry, 1e-14);
    EXPECT_GT(sim.ledger().plastic_work, 0.0);  // (the rods yielded)
  }
  {
    Model m = newton_tiny_cut();
    Simulation sim(m, m.step);
    auto exact = std::make_shared<ExactTangentSolve>();
    sim.set_newton_preconditioner(exact);
    std::size_t pairs = 0;
    while (sim.time() < 1.5e-5) {
      sim.step();
      pairs = std::max(pairs, sim.contacts().touching_pairs());
    }
    EXPECT_GT(pairs, 0u);
    EXPECT_GT(sim.broken_rods(), 0u);
    EXPECT_EQ(sim.newton_stats().krylov_iterations, sim.newton_stats().solves);
    EXPECT_LT(exact->asymmetry, 1e-14);
  }
}

TEST(Newton, BoomerAmgPreconditionsTheCutInFewerCgIterationsWithTheSameBitsOnOneAndTwoThreads) {
  if (!HypreAmg::available()) GTEST_SKIP() << "built without hypre";
  // hypre's BoomerAMG (one V-cycle per application) in place of the block-Jacobi on the tiny
  // cut: fewer CG iterations per Newton iteration (seen 1.07 against 3.12 over 150 steps), the
  // same bits on 1 and 2 threads (Debian's hypre has no OpenMP).
  auto run = [](int threads, bool amg, int steps) {
    omp_set_num_threads(threads);
    Model m = newton_tiny_cut();
    Simulation sim(m, m.step);
    if (amg) sim.set_newton_preconditioner(std::make_shared<HypreAmg>());
    for (int s = 0; s < steps; ++s) sim.step();
    return std::make_tuple(sim.state_hash(), sim.newton_stats(), m.particles.position);
  };
  const int saved = omp_get_max_threads();
  const auto [h1, s1, x1] = run(1, true, 150);
  const auto [h2, s2, x2] = run(2, true, 150);
  const auto [hb, sb, xb] = run(1, false, 150);
  EXPECT_EQ(h1, h2);
  EXPECT_EQ(s1.krylov_iterations, s2.krylov_iterations);
  const double amg_per_solve = double(s1.krylov_iterations) / double(s1.solves);
  const double jacobi_per_solve = double(sb.krylov_iterations) / double(sb.solves);
  EXPECT_LT(amg_per_solve, 0.75 * jacobi_per_solve) << amg_per_solve << " against " << jacobi_per_solve;
  // Both solve each step's residual to the same tolerance (1e-6 of the force level), so they
  // follow one another until the cut's breakage and contacts amplify the difference (seen:
  // largest 3e-8 m after 5 steps, 1e-5 m after 20, median 2e-5 m after 150). After 5 steps
  // they must agree within 1e-3 R (1e-7 m); a preconditioner that changed the problem (a
  // prescribed component moved, say) would not.
  const auto [h5, s5, x5] = run(1, true, 5);
  const auto [hb5, sb5, xb5] = run(1, false, 5);
  omp_set_num_threads(saved);
  double dmax = 0.0;
  for (std::size_t i = 0; i < x5.size(); ++i) dmax = std::max(dmax, (x5[i] - xb5[i]).norm());
  EXPECT_LT(dmax, 1e-7) << "largest position difference after 5 steps, m";
}

}  // namespace
}  // namespace swarf

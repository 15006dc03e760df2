// test_density_floor.cpp: a neighbourhood compacted beyond the onset pushes back with the bulk
// modulus (rod.compaction_modulus, forces/density_floor.h), against closed forms on an FCC block
// whose positions are set by a map (one evaluation of the rods, RodSystem::forces), against the
// gradient of its own energy, and on one and two threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "case_errors.h"
#include "scenes/fcc_world.h"
#include "scenes/pulled_bar.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/domains/domain_run.h"
#include "swarf/simulation.h"
#include "swarf/systems/rod_system.h"

namespace swarf {
namespace {

constexpr double kE = 2e11, kYield = 1e-3, kR = 1e-3;  // rod modulus (Pa), yield strain (1), radius (m)
constexpr double kK = 1.6e11, kOnset = 0.01;           // the floor's K (Pa) and theta_0 (1)

// A 4 x 4 x 4-cell FCC block of R = 1 mm with the paper's law at k = 0 (perfectly plastic), its
// positions x -> c + F (x - c) about the block's centre, then each moved by 'jitter' (m) at random.
World mapped_block(const Eigen::Matrix3d& F, double modulus, double jitter = 0.0) {
  World w = test::mapped_fcc_block(kR, {4, 4, 4}, F, kE, kYield);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (Vec3& x : w.particles.position) x += Vec3(u(rng), u(rng), u(rng));
  w.rods.compaction_modulus = modulus;
  w.rods.compaction_onset = kOnset;
  return w;
}

// The floor's force on every particle and its energy, from one evaluation of the rods.
struct Floor {
  std::vector<Vec3> force;
  std::vector<double> theta;
  double energy = 0.0;
};
Floor evaluate(World& w) {
  RodSystem rods;
  rods.setup(w);
  rods.forces(w);
  Floor f;
  const Vec3* force = rods.floor_force(w);
  f.force.assign(force, force + w.particles.size());
  f.theta = rods.floor().dilatation();
  f.energy = rods.floor().energy();
  return f;
}

// The particles whose 12 lattice neighbours are all there (more than a lattice spacing from every face).
std::vector<std::size_t> interior(const World& w) {
  std::vector<std::size_t> in;
  const Particles& p = w.particles;
  Vec3 lo = p.initial_position[0], hi = lo;
  for (const Vec3& x : p.initial_position) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 x = p.initial_position[i];
    if (((x - lo).minCoeff() > 2.1 * kR) && ((hi - x).minCoeff() > 2.1 * kR)) in.push_back(i);
  }
  return in;
}

// Compressed uniformly by 2 % a particle with its 12 neighbours has rho = 12 w(0.98), so theta =
// -(12 (w(0.98) - w(1))) / 4 = 3 (-0.02) exactly in the kernel's linear part, g = -0.05, U = 1/2 K V
// g^2 with V = 4 sqrt 2 R^3; by symmetry its force is zero (to the rounding of the pairs' sums);
// every particle's forces add up to zero (Newton's third law per pair). A face's particles, with
// fewer neighbours, read as dilated. (Tolerances: rounding of the lengths, 1e-12 relative.)
TEST(DensityFloor, AUniformCompressionMatchesTheClosedForm) {
  const double s = 0.98;
  World w = mapped_block(s * Eigen::Matrix3d::Identity(), kK);
  const Floor f = evaluate(w);
  const double V = 4.0 * std::sqrt(2.0) * kR * kR * kR, g = 3.0 * (s - 1.0) + kOnset;
  const double scale = 3.0 * kK * V * std::abs(g) / (4.0 * 2 * kR);  // (one pair's push)
  const std::vector<std::size_t> in = interior(w);
  ASSERT_GT(in.size(), 20u);
  double interior_energy = 0.0;
  for (const std::size_t i : in) {
    EXPECT_NEAR(f.theta[i], 3.0 * (s - 1.0), 1e-12) << "particle " << i;
    EXPECT_LT(f.force[i].norm(), 1e-10 * scale) << "particle " << i;
    interior_energy += 0.5 * kK * V * g * g;
  }
  Vec3 total = Vec3::Zero();
  double outer_energy = 0.0;
  for (std::size_t i = 0; i < f.force.size(); ++i) {
    total += f.force[i];
    if (std::find(in.begin(), in.end(), i) == in.end())
      outer_energy += 0.5 * kK * V * std::pow(std::min(f.theta[i] + kOnset, 0.0), 2);
  }
  EXPECT_LT(total.norm(), 1e-10 * scale);
  EXPECT_NEAR(f.energy, interior_energy + outer_energy, 1e-12 * f.energy);
  // (a corner particle, with 3 of its 12 neighbours, reads as dilated)
  EXPECT_GT(*std::max_element(f.theta.begin(), f.theta.end()), 0.0);
  // (the floor's push against a rod's: at 2 % a yielded rod of the plain lattice pushes with E eps_y A)
  EXPECT_GT(2 * scale, 10 * kE * kYield * 1e-6);
}

// Below the onset, and under a simple shear (which keeps the volume), nothing is added: no force,
// no energy, to the bit.
TEST(DensityFloor, NothingBelowTheOnsetNorUnderAShear) {
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear(0, 2) = 0.1;
  for (const Eigen::Matrix3d& F : {Eigen::Matrix3d(0.997 * Eigen::Matrix3d::Identity()), shear}) {
    World w = mapped_block(F, kK);
    const Floor f = evaluate(w);
    EXPECT_EQ(f.energy, 0.0);
    for (const Vec3& x : f.force) ASSERT_EQ(x, Vec3::Zero());
  }
}

// The force is minus the gradient of the energy: on a block compressed by 3 % and shaken by 2 % of
// R, the floor's force on a few particles against central differences of its energy. (Tolerance:
// central differences with a step of 1e-9 m err by about h^2 times the energy's third derivative
// and by a cancellation of 1e-16 U / h; 1e-6 of the largest force.)
TEST(DensityFloor, TheForceIsMinusTheGradientOfItsEnergy) {
  World w = mapped_block(0.97 * Eigen::Matrix3d::Identity(), kK, 0.02 * kR);
  const Floor f = evaluate(w);
  double scale = 0.0;
  for (const Vec3& x : f.force) scale = std::max(scale, x.norm());
  ASSERT_GT(scale, 0.0);
  const double h = 1e-9;
  for (const std::size_t i : {std::size_t(0), w.particles.size() / 3, w.particles.size() / 2}) {
    for (int c = 0; c < 3; ++c) {
      World plus = w, minus = w;
      plus.particles.position[i][c] += h;
      minus.particles.position[i][c] -= h;
      const double grad = (evaluate(plus).energy - evaluate(minus).energy) / (2 * h);
      EXPECT_NEAR(f.force[i][c], -grad, 1e-6 * scale) << "particle " << i << " component " << c;
    }
  }
}

// The same forces and energy, to the bit, on one thread and on two.
TEST(DensityFloor, TheSameBitsOnOneAndTwoThreads) {
  const int threads = omp_get_max_threads();
  World one = mapped_block(0.97 * Eigen::Matrix3d::Identity(), kK, 0.02 * kR), two = one;
  omp_set_num_threads(1);
  const Floor a = evaluate(one);
  omp_set_num_threads(2);
  const Floor b = evaluate(two);
  omp_set_num_threads(threads);
  EXPECT_EQ(a.energy, b.energy);
  for (std::size_t i = 0; i < a.force.size(); ++i) ASSERT_EQ(a.force[i], b.force[i]) << i;
}

// Between two builds of its lists the floor skips the particles its bound proves inactive; the
// forces and the energy are those of summing every particle, to the bit. A block whose left half is
// compressed by 3 % (active) and right half by 0.1 % (inactive), squeezed a little further at each
// of 30 evaluations (by less than the lists' skin: one build), against the same with every
// particle summed.
TEST(DensityFloor, TheBoundSkipsOnlyWhatIsInactiveToTheBit) {
  World w = mapped_block(Eigen::Matrix3d::Identity(), kK, 0.002 * kR);
  const std::vector<Vec3> x0 = w.particles.position;
  double xmid = 0.0;
  for (const Vec3& x : x0) xmid += x[0] / double(x0.size());
  DensityFloor fast, exact;
  exact.always_exact(true);
  const Particles& p = w.particles;
  int active = 0, inactive = 0;
  for (int step = 0; step < 30; ++step) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double squeeze = (x0[i][0] < xmid ? 0.03 : 0.001) + 1e-5 * step;
      w.particles.position[i] = x0[i] * (1.0 - squeeze);
    }
    fast.evaluate(p.position.data(), p.radius.data(), p.size(), w.periodic, kK, kOnset);
    exact.evaluate(p.position.data(), p.radius.data(), p.size(), w.periodic, kK, kOnset);
    ASSERT_EQ(fast.energy(), exact.energy()) << "evaluation " << step;
    for (std::size_t i = 0; i < p.size(); ++i) ASSERT_EQ(fast.force()[i], exact.force()[i]) << step << " " << i;
    if (step == 29)
      for (std::size_t i = 0; i < p.size(); ++i) (exact.dilatation()[i] < -kOnset ? active : inactive) += 1;
  }
  EXPECT_GT(active, 20);  // (both kinds are there)
  EXPECT_GT(inactive, 20);
  EXPECT_GT(fast.energy(), 0.0);
}

// A periodic width of less than twice the floor's reach is refused by name (the nearest image would
// not be the only one in reach), and one flung particle does not stretch the search over empty space.
TEST(DensityFloor, ANarrowPeriodRefusedAndAFlungParticleFound) {
  World w = mapped_block(0.97 * Eigen::Matrix3d::Identity(), kK);
  DensityFloor floor;
  const Particles& p = w.particles;
  try {
    floor.evaluate(p.position.data(), p.radius.data(), p.size(), Periodic::along_y(4.5 * kR), kK, kOnset);
    FAIL() << "a period of 4.5 R was taken";
  } catch (const InputError& e) {
    test::expect_mentions(e.what(), {"rod.compaction_modulus", "periodic width"});
  }
  DensityFloor near, far;
  near.evaluate(p.position.data(), p.radius.data(), p.size(), w.periodic, kK, kOnset);
  const double energy = near.energy();
  w.particles.position.push_back(Vec3(1e3, 0.0, 0.0));  // (a km away: alone)
  w.particles.radius.push_back(kR);
  far.evaluate(p.position.data(), p.radius.data(), p.size(), w.periodic, kK, kOnset);
  EXPECT_EQ(far.energy(), energy);
  EXPECT_EQ(far.force()[p.size() - 1], Vec3::Zero());
}

// The floor's force reaches the particles through the step: a free block compressed by 3 % springs
// apart under its elastic rods and the floor, and Verlet keeps kinetic + elastic energy (the rods'
// and the floor's) to its O((omega dt)^2) error (omega dt = 0.01 here: 1e-4 relative, tolerance 1e-3);
// without the floor the same block gains a quarter less kinetic energy.
TEST(DensityFloor, AFreeCompressedBlockKeepsItsEnergyThroughTheStep) {
  double kinetic[2] = {0.0, 0.0};
  for (const double modulus : {0.0, kK}) {
    World w = test::mapped_fcc_block(kR, {4, 4, 4}, 0.97 * Eigen::Matrix3d::Identity(), kE, 1.0);  // (elastic)
    w.rods.compaction_modulus = modulus;
    w.rods.compaction_onset = kOnset;
    StepSettings s;
    s.scheme = Scheme::Verlet;
    s.dt = 1e-6;  // (1 kg particles on rods of E A / 2R = 1e8 N/m: omega = 1e4 /s)
    s.length_scale = 2 * kR;
    s.stiffness_scale = kE * w.rods.area / (2 * kR);
    Simulation sim(w, s);
    sim.step();
    const double start = sim.kinetic_energy() + sim.elastic_energy();
    for (int k = 0; k < 200; ++k) sim.step();
    const double end = sim.kinetic_energy() + sim.elastic_energy();
    EXPECT_NEAR(end, start, 1e-3 * start) << "K = " << modulus;
    kinetic[modulus > 0.0] = sim.kinetic_energy();
  }
  EXPECT_GT(kinetic[1], 1.25 * kinetic[0]);
}

// The keys reach the rods; Newton and the domains refuse the floor by name, and an onset without a
// modulus is refused.
TEST(DensityFloor, TheKeysReachTheRodsAndNewtonDomainsRefuseThem) {
  auto with = [](std::string text, const std::string& keys) {
    text.insert(text.find("[rod]\n") + 6, keys);
    return text;
  };
  test::PulledBar verlet;
  verlet.integrator = "end_time = 1e-6\nscheme = \"verlet\"";
  const std::string floor = "compaction_modulus = 1.6e11\n";
  const Model m = build_model(
      parse_case(with(test::pulled_bar_case(verlet), floor + "compaction_onset = 0.02\n"), "floor.toml", {}));
  EXPECT_EQ(m.rods.compaction_modulus, 1.6e11);
  EXPECT_EQ(m.rods.compaction_onset, 0.02);
  EXPECT_EQ(build_model(parse_case(test::pulled_bar_case({}), "plain.toml", {})).rods.compaction_modulus, 0.0);
  std::string domains;
  try {
    DomainRun::check_supported(m, m.step);
  } catch (const InputError& e) {
    domains = e.what();
  }
  test::expect_mentions(domains, {"rod.compaction_modulus"});
  test::expect_mentions(
      test::case_error(with(test::pulled_bar_case(verlet), "compaction_onset = 0.02\n"), {}, "onset.toml"),
      {"onset.toml", "compaction_onset", "0.02"});
  test::PulledBar newton;
  newton.integrator = "end_time = 1e-6\nscheme = \"newmark\"\nsolver = \"newton\"";
  test::expect_mentions(test::case_error(with(test::pulled_bar_case(newton), floor), {}, "newton.toml"),
                        {"newton.toml", "rod.compaction_modulus"});
}

}  // namespace
}  // namespace swarf

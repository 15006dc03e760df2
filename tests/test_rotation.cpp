// test_rotation.cpp: quaternion rotation (paper eqs. 2-7, 12-13): a torque-free asymmetric
// body conserves energy and angular momentum and keeps |q| = 1, shows the intermediate-axis
// instability, and a body under constant torque follows the closed form; plus the
// Simulation's rotational stage.
#include <gtest/gtest.h>

#include <cmath>

#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/laws/rotation.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

const Vec3 kI(1.0, 2.0, 3.0);  // kg m^2, asymmetric

TEST(Quaternion, ProductAndFrames) {
  // 90 degrees about z maps x to y.
  const Quat q(std::cos(M_PI / 4), 0, 0, std::sin(M_PI / 4));
  const Vec3 y = to_world(q, Vec3(1, 0, 0));
  EXPECT_NEAR(y[0], 0.0, 1e-15);
  EXPECT_NEAR(y[1], 1.0, 1e-15);
  const Vec3 back = to_body(q, y);
  EXPECT_NEAR(back[0], 1.0, 1e-15);
  // Hamilton product: i j = k.
  const Quat k = qmul(Quat(0, 1, 0, 0), Quat(0, 0, 1, 0));
  EXPECT_EQ(k, Quat(0, 0, 0, 1));
}

TEST(Euler, ThirdRowDividesByIz) {
  // The paper prints /Ix in the third row (a typo); with Ix != Iz the torque about z must
  // give dwz = lz / Iz.
  const Vec3 dw = euler_acceleration(Vec3(0, 0, 6.0), Vec3::Zero(), kI);
  EXPECT_DOUBLE_EQ(dw[2], 2.0);
}

struct Drift {
  double energy, momentum, norm;
};

// Largest relative drift of energy and |L| (world) and of |q| - 1 over a time T.
Drift free_spin(double h, double T, const RotationSettings& rs) {
  RotState s;
  s.w = Vec3(0.4, 0.05, 1.1);                        // rad/s, mostly about the major axis
  s.dw = euler_acceleration(Vec3::Zero(), s.w, kI);  // a consistent start (gyroscopic acceleration)
  const double e0 = rotational_energy(s, kI);
  const Vec3 l0 = angular_momentum_world(s, kI);
  Drift d{0, 0, 0};
  const int n = static_cast<int>(std::lround(T / h));
  for (int k = 0; k < n; ++k) {
    s = rotation_step(s, Vec3::Zero(), kI, h, rs).state;
    d.energy = std::max(d.energy, std::abs(rotational_energy(s, kI) - e0) / e0);
    d.momentum = std::max(d.momentum, (angular_momentum_world(s, kI) - l0).norm() / l0.norm());
    d.norm = std::max(d.norm, std::abs(s.q.norm() - 1.0));
  }
  return d;
}

TEST(Rotation, TorqueFreeBodyConservesEnergyAndMomentum) {
  for (double beta : {0.25, 0.0}) {  // implicit Newmark and the explicit variant
    RotationSettings rs;
    rs.beta = beta;
    rs.tolerance = 1e-14;
    const Drift a = free_spin(0.01, 20.0, rs), b = free_spin(0.005, 20.0, rs);
    // The Newmark update on the quaternion coefficients with rescaling is not exactly
    // conservative; its errors are O(h^2): with |w| h = 0.012 they stay below 1e-4 over
    // about four turns (measured 1e-6 in energy, 4e-5 in L), and halving h divides them
    // by 4 (3..5 allows for higher terms).
    EXPECT_LT(a.energy, 1e-4) << "beta " << beta;
    EXPECT_LT(a.momentum, 1e-4) << "beta " << beta;
    EXPECT_GT(a.energy / b.energy, 3.0) << "beta " << beta;
    EXPECT_LT(a.energy / b.energy, 5.0) << "beta " << beta;
    EXPECT_GT(a.momentum / b.momentum, 3.0) << "beta " << beta;
    EXPECT_LT(a.momentum / b.momentum, 5.0) << "beta " << beta;
    // |q| = 1 is restored by scaling every step.
    EXPECT_LT(a.norm, 1e-15);
  }
}

// Spin about principal axis 'axis' with a 1e-3 perturbation; returns the smallest value of
// the spin component along that axis (relative to its start) over 60 s.
double min_spin_fraction(int axis) {
  RotState s;
  s.w = Vec3::Constant(1e-3);
  s.w[axis] = 1.0;
  s.dw = euler_acceleration(Vec3::Zero(), s.w, kI);
  double lowest = 1.0;
  RotationSettings rs;
  for (int k = 0; k < 12000; ++k) {
    s = rotation_step(s, Vec3::Zero(), kI, 0.005, rs).state;
    lowest = std::min(lowest, s.w[axis] / 1.0);
  }
  return lowest;
}

TEST(Rotation, IntermediateAxisIsUnstable) {
  // Spin about the smallest and the largest axis is stable; about the intermediate one the
  // perturbation grows and the body flips (the spin component changes sign).
  EXPECT_GT(min_spin_fraction(0), 0.99);
  EXPECT_GT(min_spin_fraction(2), 0.99);
  EXPECT_LT(min_spin_fraction(1), -0.9);
}

TEST(Rotation, ConstantTorqueFollowsTheClosedForm) {
  // Spin about principal axis z with torque lz: w = w0 + (lz/Iz) t, angle w0 t + lz t^2/(2 Iz),
  // q = [cos(angle/2), 0, 0, sin(angle/2)].
  const double w0 = 2.0, lz = 1.5, T = 3.0;
  auto error = [&](double h) {
    RotState s;
    s.w = Vec3(0, 0, w0);
    s.dw = Vec3(0, 0, lz / kI[2]);
    RotationSettings rs;
    rs.tolerance = 1e-14;
    const int n = static_cast<int>(std::lround(T / h));
    for (int k = 0; k < n; ++k) s = rotation_step(s, Vec3(0, 0, lz), kI, h, rs).state;
    const double angle = w0 * T + 0.5 * lz / kI[2] * T * T;
    const Quat exact(std::cos(angle / 2), 0, 0, std::sin(angle / 2));
    EXPECT_NEAR(s.w[2], w0 + lz / kI[2] * T, 1e-3);
    EXPECT_NEAR(s.w[0], 0.0, 1e-14);
    return (s.q - exact).norm();
  };
  const double e1 = error(0.01), e2 = error(0.005);
  EXPECT_LT(e1, 1e-3);
  EXPECT_GT(e1 / e2, 3.0);  // second order
  EXPECT_LT(e1 / e2, 5.0);
}

TEST(Rotation, SimulationStageSpinsParticles) {
  // With the rotational stage on, free spheres without torque spin at a constant rate, in
  // both schemes, and the kinetic energy includes rotation. Their orientation turns by the
  // closed form (the update is exact for a constant rate, to rounding: 1e-9 after 100 steps
  // is far above it) when output.orientations asks for it, and stays as it was otherwise
  // (nothing in a sphere's dynamics depends on it); the rates are the same either way.
  for (const char* scheme : {"verlet", "newmark"}) {
    std::vector<Vec3> omega[2];
    for (const bool orientations : {true, false}) {
      // Free particles (bonded ones turn with their body and do not spin by themselves).
      Model m = build_model(parse_case(std::string("[[particle]]\nposition = [0.0, 0.0, 0.0]\nradius = 0.5e-3\n"
                                                   "[[particle]]\nposition = [0.01, 0.0, 0.0]\nradius = 0.5e-3\n"
                                                   "[contact]\n[output]\norientations = ") +
                                           (orientations ? "true" : "false") +
                                           "\n[integrator]\nend_time = 1\nscheme = \"" + scheme + "\"\n",
                                       "spin", {}));
      for (auto& w : m.particles.omega) w = Vec3(0, 0, 100.0);
      Simulation sim(m, m.step);
      sim.set_rotations(true);
      const double e0 = sim.kinetic_energy();
      EXPECT_GT(e0, 0.0);
      for (int k = 0; k < 100; ++k) sim.step();
      const double angle = 100.0 * sim.time();
      EXPECT_NEAR(m.particles.orientation[0][3], orientations ? std::sin(angle / 2) : 0.0, 1e-9) << scheme;
      EXPECT_EQ(m.particles.orientation[1][0], orientations ? m.particles.orientation[0][0] : 1.0) << scheme;
      EXPECT_NEAR(sim.kinetic_energy(), e0, 1e-12 * e0) << scheme;
      omega[orientations] = m.particles.omega;
    }
    EXPECT_EQ(omega[0], omega[1]) << scheme;
  }
}

}  // namespace
}  // namespace swarf

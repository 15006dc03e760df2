// test_particle_fields.cpp: the per-particle fields (measure/particle_fields.h) against closed
// forms. The virial stress of an interior particle under a homogeneous deformation is the
// Cauchy-Born crystal's stress times det F (the same sum over the 6 bond directions, over the
// reference volume a^3/4); a contact's part is -R f/V along its normal; the plastic strain
// fitted to rods whose plastic strains come from one tensor gives back that tensor's von Mises
// equivalent; the von Mises stress of uniaxial, shear and hydrostatic states.
#include <gtest/gtest.h>

#include <cmath>

#include "lattice_gen/cauchy_born.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/measure/particle_fields.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

const char* kBlock = R"(
[workpiece]
cells = [5, 5, 5]
radius = 0.5e-3
[rod]
youngs_modulus = 200e9
yield_strain = 1e-3
hardening_modulus = 20e9
[integrator]
end_time = 1e-6
)";

int rods_of(const Model& m, std::size_t i) { return m.rods.row_start[i + 1] - m.rods.row_start[i]; }

// Strains of 1e-4 (elastic): the rod strain's rounding (len - L0) is ~1e-12 of it; the virial
// and the Cauchy-Born sum add the same 12 terms in another order. Tolerance 1e-9 of |sigma|.
void check_virial(const Eigen::Matrix3d& H) {
  Model m = build_model(parse_case(kBlock, "fields", {}));
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + H;
  for (std::size_t i = 0; i < m.particles.size(); ++i) m.particles.position[i] = F * m.particles.initial_position[i];
  Simulation sim(m, m.step);  // evaluates the rods' forces of this state
  const ParticleFields f = particle_fields(m.particles, m.rods, m.periodic, &sim.contacts());
  const CauchyBornCrystal crystal(m.rods.law, m.derived.cell_edge, m.derived.rod_area);
  const Eigen::Matrix3d want = crystal.evaluate(F).sigma * F.determinant();
  const double scale = want.norm();
  ASSERT_GT(scale, 0.0);
  int interior = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i) {
    if (rods_of(m, i) != 12) continue;
    ++interior;
    const auto& s = f.stress[i];
    const double got[6] = {s[0], s[1], s[2], s[3], s[4], s[5]};
    const double exp[6] = {want(0, 0), want(1, 1), want(2, 2), want(0, 1), want(1, 2), want(0, 2)};
    for (int c = 0; c < 6; ++c) ASSERT_NEAR(got[c], exp[c], 1e-9 * scale) << "particle " << i << " component " << c;
    ASSERT_NEAR(hydrostatic(f.stress[i]), want.trace() / 3.0, 1e-9 * scale);
    ASSERT_NEAR(von_mises(f.stress[i]), von_mises({exp[0], exp[1], exp[2], exp[3], exp[4], exp[5]}), 1e-9 * scale);
  }
  EXPECT_GT(interior, 50);
}

TEST(ParticleFields, InteriorVirialStressIsTheCauchyBornStressUnderStretch) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  H(0, 0) = 1e-4;
  check_virial(H);
}

TEST(ParticleFields, InteriorVirialStressIsTheCauchyBornStressUnderAGeneralDeformation) {
  Eigen::Matrix3d H;
  H << 0.8e-4, 0.3e-4, -0.2e-4, 0.1e-4, -0.5e-4, 0.4e-4, 0.25e-4, -0.15e-4, 0.6e-4;
  check_virial(H);
}

// Rod plastic strains set from one tensor Ep (shift = n.Ep.n / ((E - k)/E)): every particle
// whose rods span the 6 directions gets Ep's von Mises equivalent back; a uniaxial isochoric
// Ep = diag(e, -e/2, -e/2) has the equivalent e. Tolerance 1e-10 relative (a 6 x 6 solve).
TEST(ParticleFields, PlasticStrainOfRodsFromOneTensorIsItsVonMisesEquivalent) {
  Model m = build_model(parse_case(kBlock, "fields", {}));
  const double e = 0.02,
               to_plastic = (std::get<RodLaw>(m.rods.law).youngs_modulus - std::get<RodLaw>(m.rods.law).hardening) /
                            std::get<RodLaw>(m.rods.law).youngs_modulus;
  Eigen::Matrix3d ep = Eigen::Matrix3d::Zero();
  ep.diagonal() << e, -0.5 * e, -0.5 * e;
  for (std::size_t k = 0; k < m.rods.size(); ++k) {
    const auto [i, j] = m.rods.ends[k];
    const Vec3 n = (m.particles.position[j] - m.particles.position[i]).normalized();
    m.rods.shift[k] = n.dot(ep * n) / to_plastic;
  }
  const ParticleFields f = particle_fields(m.particles, m.rods, m.periodic, nullptr);
  int interior = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (rods_of(m, i) == 12) {
      ++interior;
      ASSERT_NEAR(f.plastic_strain[i], e, 1e-10 * e) << i;
    }
  EXPECT_GT(interior, 50);
  // Shear: Ep = g/2 (e_x e_y + e_y e_x) has the equivalent g / sqrt(3).
  ep.setZero();
  ep(0, 1) = ep(1, 0) = 0.5 * e;
  for (std::size_t k = 0; k < m.rods.size(); ++k) {
    const auto [i, j] = m.rods.ends[k];
    const Vec3 n = (m.particles.position[j] - m.particles.position[i]).normalized();
    m.rods.shift[k] = n.dot(ep * n) / to_plastic;
  }
  const ParticleFields g = particle_fields(m.particles, m.rods, m.periodic, nullptr);
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (rods_of(m, i) == 12) {
      ASSERT_NEAR(g.plastic_strain[i], e / std::sqrt(3.0), 1e-10 * e) << i;
    }
}

// Two spheres pressed together at rest: each carries -R f/V along the line of centres (f the
// Hertz force's magnitude, from the evaluation's own particle force), nothing across it.
TEST(ParticleFields, ContactStressIsMinusRadiusTimesForceOverVolume) {
  Model m = build_model(parse_case(R"([material]
density = 2800.0
[[particle]]
position = [0.0, 0.0, 0.0]
radius = 0.01
[[particle]]
position = [0.0199, 0.0, 0.0]
radius = 0.01
[contact]
youngs_modulus = 48e9
friction = 0.0
[integrator]
end_time = 1e-6
)",
                                   "two", {}));
  Simulation sim(m, m.step);
  const double push = m.particles.force[0][0];  // on sphere 0, away from sphere 1: negative
  ASSERT_LT(push, 0.0);
  const ParticleFields f = particle_fields(m.particles, m.rods, m.periodic, &sim.contacts());
  const double v = particle_volume(0.01);
  EXPECT_NEAR(v, 4.0 * std::sqrt(2.0) * 1e-6, 1e-20);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(f.stress[i][0], 0.01 * push / v, 1e-12 * std::abs(push / v * 0.01)) << i;
    for (int c = 1; c < 6; ++c) EXPECT_EQ(f.stress[i][c], 0.0) << i << " " << c;
    EXPECT_NEAR(von_mises(f.stress[i]), std::abs(f.stress[i][0]), 1e-12 * std::abs(f.stress[i][0]));
  }
}

TEST(ParticleFields, VonMisesOfUniaxialShearAndHydrostaticStates) {
  EXPECT_NEAR(von_mises({5.0, 0, 0, 0, 0, 0}), 5.0, 1e-14);
  EXPECT_NEAR(von_mises({0, 0, 0, 2.0, 0, 0}), 2.0 * std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(von_mises({0, 0, 0, 0, 0, -2.0}), 2.0 * std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(von_mises({7.0, 7.0, 7.0, 0, 0, 0}), 0.0, 1e-14);
  EXPECT_NEAR(von_mises({1.0, -1.0, 0, 0, 0, 0}), std::sqrt(3.0), 1e-14);
}

}  // namespace
}  // namespace swarf

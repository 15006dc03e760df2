// test_patch.cpp: patch tests of the bonded lattice. A homogeneous deformation x = F X
// gives zero net force on every interior particle, and the stored energy of the closed form
// W = 1/2 eps:C:eps with the FCC constants C11 = 2 kb/a, C12 = C44 = kb/a (docs/physics.md
// section 1) times the volume the rods represent.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

const char* kCase = R"(
[workpiece]
cells = [5, 5, 5]
radius = 0.5e-3
[rod]
youngs_modulus = 200e9
[integrator]
end_time = 1e-6
)";

struct PatchResult {
  double max_interior_force = 0;  // N
  double max_surface_force = 0;   // N
  double energy = 0;              // J
  Model model;
};

PatchResult deform(const Eigen::Matrix3d& F) {
  PatchResult out{0, 0, 0, build_model(parse_case(kCase, "patch", {}))};
  Model& m = out.model;
  for (std::size_t i = 0; i < m.particles.size(); ++i) m.particles.position[i] = F * m.particles.initial_position[i];
  Simulation sim(m, m.step);  // evaluates the forces of the given state
  for (std::size_t i = 0; i < m.particles.size(); ++i) {
    const int rods = m.rods.row_start[i + 1] - m.rods.row_start[i];
    const double f = m.particles.force[i].norm();
    if (rods == 12)
      out.max_interior_force = std::max(out.max_interior_force, f);
    else
      out.max_surface_force = std::max(out.max_surface_force, f);
  }
  out.energy = sim.elastic_energy();
  return out;
}

// Continuum energy of the small strain eps in the rods' volume: the rods are stored once, six
// per particle in the bulk, each particle standing for a^3/4; on a cube of cells all six
// bond directions are equally frequent, so the rods represent M/6 particles' volume.
double closed_form_energy(const Model& m, const Eigen::Matrix3d& eps) {
  const double kb = m.derived.rod_stiffness, a = m.derived.cell_edge;
  const double c11 = 2 * kb / a, c12 = kb / a, c44 = kb / a;
  const double w = 0.5 * c11 * (eps(0, 0) * eps(0, 0) + eps(1, 1) * eps(1, 1) + eps(2, 2) * eps(2, 2)) +
                   c12 * (eps(0, 0) * eps(1, 1) + eps(1, 1) * eps(2, 2) + eps(2, 2) * eps(0, 0)) +
                   2 * c44 * (eps(0, 1) * eps(0, 1) + eps(1, 2) * eps(1, 2) + eps(2, 0) * eps(2, 0));
  const double volume = double(m.rods.size()) / 6.0 * a * a * a / 4.0;
  return w * volume;
}

// Strains of 1e-6: the rod strain |F n| - 1 differs from n.eps.n by O(|H|^2), so the energy
// matches the quadratic closed form to a relative O(1e-6); the subtraction len - L0 loses
// about 1e-10 relative. Tolerance 1e-4 relative.
void check(const Eigen::Matrix3d& H) {
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + H;
  const Eigen::Matrix3d eps = 0.5 * (H + H.transpose());
  PatchResult r = deform(F);
  const double rod_force = r.model.derived.rod_stiffness * r.model.derived.nn_distance * H.norm();
  // Interior: zero to rounding (each rod force is ~1e-10 relative exact; 1e-6 of a rod force is far above).
  EXPECT_LT(r.max_interior_force, 1e-6 * rod_force);
  const double want = closed_form_energy(r.model, eps);
  EXPECT_NEAR(r.energy, want, 1e-4 * std::abs(want));
  // The test can fail: the surfaces do carry unbalanced forces under a non-rigid deformation.
  if (eps.norm() > 0) {
    EXPECT_GT(r.max_surface_force, 1e-2 * rod_force);
  }
}

TEST(Patch, UniaxialStrainGivesC11) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  H(0, 0) = 1e-6;
  check(H);
}

TEST(Patch, BiaxialStrainGivesC12) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  H(0, 0) = 1e-6;
  H(1, 1) = -0.7e-6;
  check(H);
}

TEST(Patch, ShearGivesC44) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  H(0, 1) = 1e-6;
  H(1, 0) = 1e-6;
  check(H);
}

TEST(Patch, GeneralDeformationWithRotation) {
  Eigen::Matrix3d H;
  H << 0.8, -0.3, 0.5, 0.9, -0.4, 0.2, -0.1, 0.6, 0.3;
  check(1e-6 * H);
}

TEST(Patch, RigidTranslationAndRotationStoreNothing) {
  // A finite rotation (30 degrees) leaves every rod length unchanged: no force, no energy.
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.5236, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  PatchResult r = deform(Q);
  const double kb = r.model.derived.rod_stiffness, d = r.model.derived.nn_distance;
  EXPECT_LT(r.max_interior_force, 1e-12 * kb * d);
  EXPECT_LT(r.max_surface_force, 1e-12 * kb * d);
  EXPECT_LT(r.energy, 1e-20 * kb * d * d);
}

TEST(Patch, Youngs100FromTheCubicConstants) {
  // E along [100] of a cubic crystal: (C11 - C12)(C11 + 2 C12)/(C11 + C12) = 4 kb/(3a).
  Model m = build_model(parse_case(kCase, "patch", {}));
  const double c11 = m.derived.c11, c12 = m.derived.c12;
  EXPECT_NEAR(m.derived.youngs_modulus_100, (c11 - c12) * (c11 + 2 * c12) / (c11 + c12),
              1e-14 * m.derived.youngs_modulus_100);
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// Rod parameters derived from macroscopic [100] properties reproduce them through the
// lattice relations (the same relations the hysteresis bar is measured against).
TEST(MaterialConversion, RodLawFromMacroscopicProperties) {
  const char* text = R"(
[workpiece]
cells = [3, 3, 3]
radius = 0.1e-3
[material]
density = 7800.0
youngs_modulus = 210e9
yield_stress = 400e6
hardening_modulus = 2e9
tensile_strength = 600e6
[integrator]
scheme = "newmark"
end_time = 1e-6
)";
  const Model m = build_model(parse_case(text, "macro", {}));
  const Derived& d = m.derived;
  EXPECT_TRUE(d.converted);
  EXPECT_NEAR(d.youngs_modulus_100, 210e9, 1e-12 * 210e9);
  EXPECT_NEAR(d.bar_yield_stress, 400e6, 1e-12 * 400e6);
  EXPECT_NEAR(d.bar_hardening_tangent, 2e9, 1e-12 * 2e9);
  EXPECT_NEAR(d.bar_failure_stress, 600e6, 1e-12 * 600e6);
  // kb = 3 a E100 / 4 and the rod modulus E = kb L0 / A.
  EXPECT_NEAR(d.rod_stiffness, 0.75 * d.cell_edge * 210e9, 1e-12 * d.rod_stiffness);
  // Giving the rod law as well is refused.
  try {
    build_model(parse_case(std::string(text) + "[rod]\nyield_strain = 1e-3\n", "macro", {}));
    ADD_FAILURE() << "rod law and material properties both accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rod.yield_strain"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace swarf

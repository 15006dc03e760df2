// test_plastic_volume.cpp: rods whose plastic flow keeps the volume (rod.isochoric_plasticity,
// forces/plastic_volume.h), against closed forms on an FCC block whose positions are set by an
// affine map (no dynamics: one evaluation of the rods, RodSystem::forces).
#include <gtest/gtest.h>

#include <cmath>

#include "scenes/fcc_world.h"
#include "scenes/pulled_bar.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/domains/domain_run.h"
#include "swarf/systems/rod_system.h"

namespace swarf {
namespace {

constexpr double kE = 2e11, kYield = 1e-3;  // rod modulus (Pa) and yield strain (1): perfectly plastic

// A 6 x 6 x 6-cell FCC block of R = 1 mm with the paper's single-slope law at k = 0, its
// positions mapped by x -> F x about the block's centre.
World mapped_block(const Eigen::Matrix3d& F, bool isochoric) {
  World w = test::mapped_fcc_block(1e-3, {6, 6, 6}, F, kE, kYield);
  w.rods.isochoric = isochoric;
  return w;
}

// Each particle's mean trial increment over its intact rods.
std::vector<double> mean_increments(const World& w) {
  const Rods& r = w.rods;
  std::vector<double> m(w.particles.size(), 0.0);
  for (std::size_t i = 0; i < m.size(); ++i) {
    int c = 0;
    for (std::int32_t e = r.row_start[i]; e < r.row_start[i + 1]; ++e) {
      m[i] += r.trial_shift[r.entries[e].rod] - r.shift[r.entries[e].rod];
      ++c;
    }
    m[i] /= c;
  }
  return m;
}

// Under a uniform compression by 0.5 % (five yield strains) every rod of the plain lattice
// yields: at k = 0 its stress stops at -E eps_y and its shift is eps + eps_y = -0.004 (the
// lattice loses volume plastically). With isochoric plasticity every rod proposes that same
// increment, every particle's mean is it, and the first pass takes it all off: no rod yields,
// and the stress is the elastic E eps. (Tolerances: rounding of the means and of the strains.)
TEST(PlasticVolume, PressureAloneYieldsThePlainLatticeAndNotTheIsochoricOne) {
  const double s = 1.0 - 5e-3;
  const Eigen::Matrix3d F = s * Eigen::Matrix3d::Identity();
  for (const bool iso : {false, true}) {
    World w = mapped_block(F, iso);
    RodSystem rods;
    rods.setup(w);
    rods.forces(w);
    const Rods& r = w.rods;
    for (std::size_t k = 0; k < r.size(); ++k) {
      const double strain = s - 1.0;
      if (!iso) {
        ASSERT_NEAR(r.trial_shift[k], strain + kYield, 1e-12) << "rod " << k;
        ASSERT_NEAR(r.stress[k], -kE * kYield, 1e-12 * kE) << "rod " << k;
      } else {
        ASSERT_NEAR(r.trial_shift[k], 0.0, 1e-14) << "rod " << k;
        ASSERT_NEAR(r.stress[k], kE * strain, 1e-12 * kE) << "rod " << k;
      }
    }
  }
}

// A volume-keeping stretch, diag(1 + g, 1, 1/(1 + g)) with g = 1 % (ten yield strains): the rods
// along (1,0,+-1) keep their length to second order, those along (1,+-1,0) stretch and those
// along (0,1,+-1) shorten by about g/2. The plain law's increments then have a mean of second
// order per particle (the finite strain's); the isochoric law keeps the law's increments less
// that mean, and deep inside the block, where every particle's neighbours share its mean, the
// increments it keeps have no mean left (the passes remove a mean shared with the neighbours at
// once; a particle within four layers of a face still sees the faces' different means).
TEST(PlasticVolume, AVolumeKeepingFlowKeepsTheLawsIncrementsLessTheirMean) {
  const double g = 0.01;
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 0) = 1.0 + g;
  F(2, 2) = 1.0 / (1.0 + g);
  World plain = mapped_block(F, false), iso = mapped_block(F, true);
  RodSystem a, b;
  a.setup(plain);
  a.forces(plain);
  b.setup(iso);
  b.forces(iso);
  const auto mp = mean_increments(plain), mi = mean_increments(iso);
  const double a_cell = plain.rods.rest_length[0] * std::sqrt(2.0);
  Vec3 lo = Vec3::Constant(1e9), hi = Vec3::Constant(-1e9);
  for (const Vec3& x : plain.particles.initial_position) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  int deep = 0;
  double largest_plain = 0.0;
  for (std::size_t i = 0; i < mp.size(); ++i) {
    const Vec3& x = plain.particles.initial_position[i];
    const double depth = std::min((x - lo).minCoeff(), (hi - x).minCoeff());
    largest_plain = std::max(largest_plain, std::abs(mp[i]));
    if (depth < 2.4 * a_cell) continue;  // (a pass reaches a/2 deeper: four reach 2 a)
    ++deep;
    EXPECT_LT(std::abs(mi[i]), 1e-3 * std::abs(mp[i]) + 1e-15) << "particle " << i;
  }
  ASSERT_GT(deep, 0);
  EXPECT_GT(largest_plain, 1e-6);  // (the plain mean is there to be removed: second order, g^2/4 scale)
  // Every rod keeps the law's increment less at most the largest mean: the flow is the law's.
  for (std::size_t k = 0; k < plain.rods.size(); ++k) {
    const double dp = plain.rods.trial_shift[k], di = iso.rods.trial_shift[k];
    ASSERT_LE(std::abs(di - dp), 2.0 * largest_plain + 1e-15) << "rod " << k;
  }
}

// The key reaches the rods; the paths that cannot honour it refuse it by name: Newton's tangent
// has no term for the correction, and a domain's ghost has not all its rods.
TEST(PlasticVolume, TheKeyReachesTheRodsAndNewtonAndDomainsRefuseItByName) {
  auto with_key = [](std::string text) {
    text.insert(text.find("[rod]\n") + 6, "isochoric_plasticity = true\n");
    return text;
  };
  test::PulledBar verlet;
  verlet.integrator = "end_time = 1e-6\nscheme = \"verlet\"";
  const Model m = build_model(parse_case(with_key(test::pulled_bar_case(verlet)), "iso.toml", {}));
  EXPECT_TRUE(m.rods.isochoric);
  EXPECT_FALSE(build_model(parse_case(test::pulled_bar_case({}), "plain.toml", {})).rods.isochoric);
  try {
    DomainRun::check_supported(m, m.step);
    FAIL() << "the domains took the isochoric rods";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rod.isochoric_plasticity"), std::string::npos) << e.what();
  }
  test::PulledBar newton;
  newton.integrator = "end_time = 1e-6\nscheme = \"newmark\"\nsolver = \"newton\"";
  try {
    parse_case(with_key(test::pulled_bar_case(newton)), "newton.toml", {});
    FAIL() << "the Newton solver took the isochoric rods";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("newton.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("rod.isochoric_plasticity"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace swarf

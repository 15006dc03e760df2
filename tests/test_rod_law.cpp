// test_rod_law.cpp: the rod law against hand-computed points of a loop with two reversals
// and failure, and the 'swarf rod' driver against the closed-form loop.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "app/rod_driver.h"
#include "swarf/laws/rod_law.h"
#include "test_helpers.h"

namespace swarf {
namespace {

// E = 200 GPa, eps_y = 1e-3 (sigma_02 = 200 MPa), k = 20 GPa, sigma_max = 300 MPa.
// Band: 20e9 eps - 180e6 <= sigma <= 20e9 eps + 180e6 (Pa).
RodLaw steel() {
  RodLaw law;
  law.youngs_modulus = 200e9;
  law.yield_strain = 1e-3;
  law.hardening = 20e9;
  law.tensile_strength = 300e6;
  return law;
}

// Relative tolerance: every value below is a sum of a few products of exact decimals;
// double rounding leaves a few ulps (1e-15 relative). 1e-12 is far above that and far below
// any modelling error.
constexpr double kTol = 1e-12;

void expect_rel(double got, double want, double scale) { EXPECT_NEAR(got, want, kTol * scale) << "want " << want; }

TEST(RodLaw, ElasticBelowYield) {
  const RodLaw law = steel();
  const RodResponse r = evaluate(law, 0.5e-3, 0.0, 0.0);
  expect_rel(r.stress, 100e6, 1e9);
  EXPECT_EQ(r.shift, 0.0);
  EXPECT_FALSE(r.broken);
}

TEST(RodLaw, LoopWithTwoReversalsAndFailure) {
  // Points of the path 0 -> 0.004 -> -0.004 -> 0 -> 0.007, worked by hand (stress in Pa;
  // shift eps0 = (E eps - sigma)/(E - k) whenever the trial leaves the band). For 1-D linear
  // kinematic hardening the return map is exact for any monotone increment, so large
  // increments give the same points as a fine path.
  const RodLaw law = steel();
  struct Point {
    double strain, stress, shift;
    bool broken;
  };
  const Point pts[] = {
      {0.001, 200e6, 0.0, false},       // trial 200e6 = upper band 20e9*0.001 + 180e6: first yield, elastic
      {0.004, 260e6, 0.003, false},     // trial 800e6 > 80e6 + 180e6: hardening; eps0 = 540e6/180e9
      {0.002, -140e6, 0.003, false},    // unloading: 60e6 + 200e9*(-0.001) = -140e6 = lower band (260 - 2*200)
      {0.001, -160e6, 0.002, false},    // trial -340e6 < 20e6 - 180e6: reverse flow; eps0 = 360e6/180e9
      {-0.004, -260e6, -0.003, false},  // trial -1160e6 < -80e6 - 180e6; eps0 = -540e6/180e9
      {0.0, 180e6, -0.001, false},      // second reversal: trial 540e6 > 0 + 180e6; eps0 = -180e6/180e9
      {0.005, 280e6, 0.004, false},     // trial 1180e6 > 100e6 + 180e6; eps0 = 720e6/180e9
      {0.007, 320e6, 0.006, true},      // upper band 140e6 + 180e6 = 320e6 > 300e6: breaks; eps0 = 1080e6/180e9
  };
  double shift = 0.0;
  for (int n = 0; n < 8; ++n) {
    const Point& p = pts[n];
    const RodResponse r = evaluate(law, p.strain, 0.0, shift);
    EXPECT_EQ(r.broken, p.broken) << "point " << n;
    expect_rel(r.stress, p.stress, 1e9);
    expect_rel(r.shift, p.shift, 1e-2);
    shift = r.shift;  // commit
  }
}

TEST(RodLaw, BauschingerReverseYieldIsTwoSigma02BelowTurn) {
  // After tensile yield to sigma_t, reverse yield happens at sigma_t - 2 sigma_02.
  const RodLaw law = steel();
  const RodResponse up = evaluate(law, 0.006, 0.0, 0.0);  // sigma_t = 120e6 + 180e6 = 300e6
  expect_rel(up.stress, 300e6, 1e9);
  // Unload elastically by 2 eps_y exactly: stress sigma_t - 2 E eps_y = -100e6, still elastic.
  const RodResponse back = evaluate(law, 0.006 - 2e-3, 0.0, up.shift);
  expect_rel(back.stress, 300e6 - 400e6, 1e9);
  EXPECT_NEAR(back.shift, up.shift, 1e-15);
  // A little further and the shift moves: plastic flow in compression.
  const RodResponse more = evaluate(law, 0.006 - 2.1e-3, 0.0, up.shift);
  EXPECT_LT(more.shift, up.shift);
}

TEST(RodLaw, NoFailureInCompression) {
  RodLaw law = steel();
  law.tensile_strength = 100e6;
  // Compressive stress beyond the strength in magnitude never breaks the rod.
  const RodResponse r = evaluate(law, -0.01, 0.0, 0.0);
  EXPECT_FALSE(r.broken);
  EXPECT_LT(r.stress, -100e6);
}

TEST(RodLaw, ViscousStressIsRateTimesViscosity) {
  RodLaw law = steel();
  law.viscosity = 1e4;  // Pa s
  const RodResponse r = evaluate(law, 1e-4, 3.0, 0.0);
  expect_rel(r.viscous_stress, 3e4, 1e5);
  expect_rel(r.stress, 20e6, 1e9);  // the elastic-plastic part is unaffected
}

TEST(RodLaw, EvaluateIsPure) {
  // Same inputs, same outputs; nothing is kept between calls.
  const RodLaw law = steel();
  const RodResponse a = evaluate(law, 0.004, 0.0, 0.0);
  const RodResponse b = evaluate(law, 0.004, 0.0, 0.0);
  EXPECT_EQ(a.stress, b.stress);
  EXPECT_EQ(a.shift, b.shift);
}

// Closed form of the quasi-static loop along a path of monotone segments: on each segment
// the stress is elastic from the turning state until it meets the band edge it moves
// towards, then it follows that edge.
double closed_form_stress(const RodLaw& law, double strain, double turn_strain, double turn_stress, int direction) {
  const double E = law.youngs_modulus, k = law.hardening, h = (E - k) * law.yield_strain;
  const double elastic = turn_stress + E * (strain - turn_strain);
  const double edge = k * strain + direction * h;
  return direction > 0 ? std::min(elastic, edge) : std::max(elastic, edge);
}

TEST(RodDriver, ReproducesClosedFormLoopIncludingFailure) {
  const RodLaw law = steel();
  const std::vector<double> path{0.0, 0.004, -0.004, 0.008};
  const auto samples = drive_rod(law, path, 40);
  ASSERT_EQ(samples.size(), 1u + 3 * 40);
  double turn_strain = 0, turn_stress = 0;
  bool broke = false;
  for (std::size_t s = 1; s < path.size(); ++s) {
    const int dir = path[s] > path[s - 1] ? 1 : -1;
    for (int k = 1; k <= 40; ++k) {
      const auto& smp = samples[(s - 1) * 40 + k];
      double want = closed_form_stress(law, smp.strain, turn_strain, turn_stress, dir);
      if (broke || (smp.strain > 0 && want > law.tensile_strength)) {
        broke = true;
        EXPECT_TRUE(smp.broken) << "strain " << smp.strain;
        EXPECT_EQ(smp.stress, 0.0);
        continue;
      }
      EXPECT_FALSE(smp.broken) << "strain " << smp.strain;
      EXPECT_NEAR(smp.stress, want, kTol * 1e9) << "segment " << s << " strain " << smp.strain;
    }
    turn_strain = path[s];
    turn_stress = samples[s * 40].stress;
  }
  EXPECT_TRUE(broke) << "the path must reach the tensile strength: 20e9*0.008 + 180e6 = 340 MPa > 300 MPa";
  // The failure happens where the upper band crosses 300 MPa: eps = (300e6 - 180e6)/20e9 = 0.006.
  std::size_t first = 0;
  while (!samples[first].broken) ++first;
  EXPECT_GT(samples[first].strain, 0.006);
  EXPECT_LE(samples[first - 1].strain, 0.006 + 1e-15);
}

TEST(RodDriver, CliWritesCsv) {
  const auto r = test::run_command(
      std::string(SWARF_BINARY) +
      " rod --E 200e9 --yield-strain 1e-3 --hardening 20e9 --path 0,0.004,-0.004 --steps 4");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream in(r.output);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "strain,stress,shift,broken");
  std::getline(in, line);
  EXPECT_EQ(line, "0,0,0,0");
  int rows = 1;
  std::string last;
  while (std::getline(in, line)) {
    ++rows;
    last = line;
  }
  EXPECT_EQ(rows, 9);
  EXPECT_EQ(last, "-0.004,-260000000,-0.003,0");
}

TEST(RodDriver, CliRejectsBadPath) {
  const auto r = test::run_command(std::string(SWARF_BINARY) + " rod --E 200e9 --path 0,abc");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--path"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("abc"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace swarf

// test_flow_curve.cpp: the rod law with a piecewise-linear hardening curve and failure by
// strain, against closed forms: the linear law it must reproduce, the points of a monotonic
// curve, a reversal with the band's width (the Bauschinger effect), mirrored compression,
// and the return map's exactness for any increment.
#include <gtest/gtest.h>

#include <cmath>

#include "swarf/laws/rod_law.h"

namespace swarf {
namespace {

constexpr double E = 200e9;

// Flow stress s_y = 200 MPa at eps_p = 0, 400 MPa at 0.01, 500 MPa at 0.11, then on with the
// last slope 1 GPa: back stress slopes H = 20 GPa, 1 GPa.
RodLaw curve_law() {
  RodLaw law;
  law.youngs_modulus = E;
  law.yield_strain = 200e6 / E;
  law.hardening = 0.0;
  law.tensile_strength = HUGE_VAL;
  law.flow.points = 3;
  law.flow.plastic_strain = {0.0, 0.01, 0.11};
  law.flow.stress = {200e6, 400e6, 500e6};
  return law;
}

// Every value is a few products and sums of exact decimals: rounding leaves ulps, 1e-12
// relative (of 1 GPa for stresses, of 1 for strains) is far above that.
constexpr double kStressTol = 1e-12 * 1e9, kStrainTol = 1e-12;

TEST(FlowCurve, TwoPointsAreTheLinearLaw) {
  // A two-point curve with back-stress slope H is linear kinematic hardening with
  // k = E H / (E + H); the linear law's shift is eps0 = eps_p E / (E - k). Same stresses on a
  // path with two reversals.
  RodLaw lin;
  lin.youngs_modulus = E;
  lin.yield_strain = 1e-3;
  lin.hardening = 20e9;
  lin.tensile_strength = HUGE_VAL;
  const double k = lin.hardening, H = E * k / (E - k);
  RodLaw tab = lin;
  tab.hardening = 0.0;
  tab.flow.points = 2;
  tab.flow.plastic_strain = {0.0, 0.01};
  tab.flow.stress = {E * 1e-3, E * 1e-3 + H * 0.01};
  double s_lin = 0.0, s_tab = 0.0;
  for (double eps : {0.001, 0.004, 0.002, 0.001, -0.004, 0.0, 0.005, 0.02, -0.03}) {
    const RodResponse a = evaluate(lin, eps, 0.0, s_lin), b = evaluate(tab, eps, 0.0, s_tab);
    EXPECT_NEAR(a.stress, b.stress, kStressTol) << "strain " << eps;
    EXPECT_NEAR(a.shift * (E - k) / E, b.shift, kStrainTol) << "strain " << eps;
    s_lin = a.shift;
    s_tab = b.shift;
  }
  EXPECT_DOUBLE_EQ(plastic_tangent(tab, 0.003), k);
}

TEST(FlowCurve, MonotonicTensionPassesThroughThePoints) {
  // On the curve, eps = eps_p + f(eps_p)/E: one increment from 0 to each point's strain lands on
  // it (the return map is exact for any increment: it walks the pieces).
  const RodLaw law = curve_law();
  const double pts[][2] = {{0.0, 200e6}, {0.005, 300e6}, {0.01, 400e6}, {0.06, 450e6}, {0.11, 500e6}, {0.31, 700e6}};
  for (const auto& p : pts) {
    const double eps = p[0] + p[1] / E;
    const RodResponse r = evaluate(law, eps, 0.0, 0.0);
    EXPECT_NEAR(r.stress, p[1], kStressTol) << "eps_p " << p[0];
    EXPECT_NEAR(r.shift, p[0], kStrainTol) << "eps_p " << p[0];
  }
  // The same end point reached in 1,000 increments: the path does not matter while monotone.
  double s = 0.0;
  RodResponse r;
  for (int i = 1; i <= 1000; ++i) {
    r = evaluate(law, (0.31 + 700e6 / E) * i / 1000.0, 0.0, s);
    s = r.shift;
  }
  EXPECT_NEAR(r.stress, 700e6, 1e-9 * 1e9);
  EXPECT_NEAR(s, 0.31, 1e-9);
}

TEST(FlowCurve, ReversalYieldsAtBackStressMinusYield) {
  // Loaded to eps_p = 0.06 (flow 450 MPa, back stress 250 MPa), reversed: elastic down to
  // alpha - s_y = 50 MPa, then reverse flow; the band keeps its width 2 s_y = 400 MPa.
  const RodLaw law = curve_law();
  const double eps_top = 0.06 + 450e6 / E;
  const RodResponse top = evaluate(law, eps_top, 0.0, 0.0);
  ASSERT_NEAR(top.shift, 0.06, kStrainTol);
  const RodResponse back = evaluate(law, 0.06 + 50e6 / E, 0.0, top.shift);
  EXPECT_NEAR(back.stress, 50e6, kStressTol);
  EXPECT_NEAR(back.shift, 0.06, kStrainTol);  // still elastic at the band's lower edge
  // Further back to eps_p = 0.005: back stress falls to 100 MPa, stress 100 - 200 = -100 MPa.
  const RodResponse rev = evaluate(law, 0.005 - 100e6 / E, 0.0, top.shift);
  EXPECT_NEAR(rev.stress, -100e6, kStressTol);
  EXPECT_NEAR(rev.shift, 0.005, kStrainTol);
  // And through zero into compression: at eps_p = -0.06 the stress is -450 MPa.
  const RodResponse comp = evaluate(law, -0.06 - 450e6 / E, 0.0, rev.shift);
  EXPECT_NEAR(comp.stress, -450e6, kStressTol);
  EXPECT_NEAR(comp.shift, -0.06, kStrainTol);
}

TEST(FlowCurve, CompressionMirrorsTension) {
  const RodLaw law = curve_law();
  for (double eps : {0.0005, 0.003, 0.05, 0.4}) {
    const RodResponse t = evaluate(law, eps, 0.0, 0.0), c = evaluate(law, -eps, 0.0, 0.0);
    EXPECT_EQ(t.stress, -c.stress);
    EXPECT_EQ(t.shift, -c.shift);
  }
}

TEST(FlowCurve, OnePointIsPerfectlyPlastic) {
  RodLaw law = curve_law();
  law.flow.points = 1;
  EXPECT_NEAR(evaluate(law, 0.5, 0.0, 0.0).stress, 200e6, kStressTol);
  EXPECT_EQ(plastic_tangent(law, 0.3), 0.0);
}

TEST(FlowCurve, TangentIsThePiecesSlope) {
  const RodLaw law = curve_law();
  EXPECT_DOUBLE_EQ(plastic_tangent(law, 0.005), E * 20e9 / (E + 20e9));
  EXPECT_DOUBLE_EQ(plastic_tangent(law, 0.5), E * 1e9 / (E + 1e9));
}

TEST(RodFailure, ByStrainInTensionOnly) {
  RodLaw law = curve_law();
  law.failure_strain = 0.2;
  EXPECT_FALSE(evaluate(law, 0.2, 0.0, 0.0).broken);
  EXPECT_TRUE(evaluate(law, 0.2000001, 0.0, 0.0).broken);
  EXPECT_FALSE(evaluate(law, -0.5, 0.0, 0.0).broken);  // compression never breaks a rod
  // The linear law too.
  RodLaw lin;
  lin.youngs_modulus = E;
  lin.yield_strain = 1e-3;
  lin.hardening = 1e9;
  lin.tensile_strength = HUGE_VAL;
  lin.failure_strain = 0.1;
  EXPECT_FALSE(evaluate(lin, 0.099, 0.0, 0.0).broken);
  EXPECT_TRUE(evaluate(lin, 0.101, 0.0, 0.0).broken);
}

}  // namespace
}  // namespace swarf

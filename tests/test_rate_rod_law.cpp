// test_rate_rod_law.cpp: the Johnson-Cook rate-hardening rod law (laws/johnson_cook_rod_law.h)
// against closed forms: the paper's law below the reference rate (bit for bit), the yield stress
// R sigma_y at a constant rate, hand-computed monotonic and cyclic (Bauschinger) paths, the plastic
// strain of both laws, the rod kernel against evaluate() per rod, and a rod pulled at a constant
// rate through a case file and the Simulation.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "case_errors.h"
#include "lattice_gen/lattice_file.h"
#include "rod_law_fixtures.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/parallel.h"
#include "swarf/forces/rod_forces.h"
#include "swarf/laws/any_rod_law.h"
#include "swarf/simulation.h"
#include "test_helpers.h"

namespace swarf {
namespace {

using test::curve_law, test::kE, test::kEpsY, test::kK, test::linear_law;
constexpr double kC = 0.1, kRef = 1.0;  // 1, 1/s
// A rate whose factor is 1.2: ln(rate / rate_ref) = 2.
const double kRate12 = kRef * std::exp(2.0);

JohnsonCookRodLaw rate_law(const RodLaw& base) { return {base, kC, kRef}; }

// Exact equality of two responses, field by field.
void expect_same(const RodResponse& a, const RodResponse& b, const std::string& where) {
  EXPECT_EQ(a.stress, b.stress) << where;
  EXPECT_EQ(a.shift, b.shift) << where;
  EXPECT_EQ(a.viscous_stress, b.viscous_stress) << where;
  EXPECT_EQ(a.broken, b.broken) << where;
}

// Below (and at) the reference rate the factor is 1 and the law returns the paper's law's
// evaluation itself: compared with ==, along a cyclic path that flows in both directions, for
// the single slope and the hardening curve, with viscosity and failure on.
TEST(RodLawJohnsonCookRate, BelowTheReferenceRateItIsThePapersLawBitForBit) {
  for (RodLaw base : {linear_law(), curve_law()}) {
    base.viscosity = 1e3;
    base.tensile_strength = 330e6;
    const JohnsonCookRodLaw law = rate_law(base);
    for (double rate : {0.0, 0.3 * kRef, -0.9 * kRef, kRef, -kRef}) {
      double s_base = 0.0, s_rate = 0.0;
      for (double eps : {0.002, 0.004, 0.0, -0.005, -0.001, 0.003, 0.02}) {
        const RodResponse a = evaluate(base, eps, rate, s_base), b = evaluate(law, eps, rate, s_rate);
        expect_same(a, b, fmt::format("rate {} eps {}", rate, eps));
        s_base = a.shift;
        s_rate = b.shift;
      }
    }
  }
}

// At a constant rate the rod yields at R sigma_y, R = 1 + C ln(rate / rate_ref): just below that
// strain it is elastic (shift kept), just above it flows (shift moved) with the stress R sigma_y
// to rounding (1e-12 relative: the strains are 1e-12 from the yield point).
TEST(RodLawJohnsonCookRate, AtAConstantRateItYieldsAtTheRateFactorTimesSigmaY) {
  for (const RodLaw& base : {linear_law(), curve_law()})
    for (double rate : {10.0, 1e3, 1e5, -1e4}) {
      const JohnsonCookRodLaw law = rate_law(base);
      const double R = 1.0 + kC * std::log(std::abs(rate) / kRef);
      EXPECT_NEAR(rate_factor(law, rate), R, 1e-15 * R);
      const double sign = rate > 0 ? 1.0 : -1.0, eps_yield = sign * R * kEpsY;
      const RodResponse below = evaluate(law, eps_yield * (1 - 1e-12), rate, 0.0);
      EXPECT_EQ(below.shift, 0.0) << rate;
      const RodResponse above = evaluate(law, eps_yield * (1 + 1e-12), rate, 0.0);
      EXPECT_NE(above.shift, 0.0) << rate;
      EXPECT_NEAR(above.stress, sign * R * kE * kEpsY, 1e-11 * R * kE * kEpsY) << rate;
    }
}

// The single slope at R = 1.2, by hand (s_y = 200 MPa, k = 20 GPa, E = 200 GPa): the plastic
// branch sigma = R (k q +- s_y) with q = (E eps -+ R s_y) / (E - k + R k), tangent
// E R k / (E - k + R k) = 23.53 GPa.
//   tension to 0.004:     q = 560e6 / 204e9,  sigma = 1.2 (20e9 q + 200e6) = 305.882 MPa
//   reverse yield:        305.882 - 2 R s_y = -174.118 MPa at eps = 0.004 - 480e6/E = 0.0016
//   compression to -0.004: sigma = -305.882 MPa; reloading yields at +174.118 MPa, eps = -0.0016
// Driven in increments of 1e-5 with the rate's sign following the direction. Tolerance 1e-12
// relative: the plastic branch does not depend on the path, so only rounding separates the values.
TEST(RodLawJohnsonCookRate, MonotonicAndCyclicPathsOfTheSingleSlopeAtAConstantRate) {
  const JohnsonCookRodLaw law = rate_law(linear_law());
  const double top = 1.2 * (20e9 * (560e6 / 204e9) + 200e6), reverse = top - 2 * 1.2 * 200e6;
  EXPECT_NEAR(top, 305.88235294117646e6, 1e-6);
  double shift = 0.0, eps = 0.0;
  auto drive = [&](double to) {
    const double rate = to > eps ? kRate12 : -kRate12;
    const int n = static_cast<int>(std::lround(std::abs(to - eps) / 1e-5));
    const double from = eps;
    RodResponse r;
    for (int i = 1; i <= n; ++i) {
      eps = i == n ? to : from + (to - from) * i / n;
      r = evaluate(law, eps, rate, shift);
      shift = r.shift;
    }
    return r;
  };
  EXPECT_NEAR(drive(0.004).stress, top, 1e-12 * top);
  // Reverse yield: elastic just above eps = 0.0016, flowing just below, at -174.118 MPa.
  const double s_top = shift;
  EXPECT_EQ(evaluate(law, 0.0016 + 1e-9, -kRate12, s_top).shift, s_top);
  const RodResponse rev = evaluate(law, 0.0016 - 1e-9, -kRate12, s_top);
  EXPECT_NE(rev.shift, s_top);
  EXPECT_NEAR(rev.stress, reverse, 1e-3 * std::abs(reverse));  // (1e-9 of strain past the point: 0.02 MPa)
  EXPECT_NEAR(drive(-0.004).stress, -top, 1e-12 * top);
  const double s_bottom = shift;
  EXPECT_EQ(evaluate(law, -0.0016 - 1e-9, kRate12, s_bottom).shift, s_bottom);
  EXPECT_NEAR(evaluate(law, -0.0016 + 1e-9, kRate12, s_bottom).stress, -reverse, 1e-3 * std::abs(reverse));
  EXPECT_NEAR(drive(0.004).stress, top, 1e-12 * top);
  // The quasi-static law on the same path reaches 200 + 18 (0.004 - 0.001) GPa... = 254 MPa: the rate shows.
  EXPECT_NEAR(evaluate(linear_law(), 0.004, 0.0, 0.0).stress, 200e6 + 20e9 * 0.003, 1e-6);
}

// The hardening curve at R = 1.2, by hand: at plastic strain 0.005 the flow stress is
// R (200 + 200 x 0.5) MPa = 360 MPa, reached at eps = 0.005 + 360e6/E = 0.0068; the back stress
// R x 100 MPa, so the reverse yield is at 120 - 240 = -120 MPa, eps = 0.005 - 120e6/E = 0.0044.
TEST(RodLawJohnsonCookRate, MonotonicAndCyclicPathsOfTheHardeningCurveAtAConstantRate) {
  const JohnsonCookRodLaw law = rate_law(curve_law());
  const RodResponse up = evaluate(law, 0.0068, kRate12, 0.0);
  EXPECT_NEAR(up.shift, 0.005, 1e-14);
  EXPECT_NEAR(up.stress, 360e6, 1e-12 * 360e6);
  EXPECT_EQ(evaluate(law, 0.0044 + 1e-9, -kRate12, up.shift).shift, up.shift);
  const RodResponse rev = evaluate(law, 0.0044 - 1e-9, -kRate12, up.shift);
  EXPECT_LT(rev.shift, up.shift);
  EXPECT_NEAR(rev.stress, -120e6, 1e-3 * 120e6);
  // Past the curve's first kink (eps_p 0.01, R 400 MPa = 480 MPa): eps_p 0.03 -> R (400 + 20) MPa.
  const RodResponse far = evaluate(law, 0.03 + 504e6 / kE, kRate12, up.shift);
  EXPECT_NEAR(far.shift, 0.03, 1e-13);
  EXPECT_NEAR(far.stress, 504e6, 1e-12 * 504e6);
}

// plastic_strain() of either law is eps - sigma / E of the state the law left (docs/physics.md
// section 2), and for the single slope (E - k)/E eps0: at eps = 0.004 the paper's law has
// eps0 = 0.003 and eps_p = 0.0027; the rate law at R = 1.2 has eps_p = 0.004 - 305.88e6 / E.
// Tolerance 1e-15 absolute: strains of 1e-3 and a few roundings.
TEST(RodLawJohnsonCookRate, PlasticStrainOfEachLawIsTheClosedForm) {
  const RodLaw paper = linear_law();
  const RodResponse a = evaluate(paper, 0.004, 0.0, 0.0);
  EXPECT_NEAR(plastic_strain(paper, a.shift), 0.0027, 1e-15);
  const JohnsonCookRodLaw fast = rate_law(paper);
  const RodResponse b = evaluate(fast, 0.004, kRate12, 0.0);
  EXPECT_NEAR(plastic_strain(fast, b.shift), 0.004 - 1.2 * (20e9 * (560e6 / 204e9) + 200e6) / kE, 1e-15);
  for (const AnyRodLaw& law : {AnyRodLaw(curve_law()), AnyRodLaw(rate_law(curve_law()))})
    for (double eps : {0.0068, -0.02, 0.3}) {
      const RodResponse r = evaluate(law, eps, kRate12, 0.0);
      EXPECT_NEAR(plastic_strain(law, r.shift), eps - r.stress / kE, 1e-15 + 1e-15 * std::abs(eps));
    }
}

// tangent() is the derivative of evaluate() on the trial's branch: d sigma / d eps (E on the
// elastic branch, the scaled plastic tangent on the plastic one) and d (sigma + sigma_v) / d rate
// (the viscosity, plus the rate factor's part while flowing above rate_ref), against central
// differences. Tolerances: the stress is linear in the strain on a branch, so that difference is
// exact but for rounding (1e-6 relative); in the rate it is a logarithm, a relative step of 1e-4
// leaves a truncation of about 1e-8 (1e-5 relative).
TEST(RodLawJohnsonCookRate, TheTangentIsTheDerivativeOfEvaluate) {
  for (RodLaw base : {linear_law(), curve_law()}) {
    base.viscosity = 20.0;
    const JohnsonCookRodLaw law = rate_law(base);
    for (double rate : {50.0, -3e3, 0.5})
      for (double eps : {0.0068, -0.02, 0.0005}) {
        const double s0 = rate > 0 ? 0.0 : 0.001;  // (committed shift: a little history)
        const RodResponse r = evaluate(law, eps, rate, s0);
        const RodTangent t = tangent(law, eps, rate, s0, r.shift);
        auto total = [&](double e, double q) {
          const RodResponse x = evaluate(law, e, q, s0);
          return x.stress + x.viscous_stress;
        };
        // (Below rate_ref the stress does not depend on the rate: a wide step, inside (0, rate_ref),
        // keeps the stress's rounding, about 1e-7 Pa over 2 hq, below the tolerance.)
        const double he = 1e-9, hq = (std::abs(rate) > kRef ? 1e-4 : 0.2) * std::abs(rate);
        const double d_eps = (total(eps + he, rate) - total(eps - he, rate)) / (2 * he);
        const double d_rate = (total(eps, rate + hq) - total(eps, rate - hq)) / (2 * hq);
        const std::string where = fmt::format("rate {} eps {}", rate, eps);
        EXPECT_NEAR(t.stiffness, d_eps, 1e-6 * kE) << where;
        EXPECT_NEAR(t.damping, d_rate, 1e-5 * std::max(std::abs(d_rate), base.viscosity)) << where;
        if (r.shift != s0 && std::abs(rate) > kRef && r.stress * rate > 0) {
          EXPECT_GT(t.damping, 1.5 * base.viscosity) << where;  // (the rate factor adds to eta)
        }
      }
  }
}

// The rod kernel with the rate law gives, rod by rod, what evaluate() gives for the rod's strain
// and strain rate computed as the kernel computes them; the variant is visited once per call.
// Tolerance 1e-12 of the stress scale: the build may contract the kernel's and this test's
// arithmetic into fused multiply-adds differently, a few roundings of the strain.
// With and without a dashpot: the kernel must gather the velocities for the rate law even when
// the paper's law would not (no viscosity).
void expect_kernel_agrees(double viscosity) {
  RodLaw base = curve_law();
  base.viscosity = viscosity;
  base.tensile_strength = 450e6;
  const JohnsonCookRodLaw law = rate_law(base);
  const double L0 = 1e-3, A = 1e-6;
  // Rod k joins particle 0 at the origin to particle k+1: stretched or compressed along a
  // direction, the far end moving at a speed that gives rates below and above rate_ref.
  const std::vector<double> strain = {0.0005, 0.0015, 0.0068, -0.004, 0.03, -0.0002, 0.0024};
  const std::vector<double> speed = {1e-4, 0.5, -2.0, 5.0, 0.02, -3e-4, 50.0};  // m/s along the rod
  const std::vector<double> committed = {0.0, 0.0, 0.002, -0.001, 0.0, 0.0, 0.0};
  const std::size_t m = strain.size();
  std::vector<Vec3> x(m + 1, Vec3::Zero()), v(m + 1, Vec3::Zero());
  std::vector<std::array<std::int32_t, 2>> ends(m);
  std::vector<double> l0(m, L0), trial(m), stress(m), coef(m);
  std::vector<std::uint8_t> intact(m, 1), broken(m);
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3 n = Vec3(1.0, 0.3 * k, -0.2 * k).normalized();
    x[k + 1] = L0 * (1 + strain[k]) * n;
    v[k + 1] = speed[k] * n;
    ends[k] = {0, static_cast<std::int32_t>(k + 1)};
  }
  std::vector<double> block_visc(block_count(m));
  std::vector<int> block_changed(block_count(m));
  RodKernelView view;
  view.rods = m;
  view.ends = ends.data();
  view.rest_length = l0.data();
  view.shift = committed.data();
  view.intact = intact.data();
  view.x = x.data();
  view.v = v.data();
  view.trial_shift = trial.data();
  view.trial_broken = broken.data();
  view.stress = stress.data();
  view.coef = coef.data();
  view.block_viscous = block_visc.data();
  view.block_changed = block_changed.data();
  evaluate_rods(AnyRodLaw(law), A, view, Periodic{});
  int plastic = 0, fast = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3 dx = x[ends[k][1]] - x[ends[k][0]];
    const double len = dx.norm(), inv_len = 1.0 / len;
    const double eps = (len - L0) / L0, rate = dx.dot(v[ends[k][1]] - v[ends[k][0]]) * inv_len / L0;
    const RodResponse r = evaluate(law, eps, rate, committed[k]);
    const double scale = 1e-12 * 500e6;
    EXPECT_NEAR(stress[k], r.stress, scale) << k << " viscosity " << viscosity;
    EXPECT_NEAR(trial[k], r.shift, 1e-12 * std::max(std::abs(r.shift), 1e-3)) << k << " viscosity " << viscosity;
    EXPECT_EQ(broken[k], r.broken) << k << " viscosity " << viscosity;
    if (!r.broken) {
      EXPECT_NEAR(coef[k], (r.stress + r.viscous_stress) * A * inv_len, scale * A * inv_len)
          << k << " viscosity " << viscosity;
    }
    plastic += r.shift != committed[k];
    fast += rate_factor(law, rate) > 1.0;
  }
  EXPECT_GE(plastic, 3);  // (the rods cover both branches and both sides of rate_ref)
  EXPECT_GE(fast, 3);
  EXPECT_LT(fast, static_cast<int>(m));
}

TEST(RodLawJohnsonCookRate, TheKernelAgreesWithEvaluatePerRod) {
  expect_kernel_agrees(0.0);
  expect_kernel_agrees(50.0);
}

// One rod pulled at a constant speed through a case file (rod.law = "johnson_cook_rate", the
// former name of "johnson_cook") and the Simulation: both particles held by grips, one fixed and one moving, so the
// strain is v t / L0 and the rate v / L0 at every step. Perfectly plastic (k = 0), so the stress at yield is the
// plateau: R sigma_y with the rate law, sigma_y with the paper's law run alike; every step follows the closed form
// min(E eps, R sigma_y). Tolerance 1e-9 relative: the positions advance by v dt per step, so the strain carries the
// rounding of a few hundred additions (about 1e-13 relative).
TEST(RodLawJohnsonCookRate, ARodPulledAtAConstantRateYieldsAtTheRateFactorTimesSigmaY) {
  test::TempDir dir("rate_rod");
  const test::PulledRod rod(dir.str());
  const double sy = kE * kEpsY;  // (rate 50/s: R = 1 + 0.1 ln 50 = 1.391)
  auto plateau = [&](const std::string& law_keys, double R) {
    const test::PulledRod::Result r = rod.run(rod.case_text(law_keys), R);
    EXPECT_EQ(r.law, R == 1.0 ? "bilinear" : "johnson_cook");
    EXPECT_LT(r.deviation, 1e-9) << law_keys;
    EXPECT_GT(r.steps, 100) << law_keys;  // (the path is resolved: yield is not one step's jump)
    EXPECT_GT(r.flowing, r.steps / 3) << law_keys;
    return r.stress;
  };
  EXPECT_NEAR(plateau("", 1.0), sy, 1e-9 * sy);
  const double R = 1.0 + kC * std::log(rod.rate() / kRef);
  // (kC and kRef as TOML floats.)
  const double fast = plateau("law = \"johnson_cook_rate\"\nrate_sensitivity = 0.1\nreference_rate = 1.0\n", R);
  EXPECT_NEAR(fast, R * sy, 1e-9 * R * sy);
  // The rate keys belong to the rate law: without rod.law they are an error that names them.
  test::expect_mentions(test::case_error(rod.case_text("rate_sensitivity = 0.1\n")),
                        {"rate_sensitivity", "johnson_cook"});
}

}  // namespace
}  // namespace swarf

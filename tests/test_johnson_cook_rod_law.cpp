// test_johnson_cook_rod_law.cpp: the Johnson-Cook rod law with rate hardening and thermal softening
// (laws/johnson_cook_rod_law.h) against closed forms: one rod driven through the kernel along a
// strain path at several fixed temperatures and rates, S flow(eps_p) with S = R Theta; the
// Bauschinger shift kept on reversal; a trial that is not committed (a rejected try) leaves the
// committed state as it was; a particle without a temperature (0) is at T_ref; a rod at and
// above T_melt keeps the 1e-3 floor; the tangent with a temperature; the case keys and the
// [material] route (the preset's factors, the rate conversion 2/sqrt3 or 3).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "case_errors.h"
#include "lattice_gen/lattice_file.h"
#include "rod_law_fixtures.h"
#include "setup/case_config.h"
#include "setup/material_presets.h"
#include "setup/model.h"
#include "swarf/core/parallel.h"
#include "swarf/forces/rod_forces.h"
#include "swarf/laws/any_rod_law.h"
#include "swarf/simulation.h"
#include "swarf/systems/rod_system.h"
#include "test_helpers.h"

namespace swarf {
namespace {

using test::curve_law, test::kE, test::kEpsY, test::kK, test::linear_law;
constexpr double kL0 = 1e-3, kA = 1e-8;            // m, m^2
constexpr double kTref = 293.15, kTmelt = 1733.0;  // K (C45's)

JohnsonCookRodLaw jc_law(const RodLaw& base, double m = 1.0) {
  JohnsonCookRodLaw law;
  law.base = base;
  law.rate_sensitivity = 0.05;
  law.reference_rate = 1.0;
  law.rate_to_equivalent = 2.0 / std::sqrt(3.0);
  law.softening_exponent = m;
  law.melt_temperature = kTmelt;
  law.reference_temperature = kTref;
  return law;
}

// The closed form of the scale, written out apart from the law's functions.
double closed_scale(double rate, double T, double m) {
  const double x = 2.0 / std::sqrt(3.0) * std::abs(rate) / 1.0;
  const double R = x > 1.0 ? 1.0 + 0.05 * std::log(x) : 1.0;
  double ts = (T - kTref) / (kTmelt - kTref);
  ts = ts < 0 ? 0 : (ts > 1 ? 1 : ts);
  return R * std::max(1.0 - std::pow(ts, m), 1e-3);
}

// The reference flow curve s_y + alpha(p) of curve_law (p >= 0), written out apart from FlowCurve.
double flow(double p) {
  if (p <= 0.01) return 200e6 + 2e10 * p;
  return 400e6 + 1e9 * (p - 0.01);
}

// Monotonic tension from the virgin state at scale S: the plastic strain p solving
// E (eps - p) = S flow(p) (its left side falls and its right side rises in p: bisection), and the
// stress. The single slope: q = (E eps - S s_y) / (E - k + S k) in the shift, sigma = E eps - (E - k) q.
double closed_stress(bool curve, double eps, double S) {
  if (!curve) {
    if (kE * eps <= S * kE * kEpsY) return kE * eps;
    const double q = (kE * eps - S * kE * kEpsY) / (kE - kK + S * kK);
    return kE * eps - (kE - kK) * q;
  }
  if (kE * eps <= S * flow(0.0)) return kE * eps;
  double lo = 0.0, hi = eps;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (kE * (eps - mid) > S * flow(mid) ? lo : hi) = mid;
  }
  return kE * (eps - 0.5 * (lo + hi));
}

// One rod (particles 0 and 1) through the kernel, its ends at the temperatures t0 and t1 (or no
// temperature field), the far end moving along the rod at rate x L0.
struct OneRod {
  std::vector<Vec3> x{Vec3::Zero(), Vec3(kL0, 0, 0)}, v{Vec3::Zero(), Vec3::Zero()};
  std::vector<double> temperature{0.0, 0.0};
  std::array<std::int32_t, 2> ends{0, 1};
  double l0 = kL0, shift = 0.0, trial = 0.0, stress = 0.0, coef = 0.0;
  std::uint8_t intact = 1, broken = 0;
  double visc = 0.0;
  int changed = 0;

  RodResponse evaluate_at(const AnyRodLaw& law, double eps, double rate, bool with_temperature = true) {
    x[1] = Vec3(kL0 * (1 + eps), 0, 0);
    v[1] = Vec3(rate * kL0, 0, 0);
    RodKernelView view;
    view.rods = 1;
    view.ends = &ends;
    view.rest_length = &l0;
    view.shift = &shift;
    view.intact = &intact;
    view.x = x.data();
    view.v = v.data();
    view.temperature = with_temperature ? temperature.data() : nullptr;
    view.trial_shift = &trial;
    view.trial_broken = &broken;
    view.stress = &stress;
    view.coef = &coef;
    view.block_viscous = &visc;
    view.block_changed = &changed;
    evaluate_rods(law, kA, view, Periodic{});
    return {stress, 0.0, trial, broken != 0};
  }
  // What the commit does for a converged step: the trial becomes the state.
  void commit() { shift = trial; }
};

// A rod pulled from the virgin state to a strain of 0.05 in increments of 1e-4, each committed,
// at a fixed temperature (its two ends 100 K apart around T: the rod reads their mean) and a
// fixed rate, follows S flow(eps_p) at every increment: the closed form above, which shares no
// code with the law. Temperatures from below T_ref to T_melt, rates below and far above rate_ref,
// m = 1 and 0.8, both the hardening curve and the single slope. Tolerance 1e-9 of the stress:
// on a monotonic path the plastic branch depends on the strain alone, so only rounding
// separates the two (the strain from the positions: a few 1e-16 relative; the bisection: 1e-16).
TEST(JohnsonCookRodLaw, FollowsTheScaledFlowCurveAtSeveralTemperaturesAndRates) {
  int checked = 0;
  for (bool curve : {true, false})
    for (double m : {1.0, 0.8})
      for (double T : {250.0, kTref, 600.0, 1000.0, 1500.0})
        for (double rate : {0.5, 1e3, 1e5}) {
          const AnyRodLaw law = jc_law(curve ? curve_law() : linear_law(), m);
          const double S = closed_scale(rate, T, m);
          OneRod rod;
          rod.temperature = {T - 50.0, T + 50.0};
          if (T < kTref) rod.temperature = {T, T};  // (both below T_ref: Theta = 1, no hardening by cold)
          double worst = 0.0;
          for (int i = 1; i <= 500; ++i) {
            const double eps = 1e-4 * i;
            const RodResponse r = rod.evaluate_at(law, eps, rate);
            rod.commit();
            worst = std::max(worst, std::abs(r.stress - closed_stress(curve, eps, S)));
          }
          EXPECT_LT(worst, 1e-9 * S * 500e6) << "curve " << curve << " m " << m << " T " << T << " rate " << rate;
          EXPECT_GT(rod.shift, 0.01) << "the path flowed";
          ++checked;
        }
  EXPECT_EQ(checked, 60);
  // The scale itself against numbers by hand: C45-like at 1000 K, 1e3/s: T* = 706.85/1439.85,
  // R = 1 + 0.05 ln(1154.7) = 1.35254.
  EXPECT_NEAR(closed_scale(1e3, 1000.0, 1.0), (1 + 0.05 * std::log(1e3 * 2 / std::sqrt(3.0))) * (1 - 706.85 / 1439.85),
              1e-12);
  EXPECT_NEAR(rate_factor(jc_law(curve_law()), 1e3) * thermal_factor(jc_law(curve_law()), 1000.0),
              closed_scale(1e3, 1000.0, 1.0), 1e-15);
}

// On reversal the band keeps its width 2 S s_y around the scaled back stress S alpha(p): loaded
// in tension at scale S to plastic strain p, the rod unloads elastically and yields in
// compression at S (alpha(p) - s_y) = S (flow(p) - 2 s_y), not at -S s_y (an isotropic law) or at
// the reference curve's value. Checked at two temperatures with the hardening curve and the
// single slope (alpha = H eps_p, H = E k/(E - k)): elastic 1e-9 of strain before the point,
// flowing 1e-9 after, the stress there within 1e-3 of the closed form (1e-9 of strain past the
// point moves it by about E x 1e-9 = 200 Pa).
TEST(JohnsonCookRodLaw, KeepsTheBauschingerShiftOnReversal) {
  for (bool curve : {true, false})
    for (double T : {kTref, 1200.0}) {
      const JohnsonCookRodLaw jc = jc_law(curve ? curve_law() : linear_law());
      const AnyRodLaw law = jc;
      const double rate = 1e3, S = closed_scale(rate, T, 1.0);
      OneRod rod;
      rod.temperature = {T, T};
      for (int i = 1; i <= 200; ++i) {
        rod.evaluate_at(law, 1e-4 * i, rate);
        rod.commit();
      }
      const double p = plastic_strain(jc, rod.shift);
      ASSERT_GT(p, 0.01);
      const double top = rod.stress;
      const double back = curve ? flow(p) - 200e6 : kE * kK / (kE - kK) * p;  // alpha(p) at the reference
      const double reverse = S * (back - 200e6);
      EXPECT_NEAR(top, S * (back + 200e6), 1e-9 * top);  // (the top of the band)
      const double eps_rev = 0.02 - (top - reverse) / kE;
      const RodResponse before = rod.evaluate_at(law, eps_rev + 1e-9, -rate);
      EXPECT_EQ(before.shift, rod.shift) << "elastic before the reverse yield, T " << T;
      const RodResponse after = rod.evaluate_at(law, eps_rev - 1e-9, -rate);
      EXPECT_LT(after.shift, rod.shift) << "flowing after it, T " << T;
      EXPECT_NEAR(after.stress, reverse, 1e-3 * std::abs(reverse)) << "curve " << curve << " T " << T;
      EXPECT_GT(reverse, -S * 200e6 + 0.5 * S * back) << "the back stress moved the reverse yield";
    }
}

// A world of one rod for the RodSystem: the stages the step calls, forces and commit.
World one_rod_world(const AnyRodLaw& law) {
  World w;
  Particles& p = w.particles;
  p.resize(2);
  for (std::size_t i = 0; i < 2; ++i) {
    p.position[i] = p.initial_position[i] = Vec3(i * kL0, 0, 0);
    p.radius[i] = 0.5 * kL0;
    p.mass[i] = 1e-6;
    p.inv_mass[i] = 1e6;
    p.id[i] = static_cast<std::int64_t>(i);
  }
  p.next_id = 2;
  Rods& r = w.rods;
  r.law = law;
  r.area = kA;
  r.ends = {{0, 1}};
  r.rest_length = {kL0};
  r.reset_state();
  r.build_rows(2);
  return w;
}

// Plasticity is committed only after a converged step: the rods' forces stage (what every try of
// a step runs) at a strain where the hot rod flows gives a trial shift and leaves the committed
// shift and intact flag as they were; a later try from the same committed state (the rejected
// step retried, here elastic) sees none of the first try; the commit then writes only the
// accepted try's state and books no plastic work. A flowing try that is committed moves the
// shift to exactly its trial. (Exact comparisons: nothing but the commit writes the state.)
TEST(JohnsonCookRodLaw, ARejectedTrialLeavesTheCommittedStateUntouched) {
  World w = one_rod_world(jc_law(curve_law()));
  w.particles.temperature = {1200.0, 1200.0};
  RodSystem rods;
  rods.setup(w);
  EnergyLedger ledger;
  w.particles.position[1] = Vec3(kL0 * 1.01, 0, 0);  // the first try: strain 0.01, far past yield at 1200 K
  rods.forces(w);
  EXPECT_GT(w.rods.trial_shift[0], 0.0);
  EXPECT_EQ(w.rods.shift[0], 0.0);
  EXPECT_EQ(w.rods.intact[0], 1);
  // Rejected: the step is retried from the committed state with a smaller strain (elastic).
  const double S = closed_scale(0.0, 1200.0, 1.0), eps_el = 0.5 * S * kEpsY;
  w.particles.position[1] = Vec3(kL0 * (1 + eps_el), 0, 0);
  rods.forces(w);
  EXPECT_EQ(w.rods.trial_shift[0], 0.0);
  EXPECT_NEAR(w.rods.stress[0], kE * eps_el, 1e-6 * kE * eps_el);
  rods.commit(w, ledger);
  EXPECT_EQ(w.rods.shift[0], 0.0);
  EXPECT_EQ(ledger.plastic_work, 0.0);
  // Accepted and flowing: the commit writes the trial.
  w.particles.position[1] = Vec3(kL0 * 1.01, 0, 0);
  rods.forces(w);
  const double trial = w.rods.trial_shift[0];
  rods.commit(w, ledger);
  EXPECT_EQ(w.rods.shift[0], trial);
  EXPECT_GT(ledger.plastic_work, 0.0);
  // The committed state then answers as the closed form at that temperature.
  EXPECT_NEAR(w.rods.stress[0], closed_stress(true, 0.01, S), 1e-9 * 500e6);
}

// A particle without a temperature (0: no [heat], or not set yet) is read as T_ref: the kernel
// with ends at 0 K, at T_ref, one of each, below T_ref, and without a temperature field gives the
// same bits as the reference law (Theta = 1: the evaluation is the base law's); with one end hot,
// the unset end counts as T_ref in the mean.
TEST(JohnsonCookRodLaw, TemperatureZeroIsTheReferenceTemperature) {
  for (bool curve : {true, false}) {
    const AnyRodLaw law = jc_law(curve ? curve_law() : linear_law());
    const std::vector<std::vector<double>> temps{{0, 0}, {kTref, kTref}, {0, kTref}, {kTref, 0}, {100, 200}};
    std::vector<double> stress(temps.size() + 1), shift(temps.size() + 1);
    for (std::size_t c = 0; c <= temps.size(); ++c) {
      OneRod rod;
      if (c < temps.size()) rod.temperature = temps[c];
      for (int i = 1; i <= 100; ++i) {
        rod.evaluate_at(law, 3e-4 * i, 1e3, c < temps.size());
        rod.commit();
      }
      stress[c] = rod.stress;
      shift[c] = rod.shift;
    }
    for (std::size_t c = 1; c < stress.size(); ++c) {
      EXPECT_EQ(stress[c], stress[0]) << c;
      EXPECT_EQ(shift[c], shift[0]) << c;
    }
    EXPECT_NEAR(stress[0], closed_stress(curve, 0.03, closed_scale(1e3, kTref, 1.0)), 1e-9 * 500e6);
    // One end unset and the other hot: the rod is at the mean of T_ref and the hot end's, not at
    // half the hot end's temperature.
    auto hot = [&](double t0, double t1) {
      OneRod rod;
      rod.temperature = {t0, t1};
      return rod.evaluate_at(law, 0.03, 1e3).stress;
    };
    EXPECT_EQ(hot(0.0, 1300.0), hot(kTref, 1300.0));
    EXPECT_EQ(hot(1300.0, 0.0), hot(kTref, 1300.0));
    EXPECT_NEAR(hot(0.0, 1300.0), closed_stress(curve, 0.03, closed_scale(1e3, 0.5 * (kTref + 1300.0), 1.0)),
                1e-9 * 500e6);
  }
}

// At and above T_melt the thermal factor is the floor 1e-3 (T* clamps to 1), not 0 or negative:
// the rod keeps 1e-3 of its flow stress, and the return map stays finite (it divides by S).
// A rod at T_melt pulled to 0.05 follows 1e-3 R flow(eps_p) (tolerance as in the path test).
TEST(JohnsonCookRodLaw, ARodAtTheMeltTemperatureKeepsTheFloor) {
  const JohnsonCookRodLaw jc = jc_law(curve_law());
  EXPECT_EQ(thermal_factor(jc, kTmelt), 1e-3);
  EXPECT_EQ(thermal_factor(jc, 2 * kTmelt), 1e-3);
  EXPECT_EQ(thermal_factor(jc, kTmelt - 1.0), 1e-3);  // (1 K below: 1 - T* = 1/1439.85 = 6.9e-4, under the floor)
  EXPECT_NEAR(thermal_factor(jc, kTmelt - 10.0), 10.0 / 1439.85, 1e-15);  // (10 K below: above it)
  for (double T : {kTmelt, 1.5 * kTmelt}) {
    OneRod rod;
    rod.temperature = {T, T};
    const double R = 1 + 0.05 * std::log(1e3 * 2 / std::sqrt(3.0));
    for (int i = 1; i <= 500; ++i) {
      const double eps = 1e-4 * i;
      const RodResponse r = rod.evaluate_at(jc, eps, 1e3);
      rod.commit();
      EXPECT_NEAR(r.stress, closed_stress(true, eps, 1e-3 * R), 1e-9 * 1e-3 * R * 500e6) << eps;
      ASSERT_TRUE(std::isfinite(r.shift));
    }
    EXPECT_NEAR(rod.stress, 1e-3 * R * flow(plastic_strain(jc, rod.shift)), 1e-9 * rod.stress);
  }
}

// The Newton step's tangent at a temperature: d sigma / d eps and d sigma / d rate of the hot law
// against central differences of evaluate at that temperature (tolerances as in
// test_rate_rod_law.cpp: linear on a branch in the strain, a logarithm in the rate).
TEST(JohnsonCookRodLaw, TheTangentAtATemperatureIsTheDerivativeOfEvaluate) {
  for (RodLaw base : {linear_law(), curve_law()}) {
    base.viscosity = 20.0;
    const JohnsonCookRodLaw law = jc_law(base);
    for (double T : {kTref, 900.0, 1600.0})
      for (double rate : {50.0, -3e3})
        for (double eps : {0.0068, -0.02}) {
          const RodResponse r = evaluate(law, eps, rate, 0.0, T);
          const RodTangent t = tangent(law, eps, rate, 0.0, r.shift, T);
          auto total = [&](double e, double q) {
            const RodResponse x = evaluate(law, e, q, 0.0, T);
            return x.stress + x.viscous_stress;
          };
          const double he = 1e-9, hq = 1e-4 * std::abs(rate);
          const double d_eps = (total(eps + he, rate) - total(eps - he, rate)) / (2 * he);
          const double d_rate = (total(eps, rate + hq) - total(eps, rate - hq)) / (2 * hq);
          EXPECT_NEAR(t.stiffness, d_eps, 1e-6 * kE) << T << " " << rate << " " << eps;
          EXPECT_NEAR(t.damping, d_rate, 1e-5 * std::max(std::abs(d_rate), base.viscosity))
              << T << " " << rate << " " << eps;
        }
  }
}

// Newton's lagged rate factor (integrate/newton.cpp): at a held scale S the slopes are those of
// evaluate_scaled at that S (central differences in the strain, 1e-6 of E as above), the rate
// term is the viscosity alone, and at S = 1 they are the base law's bit for bit.
TEST(JohnsonCookRodLaw, TheTangentAtAHeldScaleIsTheDerivativeOfEvaluateScaled) {
  for (RodLaw base : {linear_law(), curve_law()}) {
    base.viscosity = 20.0;
    const JohnsonCookRodLaw law = jc_law(base);
    for (double S : {1.0, 1.07, 0.6})
      for (double eps : {0.0068, -0.02, 0.0004}) {
        const RodResponse r = evaluate_scaled(law, eps, 50.0, 0.0, S);
        const RodTangent t = tangent_at_scale(law, 0.0, r.shift, S);
        const double he = 1e-9;
        const double d_eps = (evaluate_scaled(law, eps + he, 50.0, 0.0, S).stress -
                              evaluate_scaled(law, eps - he, 50.0, 0.0, S).stress) /
                             (2 * he);
        EXPECT_NEAR(t.stiffness, d_eps, 1e-6 * kE) << S << " " << eps;
        EXPECT_EQ(t.damping, base.viscosity);
        if (S == 1.0) {
          const RodTangent b = tangent(base, eps, 50.0, 0.0, r.shift);
          EXPECT_EQ(t.stiffness, b.stiffness);
        }
      }
  }
}

// The keys: rod.law = "johnson_cook" with the rod route's factors, "johnson_cook_rate" as its
// alias, and the [material] route taking the preset's C, m, rate and temperatures with the rate
// conversion of its calibration (2/sqrt3 in shear, 3 in tension); keys of the law without it
// are errors that name them.
// One rod pulled at a constant speed through a case file and the Simulation, its ends held at
// 1000 K (set in the World: no [heat], so nothing changes them), with the explicit step and with
// the implicit Newmark step solved by Newton (whose tangent reads the temperatures too): both
// yield at R Theta s_y, perfectly plastic, and follow min(E eps, R Theta s_y) at every step.
// Tolerance 1e-9 relative as in test_rate_rod_law.cpp (the strain is prescribed: v t / L0).
TEST(JohnsonCookRodLaw, ARodPulledHotYieldsAtRThetaSigmaYInBothSteps) {
  test::TempDir dir("jc_rod");
  const test::PulledRod rod(dir.str());
  constexpr double T = 1000.0;
  const double S = (1.0 + 0.1 * std::log(rod.rate())) * (1.0 - (T - kTref) / (kTmelt - kTref)), sy = kE * kEpsY;
  const std::string law = fmt::format(
      "law = \"johnson_cook\"\nrate_sensitivity = 0.1\nreference_rate = 1.0\nmelt_temperature = {}\n"
      "reference_temperature = {}\n",
      kTmelt, kTref);
  for (const char* integrator : {"", "scheme = \"newmark\"\nsolver = \"newton\"\n"}) {
    const test::PulledRod::Result r = rod.run(rod.case_text(law, integrator), S, [&](Model& m) {
      m.particles.temperature = {T, T};
    });
    EXPECT_LT(r.deviation, 1e-9) << integrator;
    EXPECT_GT(r.steps, 20) << integrator;
    EXPECT_GT(r.flowing, r.steps / 3) << integrator;
    EXPECT_NEAR(r.stress, S * sy, 1e-9 * S * sy) << integrator;
  }
}

// A small C45 case on the [material] route (the preset gives the flow curve and the factors).
std::string c45_case(const std::string& rod_lines) {
  return "[workpiece]\ncells = [2, 2, 2]\nradius = 1.0e-5\n[material]\npreset = \"C45\"\n[rod]\n" + rod_lines +
         "[integrator]\nscheme = \"newmark\"\nend_time = 1e-6\n";
}

TEST(JohnsonCookRodLaw, TheCaseKeysBuildTheLaw) {
  const std::string jc = "law = \"johnson_cook\"\n";
  {
    const Model m = build_model(parse_case(c45_case(jc), "c45", {}));
    const auto* law = std::get_if<JohnsonCookRodLaw>(&m.rods.law);
    ASSERT_NE(law, nullptr);
    const MaterialPreset& c45 = *find_material_preset("C45");
    EXPECT_EQ(law->rate_sensitivity, c45.jc_c);
    EXPECT_EQ(law->softening_exponent, c45.jc_m);
    EXPECT_EQ(law->reference_rate, c45.reference_rate);
    EXPECT_EQ(law->melt_temperature, c45.melt_temperature);
    EXPECT_EQ(law->reference_temperature, c45.reference_temperature);
    EXPECT_DOUBLE_EQ(law->rate_to_equivalent, 2.0 / std::sqrt(3.0));
    EXPECT_EQ(describe(m.rods.law).name, "johnson_cook");
  }
  {
    const Model m = build_model(parse_case(
        c45_case(jc), "c45",
        {"material.johnson_cook_m=0.7", "material.melt_temperature=1600.0", "material.calibration=\"tension\""}));
    const auto& law = std::get<JohnsonCookRodLaw>(m.rods.law);
    EXPECT_EQ(law.softening_exponent, 0.7);
    EXPECT_EQ(law.melt_temperature, 1600.0);
    EXPECT_EQ(law.rate_to_equivalent, 3.0);
  }
  {
    // The rod route, and the former name as an alias.
    const Model m = build_model(parse_case(kDefaultCaseToml, "default",
                                           {"rod.law=\"johnson_cook_rate\"", "rod.rate_sensitivity=0.02",
                                            "rod.melt_temperature=1500.0", "rod.thermal_softening_exponent=0.9"}));
    const auto& law = std::get<JohnsonCookRodLaw>(m.rods.law);
    EXPECT_EQ(law.rate_sensitivity, 0.02);
    EXPECT_EQ(law.melt_temperature, 1500.0);
    EXPECT_EQ(law.softening_exponent, 0.9);
    EXPECT_EQ(law.reference_temperature, 293.15);
    EXPECT_EQ(law.rate_to_equivalent, 1.0);
  }
  test::expect_mentions(test::case_error(c45_case(""), {"material.johnson_cook_c=0.02"}),
                        {"johnson_cook_c", "johnson_cook"});
  test::expect_mentions(test::case_error(c45_case(jc), {"rod.melt_temperature=1500.0"}),
                        {"melt_temperature", "material"});
  test::expect_mentions(test::case_error(c45_case(jc), {"material.melt_temperature=200.0"}),
                        {"melt_temperature", "T_ref"});
  // The cold cut keeps the paper's law, to which the Johnson-Cook keys do not belong.
  const std::string cold = test::read_file(test::cold_cut_case());
  test::expect_mentions(test::case_error(cold, {"rod.thermal_softening_exponent=0.9"}),
                        {"thermal_softening_exponent", "johnson_cook"});
}

}  // namespace
}  // namespace swarf

// The rate factor's logarithm (core/series_log.h) against libm's over the rates a cut meets and
// far beyond (ratios 1 to 1e15, mantissas of every kind): within 4 ulp of std::log, the bound
// its series (truncation below 3e-19) and a dozen roundings give; ln 1 exactly 0 and below 1
// clamped to 0 (R = 1 at and under the reference rate).
TEST(JohnsonCookRodLaw, TheSeriesLogarithmAgreesWithLibmWithinFourUlp) {
  double worst = 0.0;
  std::uint64_t state = 0x9e3779b97f4a7c15ULL;
  for (int i = 0; i < 200000; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = static_cast<double>(state >> 11) * 0x1.0p-53;  // [0, 1)
    const double x = std::pow(10.0, 15.0 * u);
    const double ref = std::log(x);
    if (ref == 0.0) continue;
    worst = std::max(worst, std::fabs(swarf::series_log(x) - ref) / std::fabs(ref));
  }
  // (around x = 1 the relative error of ln x is the one to watch: x = 1 + 2^-k)
  for (int k = 1; k < 52; ++k) {
    const double x = 1.0 + std::ldexp(1.0, -k), ref = std::log(x);
    worst = std::max(worst, std::fabs(swarf::series_log(x) - ref) / ref);
  }
  EXPECT_LT(worst, 4.0 * 0x1.0p-52);
  EXPECT_EQ(swarf::series_log(1.0), 0.0);
  EXPECT_EQ(swarf::series_log_at_least_one(0.25), 0.0);
  EXPECT_EQ(swarf::series_log_at_least_one(0.0), 0.0);
  EXPECT_EQ(swarf::series_log(2.0), std::log(2.0));
}

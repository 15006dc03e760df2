// test_material_lab.cpp: 'swarf material' end to end: the built-in case's lattice measured
// against the [material] properties it was derived from, every test on a small case with a
// hardening curve (files, columns, the anisotropy's closed forms), and bad options refused with
// exit code 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "test_helpers.h"

namespace swarf {
namespace {

nlohmann::json read_json(const std::string& path) { return nlohmann::json::parse(test::read_file(path)); }

// A small case with the C45 rod hardening curve, and more [rod] lines.
std::string curve_case(const std::string& rod_lines) {
  return R"(
[workpiece]
cells = [2, 2, 2]
radius = 1.0e-5
[material]
density = 7870.0
[rod]
youngs_modulus = 276.85e9
flow_plastic_strain = [0.0, 0.003333, 0.01, 0.02667, 0.06667, 0.1667, 0.3333, 0.6667]
flow_stress = [249.0e6, 341.0e6, 368.1e6, 399.2e6, 434.6e6, 478.9e6, 519.4e6, 567.1e6]
)" + rod_lines +
         R"([integrator]
end_time = 1e-6
)";
}

TEST(MaterialLab, LinearCutTension100MatchesItsMaterialProperties) {
  // The linear-law cut (the built-in case until 2026-12-02) gives [material] youngs_modulus = 200 GPa and yield_stress
  // = 450 MPa along [100] (hardening 10 GPa); the rods are derived from them by the small-strain relations, so the
  // lattice's initial modulus is 200 GPa to O(strain): the first increment's secant, 2.5 times the increment 1e-3 high
  // (test_lattice_material.cpp), 3e-3 asked; its 0.2 % offset yield lies just above 450 MPa (450 + 10 GPa x ~0.002
  // x 1.x at most: below 480 MPa).
  test::TempDir dir("material_default");
  const auto r = test::run_command(
      fmt::format("timeout 120 {} material {} --test tension100 --to 0.02 --increment 1e-3 --out {}", SWARF_BINARY,
                  test::linear_cut_case(), dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string csv = test::read_file(dir / "out/tension100.csv");
  EXPECT_EQ(csv.rfind("strain_1,stress_Pa,equivalent_strain_1,equivalent_stress_Pa,plastic_strain_1,", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 22);  // header, strain 0, 20 increments (rods break at ~0.03)
  const auto j = read_json(dir / "out/material.json");
  const auto& t = j["tests"]["tension100"];
  EXPECT_NEAR(t["initial_modulus_Pa"].get<double>(), 200e9, 3e-3 * 200e9);
  EXPECT_GT(t["yield_test_stress_Pa"].get<double>(), 450e6);
  EXPECT_LT(t["yield_test_stress_Pa"].get<double>(), 480e6);
  EXPECT_NEAR(t["poisson_ratios"][0].get<double>(), 1.0 / 3.0, 3e-3);     // first increment, 1e-3
  EXPECT_NE(r.output.find("tension100"), std::string::npos) << r.output;  // the table
}

TEST(MaterialLab, EveryTestOnACaseWithAHardeningCurve) {
  test::TempDir dir("material_all");
  test::write_file(dir / "c.toml", curve_case("failure_strain = 1.0\n"));
  const auto r = test::run_command(fmt::format("timeout 200 {} material {} --test all --increment 2e-4 --out {}",
                                               SWARF_BINARY, dir / "c.toml", dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* t : {"tension100", "tension110", "compression100", "shear100", "shear45", "cyclic100"})
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string("out/") + t + ".csv"))) << t;
  const auto j = read_json(dir / "out/material.json");
  // Closed forms (test_lattice_material.cpp): E110/E100 = 1.5, Zener ratio 2, the first
  // increment's O(strain) error allowed: 2e-3 relative at 2e-4 (below the rods' yield strain 9e-4).
  EXPECT_NEAR(j["anisotropy"]["E110_over_E100"].get<double>(), 1.5, 1.5 * 2e-3);
  EXPECT_NEAR(j["anisotropy"]["zener_ratio"].get<double>(), 2.0, 2.0 * 2e-3);
  EXPECT_NEAR(j["lattice"]["zener_ratio"].get<double>(), 2.0, 1e-12);
  // The rod law came through the case: the lattice's [100] yield is 3 (E100/E) 249 MPa = 553 MPa
  // (the C45 curve's A) at first yield; the 0.2 % offset lies above it.
  const auto& t100 = j["tests"]["tension100"];
  EXPECT_GT(t100["yield_test_stress_Pa"].get<double>(), 553e6);
  EXPECT_LT(t100["yield_test_stress_Pa"].get<double>(), 700e6);
  EXPECT_TRUE(t100["failed"].get<bool>());
  // tau/sigma: 0.5 at first yield (test_lattice_material.cpp); at an equivalent plastic strain of
  // 0.2 % the cube-plane rods have flowed 2.6 times as far as the [100] ones (gamma_p/2 against
  // eps_p/3) and hardened more: between Tresca's 0.5 and von Mises' 0.577 here.
  const double ts = j["anisotropy"]["tau_over_sigma"]["shear100"]["0.002"].get<double>();
  EXPECT_GT(ts, 0.5);
  EXPECT_LT(ts, 0.6);
  if (std::filesystem::exists(dir / "out/tension100.png")) {  // (matplotlib present)
    EXPECT_TRUE(std::filesystem::exists(dir / "out/material.png"));
  }
}

// A Johnson-Cook law (the rod route: C = 0.0134, rate_ref 1/s, m = 1, T_melt 1733 K, T_ref 293.15 K)
// run at several temperatures and rates: every flow stress is S = R Theta times the one at T_ref
// and quasi-static, with R = 1 + C ln(rate / rate_ref) (kappa = 1 on the rod route) and
// Theta = 1 - (T - T_ref)/(T_melt - T_ref), the closed form computed here. Tolerance 1e-2
// relative: every rod's law is exactly the scaled one, but the crystal is at finite strain, and at
// the same plastic strain (0.1) the scaled lattice has a smaller elastic strain (by (1 - S) sigma/E,
// about 2e-3 here), so its rods' directions and the current areas that turn their forces into a
// Cauchy stress differ by that order (measured: below 0.2 % at S = 1.12, 0.57 % at S = 0.17). A factor
// left out is far outside it (R at 1e4/s is 1.12; Theta at 900 K 0.58).
TEST(MaterialLab, AJohnsonCookLawAtSeveralTemperaturesAndRatesScalesByTheClosedForm) {
  test::TempDir dir("material_jc");
  test::write_file(dir / "c.toml", curve_case(R"(law = "johnson_cook"
rate_sensitivity = 0.0134
reference_rate = 1.0
thermal_softening_exponent = 1.0
melt_temperature = 1733.0
reference_temperature = 293.15
)"));
  auto flow = [&](const std::string& name, const std::string& conditions) {
    const auto r = test::run_command(
        fmt::format("timeout 120 {} material {} --test tension100 --to 0.15 --increment "
                    "1e-3 {} --out {}",
                    SWARF_BINARY, dir / "c.toml", conditions, dir / name));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const auto j = read_json(dir / (name + "/material.json"));
    return std::make_pair(j["tests"]["tension100"]["flow_stress_Pa"]["0.1"].get<double>(), j);
  };
  const double ref = flow("ref", "").first;
  struct Case {
    double T, rate;
  };
  for (const Case c : {Case{293.15, 1e4}, Case{900.0, 0.0}, Case{900.0, 1e4}, Case{1500.0, 1e2}}) {
    const double R = c.rate > 1.0 ? 1.0 + 0.0134 * std::log(c.rate) : 1.0;
    const double theta = 1.0 - (c.T - 293.15) / (1733.0 - 293.15), S = R * theta;
    const auto [hot, j] = flow(fmt::format("T{}_r{}", c.T, c.rate),
                               fmt::format("--temperature {} --strain-rate {}", c.T, c.rate));
    EXPECT_NEAR(j["flow_scale"].get<double>(), S, 1e-12 * S) << c.T << " " << c.rate;
    EXPECT_NEAR(hot / ref, S, 1e-2 * S) << c.T << " " << c.rate;
  }
}

TEST(MaterialLab, BadOptionsExitWithTwo) {
  test::TempDir dir("material_bad");
  const auto run = [&](const std::string& args) {
    return test::run_command(fmt::format("timeout 60 {} material {} --out {}", SWARF_BINARY, args, dir / "out"));
  };
  auto r = run("--test frob");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("tension110"), std::string::npos) << r.output;  // the list of tests
  r = run("--test all --to 1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run("--test shear100 --to -1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run("--test shear100 --increment 0");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run(dir / "missing.toml");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run("--set rod.flow_stress=[1e8]");  // a curve without its plastic strains
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // The cold cut's law is the paper's, not Johnson-Cook: a temperature means nothing to it.
  r = run(test::cold_cut_case() + " --test tension100 --temperature 900");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("johnson_cook"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace swarf

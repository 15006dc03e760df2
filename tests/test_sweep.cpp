// test_sweep.cpp: parameter studies: study-file expansion and errors, case states and
// resuming, the report's fits on synthetic summaries, and end-to-end sweeps of a tiny bar
// with --jobs 2 and (test sweep_mpi_two_ranks) with mpirun -n 2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "study/report.h"
#include "study/study.h"
#include "study/study_record.h"
#include "study/study_table.h"
#include "study/sweep.h"
#include "swarf/core/errors.h"
#include "test_helpers.h"

namespace swarf {
namespace {

namespace fs = std::filesystem;

const std::string kTinyBase = std::string(SWARF_SOURCE_DIR) + "/tests/data/sweep_tiny.toml";

std::string message_of(const std::string& text) {
  try {
    (void)parse_study(text, "study.toml", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(StudyFile, GridExpandsFirstKeySlowest) {
  const Study s = parse_study(R"(base = "case.toml"
[set]
output.vtk = false
[grid]
rod.damping_ratio = [0.1, 0.2]
"mesh.0.rake_angle" = [0, 10.0, 20]
)",
                              "study.toml", "/studies");
  EXPECT_EQ(s.base_path, "/studies/case.toml");
  ASSERT_EQ(s.parameters, (std::vector<std::string>{"mesh.0.rake_angle", "rod.damping_ratio"}));
  ASSERT_EQ(s.cases.size(), 6u);
  EXPECT_EQ(s.cases[0].id, "0000");
  EXPECT_EQ(s.cases[5].id, "0005");
  // Keys in alphabetical order, the first one varying slowest; integers stay integers.
  EXPECT_EQ(s.cases[0].values.at("mesh.0.rake_angle"), "0");
  EXPECT_EQ(s.cases[1].values.at("mesh.0.rake_angle"), "0");
  EXPECT_EQ(s.cases[1].values.at("rod.damping_ratio"), "0.2");
  EXPECT_EQ(s.cases[2].values.at("mesh.0.rake_angle"), "10.0");
  EXPECT_EQ(s.cases[5].values.at("mesh.0.rake_angle"), "20");
  EXPECT_EQ(case_overrides(s, s.cases[3]),
            (std::vector<std::string>{"output.vtk=false", "mesh.0.rake_angle=10.0", "rod.damping_ratio=0.2"}));
}

TEST(StudyFile, PointsTimesGridTimesRepetitions) {
  const Study s = parse_study(R"(base = "/abs/case.toml"
repetitions = 3
seed_key = "workpiece.seed"
seed_start = 7
[grid]
rod.damping_ratio = [0.1, 0.2]
[[point]]
"mesh.0.origin" = [-0.3e-3, 0.35e-3, 2.2e-3]
[[point]]
mesh.0.origin = [-0.3e-3, 0.35e-3, 2.1e-3]
integrator.scheme = "newmark"
)",
                              "study.toml", "/x");
  EXPECT_EQ(s.base_path, "/abs/case.toml");
  ASSERT_EQ(s.cases.size(), 12u);
  EXPECT_EQ(s.parameters,
            (std::vector<std::string>{"integrator.scheme", "mesh.0.origin", "rod.damping_ratio", "workpiece.seed"}));
  EXPECT_EQ(s.cases[0].values.at("mesh.0.origin"), "[-0.0003, 0.00035, 0.0022]");
  EXPECT_EQ(s.cases[0].values.count("integrator.scheme"), 0u);
  EXPECT_EQ(s.cases[0].values.at("workpiece.seed"), "7");
  EXPECT_EQ(s.cases[2].values.at("workpiece.seed"), "9");
  EXPECT_EQ(s.cases[2].repetition, 2);
  EXPECT_EQ(s.cases[3].values.at("rod.damping_ratio"), "0.2");
  EXPECT_EQ(s.cases[6].values.at("integrator.scheme"), "\"newmark\"");
  EXPECT_EQ(s.cases[6].values.at("mesh.0.origin"), "[-0.0003, 0.00035, 0.0021]");
}

TEST(StudyFile, BadFilesNameFileKeyValue) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
      {"base = \"c.toml\"\nbogus = 1\n[grid]\na.b = [1, 2]\n", {"study.toml:2", "key 'bogus' = 1", "unknown key"}},
      {"[grid]\na.b = [1, 2]\n", {"study.toml", "key 'base' must be set"}},
      {"base = \"c.toml\"\n[grid]\nrod.damping_ratio = 0.1\n",
       {"study.toml:3", "key 'grid.rod.damping_ratio' = 0.1", "non-empty array"}},
      {"base = \"c.toml\"\n[grid]\nrod.damping_ratio = []\n", {"key 'grid.rod.damping_ratio' = []", "non-empty"}},
      {"base = \"c.toml\"\n[grid]\nrod.damping_ratio = [0.1, 0.1]\n", {"listed twice"}},
      {"base = \"c.toml\"\nrepetitions = 3\n[grid]\na.b = [1, 2]\n",
       {"study.toml:2", "key 'repetitions' = 3", "deterministic", "seed_key"}},
      {"base = \"c.toml\"\nrepetitions = 0\nseed_key = \"s\"\n", {"key 'repetitions' = 0", "[1, 10000]"}},
      {"base = \"c.toml\"\n[set]\na.b = 1\n[grid]\na.b = [1, 2]\n", {"key 'set.a.b' = 1", "is also varied"}},
      {"base = \"c.toml\"\nplots = \"yes\"\n[grid]\na.b = [1, 2]\n", {"key 'plots' = 'yes'", "true or false"}},
      {"base = \"c.toml\"\n[grid]\na.b = [1979-05-27]\n", {"key 'grid.a.b' = 1979-05-27", "dates"}},
      {"base = \"c.toml\"\n[grid]\na.b = [1, 2]\n[units]\nc.d = \"m\"\n", {"key 'units.c.d' = 'm'", "not a varied key"}},
      {"base = \"c.toml\"\n[grid]\n\"a b\" = [1, 2]\n", {"key 'a b'", "not a case key"}},
      {"base = \"c.toml\"\n[grid\n", {"study.toml:2", "TOML syntax error"}},
      {"base = \"c.toml\"\n", {"nothing varies"}},
      {"base = \"c.toml\"\nrepetitions = 2\nseed_key = \"a.b\"\nseed_start = 9223372036854775807\n",
       {"key 'seed_start'", "[-2^53, 2^53]"}},  // (seed_start + 1 overflowed)
      // 64 axes of two values: the count wrapped round to 0 cases (a study that ran nothing).
      {[] {
         std::string t = "base = \"c.toml\"\n[grid]\n";
         for (int k = 0; k < 64; ++k) t += fmt::format("a{}.b = [1, 2]\n", k);
         return t;
       }(),
       {"more than 100000 cases"}},
  };
  for (const auto& [text, expected] : cases) {
    const std::string msg = message_of(text);
    for (const auto& e : expected) EXPECT_NE(msg.find(e), std::string::npos) << "'" << e << "' not in: " << msg;
  }
}

TEST(StudyFile, BadCaseKeyStopsTheStudyBeforeItRuns) {
  test::TempDir dir("sweep_badkey");
  test::write_file(dir / "s.toml", fmt::format("base = \"{}\"\n[grid]\nrod.damping_ration = [0.1, 0.2]\n", kTinyBase));
  const Study s = load_study(dir / "s.toml");
  EXPECT_EQ(s.base_hash.size(), 16u);
  try {
    check_cases(s);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("case 0000 (rod.damping_ration=0.1)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("damping_ration"), std::string::npos) << msg;
  }
  test::write_file(dir / "t.toml", "base = \"nowhere.toml\"\n[grid]\na.b = [1, 2]\n");
  EXPECT_THROW((void)load_study(dir / "t.toml"), InputError);
}

// A summary.json that case_status accepts as finished, with cutting metrics.
void write_summary(const std::string& out, const Study& s, const StudyCase& c, const nlohmann::json& extra) {
  fs::create_directories(case_dir(out, c));
  nlohmann::json j = extra;
  j["status"] = "completed";
  j["overrides"] = case_overrides(s, c);
  test::write_file((fs::path(case_dir(out, c)) / "summary.json").string(), j.dump(1));
}

TEST(Resume, CaseStatesAndChangedStudies) {
  test::TempDir dir("sweep_resume");
  const std::string out = dir / "out";
  const std::string
      text = "base = \"c.toml\"\n[set]\noutput.vtk = false\n[grid]\nrod.damping_ratio = [0.1, 0.2, 0.3, 0.4]\n";
  Study s = parse_study(text, "study.toml", dir.str());
  s.base_hash = "0123456789abcdef";
  write_study_json(s, out);
  write_summary(out, s, s.cases[0], nlohmann::json::object());
  fs::create_directories(case_dir(out, s.cases[1]));
  test::write_file(case_dir(out, s.cases[1]) + "/log.txt", "killed halfway\n");  // no summary: interrupted
  fs::create_directories(case_dir(out, s.cases[2]));
  test::write_file(case_dir(out, s.cases[2]) + "/sweep_status.json", R"({"exit_code": 3, "log_tail": "boom\n"})");
  Study other = s;  // a summary run with other overrides is not this case's
  other.fixed["output.vtk"] = "true";
  write_summary(out, other, s.cases[3], nlohmann::json::object());

  EXPECT_EQ(case_status(s, s.cases[0], out).text(), "completed");
  EXPECT_EQ(case_status(s, s.cases[1], out).text(), "interrupted");
  EXPECT_EQ(case_status(s, s.cases[2], out).text(), "failed (exit 3)");
  EXPECT_EQ(case_status(s, s.cases[2], out).log_tail, "boom\n");
  EXPECT_EQ(case_status(s, s.cases[3], out).text(), "not run");

  auto reconciled = [&](const std::string& t, const std::string& hash = "0123456789abcdef") {
    Study n = parse_study(t, "study.toml", dir.str());
    n.base_hash = hash;
    reconcile_study(n, out);
    return n;
  };
  auto refusal = [&](const std::string& t, const std::string& hash = "0123456789abcdef") -> std::string {
    try {
      reconciled(t, hash);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  // Same study: same ids. A new value: a new case numbered after the others, even when listed first.
  EXPECT_EQ(reconciled(text).cases[3].id, "0003");
  const Study grown = reconciled(
      "base = \"c.toml\"\n[set]\noutput.vtk = false\n[grid]\nrod.damping_ratio = [0.05, 0.1, 0.2, 0.3, 0.4]\n");
  ASSERT_EQ(grown.cases.size(), 5u);
  EXPECT_EQ(grown.cases[0].values.at("rod.damping_ratio"), "0.1");
  EXPECT_EQ(grown.cases[4].id, "0004");
  EXPECT_EQ(grown.cases[4].values.at("rod.damping_ratio"), "0.05");
  // Changes that invalidate the finished case 0000 are refused, naming the key.
  EXPECT_NE(refusal("base = \"c.toml\"\n[set]\noutput.vtk = true\n[grid]\nrod.damping_ratio = [0.1, 0.2, 0.3, 0.4]\n")
                .find("set.output.vtk (false -> true)"),
            std::string::npos);
  EXPECT_NE(refusal("base = \"c.toml\"\n[set]\noutput.vtk = false\n[grid]\nrod.damping_ratio = [0.2, 0.3, 0.4]\n")
                .find("rod.damping_ratio = 0.1 is no longer in the study (finished case 0000)"),
            std::string::npos);
  EXPECT_NE(refusal(text, "ffffffffffffffff").find("base (the text of the base case"), std::string::npos);
  EXPECT_NE(refusal("base = \"c.toml\"\n[set]\noutput.vtk = false\n[grid]\nrod.damping_ratio = [0.1, 0.2, 0.3, 0.4]\n"
                    "rod.hardening_modulus = [1e9, 2e9]\n")
                .find("rod.hardening_modulus is newly varied"),
            std::string::npos);
  // Removing only unfinished cases is allowed.
  EXPECT_EQ(
      reconciled("base = \"c.toml\"\n[set]\noutput.vtk = false\n[grid]\nrod.damping_ratio = [0.1, 0.4]\n").cases[1].id,
      "0003");
}

TEST(StudyTable, UnitsOfTheDeclaredResults) {
  EXPECT_EQ(unit_of_key("cutting.cutting_force_per_width_mean_N_per_m"), "N/m");
  EXPECT_EQ(unit_of_key("chip.shear_angle_deg"), "deg");
  EXPECT_EQ(unit_of_key("chip.depth_of_cut_m"), "m");
  EXPECT_EQ(unit_of_key("results.plastic_work_J"), "J");
  EXPECT_EQ(unit_of_key("results.reaction_grip_N.x"), "N");
  EXPECT_EQ(unit_of_key("uniaxial.cross_section_m2"), "m^2");
  EXPECT_EQ(unit_of_key("uniaxial.deviation_percent.yield_stress"), "%");
  EXPECT_EQ(unit_of_key("results.broken_fraction"), "1");
  EXPECT_EQ(unit_of_key("chip.compression_ratio"), "1");
  EXPECT_EQ(unit_of_key("run.force_evaluations_per_us"), "1/us");
}

TEST(Report, LeastSquaresLine) {
  const LinearFit f = fit_line_r2({1, 2, 3, 4}, {2, 4, 5, 4});
  ASSERT_TRUE(f.ok);
  EXPECT_NEAR(f.slope, 0.7, 1e-12);
  EXPECT_NEAR(f.intercept, 2.0, 1e-12);
  EXPECT_NEAR(f.r2, 1.0 - 2.3 / 4.75, 1e-12);
  EXPECT_FALSE(fit_line_r2({1, 1}, {2, 3}).ok);
  EXPECT_NEAR(fit_line_r2({1, 2, 3}, {5, 5, 5}).r2, 1.0, 0.0);
}

// Synthetic cutting study: four depths of cut, Fc exactly linear in the depth, Ft scattered,
// and shear angles that follow Merchant's line exactly.
TEST(Report, SyntheticCuttingStudyFitsAndMerchant) {
  test::TempDir dir("sweep_report");
  const std::string out = dir / "out";
  const Study s = parse_study(R"(base = "first_cut.toml"
title = "synthetic depth study"
plots = false
[grid]
mesh.0.origin = [[0, 0, 2.4e-3], [0, 0, 2.3e-3], [0, 0, 2.2e-3], [0, 0, 2.1e-3]]
[units]
mesh.0.origin = "m"
)",
                              "depth.toml", dir.str());
  write_study_json(s, out);
  const double depth[4] = {3e-4, 4e-4, 5e-4, 6e-4}, ft[4] = {2e4, 4e4, 5e4, 4e4}, amb[4] = {-30, -20, -10, 0};
  for (int k = 0; k < 4; ++k) {
    const double beta = 10.0 - amb[k];  // rake 10 deg
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", 2e8 * depth[k] + 3e4},
                    {"thrust_force_per_width_mean_N_per_m", ft[k]},
                    {"tool_mesh", "tool"}};
    j["chip"] = {{"depth_of_cut_m", depth[k]},
                 {"friction_angle_deg", beta},
                 {"merchant_shear_angle_deg", 45.0 + 0.5 * amb[k]},
                 {"shear_angle_deg", 45.0 + 0.5 * amb[k]}};
    j["results"] = {{"broken_fraction", 0.01 * k}};
    write_summary(out, s, s.cases[k], j);
  }
  // The table: sorted by case, the names and then the cases (no units line: a reader's
  // names=True must find numbers on line 2), strings not in it; the units in the sidecar.
  const StudyTable t = collect_table(s, out);
  const std::string csv = table_csv(t);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "case,mesh.0.origin,status,results.broken_fraction,cutting.cutting_force_per_width_mean_N_per_m,"
            "cutting.thrust_force_per_width_mean_N_per_m,chip.depth_of_cut_m,chip.friction_angle_deg,"
            "chip.merchant_shear_angle_deg,chip.shear_angle_deg");
  EXPECT_EQ(csv.find("\n-,"), std::string::npos) << csv;
  EXPECT_EQ(csv.substr(csv.find('\n') + 1, 5), "0000,") << csv;
  EXPECT_NE(csv.find("\n0002,\"[0, 0, 0.0022]\",completed,0.02,"), std::string::npos) << csv;
  const std::string columns = columns_csv(t, collect_table(s, out, true));
  EXPECT_EQ(columns.rfind("column,unit,description\ncase,-,", 0), 0u) << columns;
  for (const char* row : {"\nmesh.0.origin,m,varied case key", "\nstatus,-,", "\nresults.broken_fraction,1,",
                          "\ncutting.cutting_force_per_width_mean_N_per_m,N/m,", "\nchip.depth_of_cut_m,m,",
                          "\nchip.shear_angle_deg,deg,"})
    EXPECT_NE(columns.find(row), std::string::npos) << row << "\n" << columns;
  // Plot data: against the one varying component of the origin.
  const auto series = plot_series(s, t);
  ASSERT_FALSE(series.empty());
  EXPECT_EQ(series[0].x_name, "mesh.0.origin[2]");
  EXPECT_EQ(series[0].x.size(), 4u);
  EXPECT_EQ(series[0].group_labels, std::vector<std::string>{""}) << "one varied key: one unnamed group";
  EXPECT_EQ(series[0].group, std::vector<int>(4, 0));

  const std::string md = test::read_file(write_report(out));
  EXPECT_NE(md.find("# Study report: synthetic depth study"), std::string::npos);
  EXPECT_NE(md.find("| 0003 | [0, 0, 0.0021] | completed |"), std::string::npos) << md;
  // Fc/w = 2e8 h + 3e4 exactly; Ft/w scattered: slope 7e7 N/m^2, intercept 6000 N/m, R^2 = 1 - 2.3/4.75.
  EXPECT_NE(md.find("| 2e+08 N/m^2 | 30000 N/m | 1.000000 | 4 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 7e+07 N/m^2 | 6000 N/m | 0.515789 | 4 |"), std::string::npos) << md;
  EXPECT_NE(md.find("a = 0.5 (Merchant: 0.5), b = 45 deg (Merchant: 45 deg), R^2 = 1.0000, 4 cases"), std::string::npos)
      << md;
  EXPECT_NE(md.find("mean phi - phi_M = 0 deg"), std::string::npos) << md;
}

// A grid of depths times speeds (the speed set by points with its own end time): against the
// measured depth one line per speed, against the speed one line per depth (the tool origin and
// the end time go with their axes), each labelled by the other axis's group mean; Oxley's figure
// rides along as the reference of the metrics he gives, none for the others.
TEST(StudyTable, PlotsGroupTheOtherAxisAndCarryOxley) {
  test::TempDir dir("sweep_groups");
  const std::string out = dir / "out";
  const Study s = parse_study(R"(base = "first_cut.toml"
plots = false
plot_against = ["chip.depth_of_cut_m", "mesh.0.velocity[0]"]
[[point]]
mesh.0.velocity = [5.0, 0.0, 0.0]
integrator.end_time = 2e-4
[[point]]
mesh.0.velocity = [10.0, 0.0, 0.0]
integrator.end_time = 1e-4
[grid]
mesh.0.origin = [[0, 0, 2.4e-3], [0, 0, 2.3e-3], [0, 0, 2.2e-3]]
[units]
mesh.0.velocity = "m/s"
mesh.0.origin = "m"
)",
                              "speed_feed.toml", dir.str());
  write_study_json(s, out);
  ASSERT_EQ(s.cases.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    const double h = 1e-4 * (1 + k % 3) * (1 + 1e-4 * k), v = k < 3 ? 5.0 : 10.0;  // measured depths scatter a little
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", 1e9 * h / v}};
    j["chip"] = {{"depth_of_cut_m", h}};
    j["oxley"] = {{"speed_m_per_s", v}, {"cutting_force_per_width_N_per_m", 9e8 * h / v}};
    write_summary(out, s, s.cases[k], j);
  }
  const StudyTable t = collect_table(s, out);
  int seen = 0;
  for (const auto& p : plot_series(s, t)) {
    if (p.y_name != "cutting.cutting_force_per_width_mean_N_per_m") continue;
    ++seen;
    ASSERT_EQ(p.group.size(), 6u);
    ASSERT_EQ(p.reference.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) EXPECT_DOUBLE_EQ(p.reference[i], 0.9 * p.y[i]);
    if (p.x_name == "chip.depth_of_cut_m") {
      EXPECT_EQ(p.group_labels,
                (std::vector<std::string>{"mesh.0.velocity[0] = 5 m/s", "mesh.0.velocity[0] = 10 m/s"}));
      EXPECT_EQ(p.group, (std::vector<int>{0, 0, 0, 1, 1, 1}));
    } else {
      EXPECT_EQ(p.x_name, "mesh.0.velocity[0]");
      EXPECT_EQ(p.group_labels,
                (std::vector<std::string>{"chip.depth_of_cut_m = 0.0001 m", "chip.depth_of_cut_m = 0.0002 m",
                                          "chip.depth_of_cut_m = 0.0003 m"}));
      EXPECT_EQ(p.group, (std::vector<int>{0, 1, 2, 0, 1, 2}));
    }
  }
  EXPECT_EQ(seen, 2);
  // A metric without Oxley's counterpart has none.
  EXPECT_EQ(oxley_key_of("chip.chip_temperature_K"), "");
  EXPECT_EQ(oxley_key_of("chip.thickness_m"), "oxley.chip_thickness_m");
}

// The interval column of a metric, by summary.json's naming.
TEST(StudyTable, ConfidenceIntervalColumnNames) {
  EXPECT_EQ(ci95_key_of("cutting.cutting_force_per_width_mean_N_per_m"),
            "cutting.cutting_force_per_width_ci95_N_per_m");
  EXPECT_EQ(ci95_key_of("chip.friction_angle_deg"), "chip.friction_angle_ci95_deg");
  EXPECT_EQ(ci95_key_of("chip.thickness_m"), "chip.thickness_ci95_m");
  EXPECT_EQ(ci95_key_of("chip.compression_ratio"), "chip.compression_ratio_ci95");
  EXPECT_EQ(ci95_key_of("cutting.thrust_to_cutting_force_ratio"), "cutting.thrust_to_cutting_force_ratio_ci95");
  EXPECT_EQ(ci95_key_of("results.reaction_grip_N.x"), "");
  EXPECT_EQ(unit_of_key("cutting.cutting_force_per_width_ci95_N_per_m"), "N/m");
  EXPECT_EQ(unit_of_key("chip.shear_angle_ci95_deg"), "deg");
}

// Steady means with their 95 % intervals: study.csv has the interval columns (empty where the
// summary has null), the plot data carry them as error bars (NaN where a case has none; none at
// all for a metric without an interval column), and the report's table reads "value +- ci".
TEST(Report, SteadyMeansCarryTheirIntervals) {
  test::TempDir dir("sweep_ci");
  const std::string out = dir / "out";
  const Study s = parse_study(R"(base = "first_cut.toml"
plots = false
[grid]
mesh.0.rake_angle = [0, 10, 20]
)",
                              "rake.toml", dir.str());
  write_study_json(s, out);
  for (int k = 0; k < 3; ++k) {
    nlohmann::json j;
    j["cutting"] = {{"cutting_force_per_width_mean_N_per_m", 1e5 - 1e4 * k},
                    {"cutting_force_per_width_std_N_per_m", 5e4},
                    {"cutting_force_per_width_ci95_N_per_m", k == 2 ? nlohmann::json(nullptr) : nlohmann::json(2e4)}};
    j["chip"] = {{"friction_angle_deg", 10.0 + k}, {"friction_angle_ci95_deg", 1.5}};
    write_summary(out, s, s.cases[k], j);
  }
  const StudyTable t = collect_table(s, out);
  const int col = t.column("cutting.cutting_force_per_width_ci95_N_per_m");
  ASSERT_GE(col, 0) << table_csv(t);
  EXPECT_EQ(t.units[col], "N/m");
  EXPECT_EQ(t.rows[0][col], "20000");
  EXPECT_EQ(t.rows[2][col], "") << "null: no interval";
  EXPECT_GE(t.column("cutting.cutting_force_per_width_mean_N_per_m"), 0);  // the existing column stays
  bool mean_seen = false, std_seen = false;
  for (const auto& p : plot_series(s, t)) {
    if (p.y_name == "cutting.cutting_force_per_width_mean_N_per_m") {
      mean_seen = true;
      ASSERT_EQ(p.y_err.size(), 3u);
      EXPECT_EQ(p.y_err[0], 2e4);
      EXPECT_TRUE(std::isnan(p.y_err[2]));
    }
    if (p.y_name == "cutting.cutting_force_per_width_std_N_per_m") {
      std_seen = true;
      EXPECT_TRUE(p.y_err.empty());
    }
  }
  EXPECT_TRUE(mean_seen && std_seen);
  const std::string md = test::read_file(write_report(out));
  EXPECT_NE(md.find("| 0000 | 0 | completed | 1e+05 +- 2e+04 | 5e+04 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 8e+04 | 5e+04 |"), std::string::npos) << md;  // no interval: the value alone
  EXPECT_NE(md.find("half-width of its 95 % confidence interval"), std::string::npos) << md;
}

// The tiny-bar study: a grid of damping ratios, three hardening moduli and a point with an
// unstable time step whose two cases fail (exit 2).
std::string tiny_study(bool plots, const std::string& series_interval = "1e-5") {
  return fmt::format(R"(base = "{}"
plots = {}
[set]
output.series_interval = {}
[grid]
rod.damping_ratio = [0.1, 0.2]
[[point]]
rod.hardening_modulus = 10e9
[[point]]
rod.hardening_modulus = 30e9
[[point]]
rod.hardening_modulus = 20e9
integrator.dt = 1.0
[units]
rod.hardening_modulus = "Pa"
rod.damping_ratio = "1"
integrator.dt = "s"
)",
                     kTinyBase, plots ? "true" : "false", series_interval);
}

std::string sweep_cmd(const std::string& study, const std::string& out, const std::string& extra = "--jobs 2") {
  return fmt::format("{} sweep {} --out {} {}", SWARF_BINARY, study, out, extra);
}

TEST(Sweep, JobsTwoFailureResumeRefusalAndReport) {
  test::TempDir dir("sweep_e2e");
  test::write_file(dir / "study.toml", tiny_study(true));
  const std::string out = dir / "out";
  auto r = test::run_command(sweep_cmd(dir / "study.toml", out));
  ASSERT_EQ(r.exit_code, 1) << r.output;  // two cases failed
  EXPECT_NE(r.output.find("6 cases, 0 finished earlier, 6 to run; 2 at once x 1 thread(s)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("FAILED"), std::string::npos);
  EXPECT_NE(r.output.find("ETA"), std::string::npos);
  const std::string csv = test::read_file(out + "/study.csv");
  EXPECT_EQ(csv.rfind("case,integrator.dt,rod.damping_ratio,rod.hardening_modulus,status,results.broken_fraction,", 0),
            0u)
      << csv;
  EXPECT_EQ(csv.find("\n-,s,1,Pa,-,1,"), std::string::npos) << "the units belong in study_columns.csv";
  const std::string columns = test::read_file(out + "/study_columns.csv");
  for (const char* row : {"\nintegrator.dt,s,", "\nrod.damping_ratio,1,", "\nrod.hardening_modulus,Pa,",
                          "\nresults.broken_fraction,1,", "\nrun.wall_time_s,s,timing.csv only: "})
    EXPECT_NE(columns.find(row), std::string::npos) << row << "\n" << columns;
  // numpy reads the metrics as numbers (with a units line it read every column as text).
  const auto np = test::run_command(
      "/usr/bin/python3 -c 'import sys, numpy; t = numpy.genfromtxt(sys.argv[1], delimiter=\",\", names=True, "
      "dtype=None, encoding=None, deletechars=\"\"); print(t.dtype[\"results.elastic_energy_J\"].kind, "
      "t[\"rod.damping_ratio\"][0])' " +
      out + "/study.csv");
  if (np.output.find("No module named") == std::string::npos) {
    EXPECT_EQ(np.exit_code, 0) << np.output;
    EXPECT_NE(np.output.find("f 0.1"), std::string::npos) << np.output;
  }
  EXPECT_NE(csv.find("\n0000,,0.1,1e+10,completed,0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n0005,1.0,0.2,2e+10,failed (exit 2),,"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("wall_time"), std::string::npos) << "timing columns belong in timing.csv";
  EXPECT_NE(test::read_file(out + "/timing.csv").find("run.wall_time_s"), std::string::npos);
  EXPECT_TRUE(fs::exists(out + "/plots/uniaxial_measured_hardening_tangent_Pa_vs_rod_hardening_modulus.png"));

  // A killed case (log, no summary) is run again, a finished one is kept, failed ones rerun.
  fs::remove(out + "/cases/0001/summary.json");
  test::write_file(out + "/cases/0000/marker", "kept");
  r = test::run_command(sweep_cmd(dir / "study.toml", out));
  ASSERT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("6 cases, 3 finished earlier, 3 to run"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out + "/cases/0000/marker"));
  EXPECT_TRUE(fs::exists(out + "/cases/0001/summary.json"));
  EXPECT_EQ(test::read_file(out + "/study.csv"), csv);

  // A changed fixed key would invalidate the finished cases: refused, naming the key.
  test::write_file(dir / "study.toml", tiny_study(true, "2e-5"));
  r = test::run_command(sweep_cmd(dir / "study.toml", out));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("set.output.series_interval (1e-05 -> 2e-05)"), std::string::npos) << r.output;

  r = test::run_command(fmt::format("{} report {}", SWARF_BINARY, out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string md = test::read_file(out + "/report.md");
  EXPECT_NE(md.find("6 cases: 4 completed, 2 failed"), std::string::npos) << md;
  EXPECT_NE(md.find("failed (exit 2), log `cases/0004/log.txt`"), std::string::npos) << md;
  EXPECT_NE(md.find("exceeds the stable step"), std::string::npos) << md;
  EXPECT_NE(md.find("](plots/uniaxial_measured_hardening_tangent_Pa_vs_rod_hardening_modulus.png)"), std::string::npos);
  EXPECT_EQ(md.find("Merchant"), std::string::npos) << "not a cutting study";
}

// A study that repeats the tiny bar over the workpiece's disorder seed: three cases, seeds 1, 2,
// 3, each completed, and their results differ (the spread the repetitions measure).
TEST(Sweep, RepetitionsOverTheDisorderSeedGiveDistinctRuns) {
  test::TempDir dir("sweep_seeds");
  test::write_file(dir / "study.toml", fmt::format(R"(base = "{}"
plots = false
repetitions = 3
seed_key = "workpiece.disorder_seed"
[set]
workpiece.position_jitter = 0.05
)",
                                                   kTinyBase));
  const std::string out = dir / "out";
  const auto r = test::run_command(sweep_cmd(dir / "study.toml", out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::vector<std::string>> rows;
  std::stringstream csv(test::read_file(out + "/study.csv"));
  for (std::string line; std::getline(csv, line);) {
    rows.emplace_back();
    std::stringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) rows.back().push_back(cell);
  }
  ASSERT_EQ(rows.size(), 4u);  // names, three cases
  const auto& names = rows[0];
  ASSERT_GE(names.size(), 4u);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 4),
            (std::vector<std::string>{"case", "workpiece.disorder_seed", "repetition", "status"}));
  const auto col = std::find(names.begin(), names.end(), "results.elastic_energy_J") - names.begin();
  ASSERT_LT(col, long(names.size()));
  std::set<std::string> energies;
  for (int k = 0; k < 3; ++k) {
    const auto& row = rows[1 + k];
    EXPECT_EQ(row[1], std::to_string(k + 1));
    EXPECT_EQ(row[3], "completed");
    energies.insert(row[col]);
  }
  EXPECT_EQ(energies.size(), 3u) << "each seed gives its own result";
}

// Run by ctest as sweep_mpi_two_ranks (SWARF_TEST_MPI=1): two MPI ranks share the cases and
// write the same study.csv as --jobs 2.
TEST(SweepMpi, TwoRanksWriteTheSameStudyCsvAsJobsTwo) {
  if (!std::getenv("SWARF_TEST_MPI")) GTEST_SKIP() << "run by the ctest test sweep_mpi_two_ranks";
  if (test::run_command("command -v mpirun").exit_code != 0) GTEST_SKIP() << "mpirun not installed";
  test::TempDir dir("sweep_mpi");
  test::write_file(dir / "study.toml", tiny_study(false));
  auto a = test::run_command(sweep_cmd(dir / "study.toml", dir / "jobs"));
  ASSERT_EQ(a.exit_code, 1) << a.output;
  auto b = test::run_command("mpirun -n 2 --oversubscribe --bind-to none --allow-run-as-root " +
                             sweep_cmd(dir / "study.toml", dir / "mpi", ""));
  ASSERT_NE(b.exit_code, 0) << "two cases fail: " << b.output;
  EXPECT_NE(b.output.find("to run on 2 ranks"), std::string::npos) << b.output;
  EXPECT_NE(b.output.find("[rank 1 of 2]: case 0001 completed"), std::string::npos) << b.output;
  const std::string csv = test::read_file(dir / "jobs/study.csv");
  EXPECT_NE(csv.find("completed"), std::string::npos);
  EXPECT_EQ(test::read_file(dir / "mpi/study.csv"), csv);
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// docs/studies.md shows validation/studies/rake_angle.toml as its example: the file's text, in
// full (it once showed a study of the first cut at four rake angles that the file no longer was).
TEST(StudyDocs, TheExampleIsTheValidationStudy) {
  const std::string doc = test::read_file(std::string(SWARF_SOURCE_DIR) + "/docs/studies.md");
  const std::string file = test::read_file(std::string(SWARF_SOURCE_DIR) + "/validation/studies/rake_angle.toml");
  ASSERT_FALSE(file.empty());
  EXPECT_NE(doc.find("Example (`validation/studies/rake_angle.toml`"), std::string::npos);
  EXPECT_NE(doc.find("```toml\n" + file + "```"), std::string::npos) << "docs/studies.md's example is not the file";
}

// Every study file in validation/studies is a study swarf accepts: 'swarf sweep --list' reads
// it, expands its cases and checks each case's overrides against its base, running nothing
// (depth_of_cut.toml once gave [units] to a key it did not vary, and nothing ran it).
TEST(StudyDocs, EveryValidationStudyIsAccepted) {
  test::TempDir dir("validation_studies");
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SWARF_SOURCE_DIR) + "/validation/studies")) {
    if (e.path().extension() != ".toml") continue;
    ++files;
    const auto r = test::run_command(
        fmt::format("{} sweep {} --out {} --list", SWARF_BINARY, e.path().string(), dir / e.path().stem().string()));
    EXPECT_EQ(r.exit_code, 0) << e.path() << ": " << r.output;
  }
  EXPECT_GE(files, 5);
}

}  // namespace
}  // namespace swarf

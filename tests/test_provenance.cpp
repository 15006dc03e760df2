// test_provenance.cpp: a run's files explain themselves and name the build that made them.
// results.h5 carries a unit and a description on every dataset, the cut's set-up as named
// values, the group names and the time history (equal to series.csv bit for bit); the
// sidecar series_columns.csv gives each column's unit; summary.json and results.h5 record the
// provenance, the same as `swarf --version` prints; run.log holds what the run printed; the
// effective case lists the defaults that the case file left out.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "io/h5file.h"
#include "scenes/tiny_cut.h"
#include "test_helpers.h"

namespace swarf {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream s(line);
  std::string x;
  while (std::getline(s, x, ',')) out.push_back(x);
  return out;
}

class Provenance : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir("provenance");
    test::write_file(*dir_ / "c.toml", test::kTinyCut);
    run_ = new test::CommandResult(
        test::run_command(std::string(SWARF_BINARY) + " run " + (*dir_ / "c.toml") + " --out " + (*dir_ / "out") +
                          " --threads 2 --set integrator.end_time=2e-5 --set output.steady_from=1e-5"));
  }
  static void TearDownTestSuite() {
    delete run_;
    delete dir_;
  }
  static std::string out(const std::string& name) { return *dir_ / ("out/" + name); }
  static test::TempDir* dir_;
  static test::CommandResult* run_;
};
test::TempDir* Provenance::dir_ = nullptr;
test::CommandResult* Provenance::run_ = nullptr;

TEST_F(Provenance, EveryResultsDatasetHasAUnitAndADescription) {
  ASSERT_EQ(run_->exit_code, 0) << run_->output;
  H5File f(out("results.h5"), H5File::Mode::Read);
  EXPECT_EQ(f.read_double_attribute("format"), 5.0);
  const auto sets = f.datasets();
  ASSERT_GT(sets.size(), 20u);
  for (const auto& s : sets) {
    EXPECT_FALSE(f.dataset_attribute(s, "description").empty()) << s;
    // (the group names are text: the only dataset whose unit is empty)
    if (s != "/groups/name") EXPECT_FALSE(f.dataset_attribute(s, "unit").empty()) << s;
  }
  EXPECT_EQ(f.dataset_attribute("/particles/position", "unit"), "m");
  EXPECT_EQ(f.dataset_attribute("/bonds/stress", "unit"), "Pa");
  EXPECT_EQ(f.dataset_attribute("/series/cutting_force_per_width", "unit"), "N/m");
  EXPECT_EQ(f.dataset_attribute("/cutting/rake_angle", "unit"), "deg");
  std::size_t r = 0, c = 0;
  EXPECT_EQ(f.read_doubles("/cutting/rake_angle", r, c), std::vector<double>{10.0});
  EXPECT_EQ(f.read_doubles("/cutting/tool_tip", r, c).size(), 3u);
  EXPECT_FALSE(f.has("/cutting/setup")) << "layout 3 has no positional set-up vector";
}

TEST_F(Provenance, TheTimeHistoryInResultsEqualsSeriesCsvAndTheSidecarGivesTheUnits) {
  ASSERT_EQ(run_->exit_code, 0) << run_->output;
  std::istringstream csv(test::read_file(out("series.csv")));
  std::string line;
  std::getline(csv, line);
  const auto head = split(line);
  std::vector<std::vector<double>> cols(head.size());
  while (std::getline(csv, line)) {
    const auto v = split(line);
    ASSERT_EQ(v.size(), head.size());
    for (std::size_t k = 0; k < v.size(); ++k) cols[k].push_back(std::stod(v[k]));
  }
  ASSERT_GT(cols[0].size(), 10u);
  H5File f(out("results.h5"), H5File::Mode::Read);
  for (std::size_t k = 0; k < head.size(); ++k) {
    std::size_t r = 0, c = 0;
    // (the CSV writes the shortest text that reads back exactly, so equality is exact)
    EXPECT_EQ(f.read_doubles("/series/" + head[k], r, c), cols[k]) << head[k];
  }
  // series_columns.csv: one row per column of series.csv, in its order, with the unit.
  std::istringstream side(test::read_file(out("series_columns.csv")));
  std::getline(side, line);
  EXPECT_EQ(line, "column,unit,meaning");
  std::size_t k = 0;
  std::map<std::string, std::string> unit;
  while (std::getline(side, line)) {
    const auto v = split(line);
    ASSERT_GE(v.size(), 3u) << line;
    ASSERT_LT(k, head.size());
    EXPECT_EQ(v[0], head[k++]);
    unit[v[0]] = v[1];
  }
  EXPECT_EQ(k, head.size());
  EXPECT_EQ(unit["time"], "\"s\"");
  EXPECT_EQ(unit["cutting_force_per_width"], "\"N/m\"");
  EXPECT_EQ(unit["reaction_base_z"], "\"N\"");
  EXPECT_EQ(unit["broken_fraction"], "\"1\"");
}

TEST_F(Provenance, GroupNamesAreStoredWithTheIndices) {
  ASSERT_EQ(run_->exit_code, 0) << run_->output;
  H5File f(out("results.h5"), H5File::Mode::Read);
  ASSERT_TRUE(f.has("/groups/name"));
  std::size_t r = 0, c = 0;
  const auto g = f.read_ints("/particles/group", r, c);
  bool base = false;
  for (auto v : g) {
    EXPECT_TRUE(v == -1 || v == 0) << v;
    base = base || v == 0;
  }
  EXPECT_TRUE(base);
}

TEST_F(Provenance, SummaryResultsAndVersionNameTheSameBuild) {
  ASSERT_EQ(run_->exit_code, 0) << run_->output;
  const auto sum = nlohmann::json::parse(test::read_file(out("summary.json")));
  ASSERT_TRUE(sum.contains("provenance")) << sum.dump();
  const auto& p = sum["provenance"];
  const std::string commit = p["git_commit"];
  EXPECT_TRUE(std::regex_match(commit, std::regex("[0-9a-f]{40}")) || commit == "unknown") << commit;
  EXPECT_TRUE(std::regex_match(p["started_utc"].get<std::string>(),
                               std::regex("[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}Z")));
  EXPECT_EQ(p["threads"], 2);
  EXPECT_FALSE(p["host"].get<std::string>().empty());
  EXPECT_FALSE(p["compiler"].get<std::string>().empty());
  EXPECT_FALSE(p["build_type"].get<std::string>().empty());
  H5File f(out("results.h5"), H5File::Mode::Read);
  EXPECT_EQ(f.read_string_attribute("git_commit"), commit);
  EXPECT_EQ(f.read_string_attribute("started_utc"), p["started_utc"].get<std::string>());
  EXPECT_EQ(f.read_double_attribute("threads"), 2.0);
  const auto v = test::run_command(std::string(SWARF_BINARY) + " --version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_NE(v.output.find("commit " + commit), std::string::npos) << v.output;
  EXPECT_NE(v.output.find(p["compiler"].get<std::string>()), std::string::npos) << v.output;
}

TEST_F(Provenance, RunLogHoldsWhatTheRunPrinted) {
  ASSERT_EQ(run_->exit_code, 0) << run_->output;
  const std::string log = test::read_file(out("run.log"));
  EXPECT_EQ(log.rfind("swarf ", 0), 0u) << log.substr(0, 200);  // the set-up, printed before the directory existed
  EXPECT_NE(log.find("stable step"), std::string::npos);
  EXPECT_NE(log.find("outputs in"), std::string::npos);
  EXPECT_NE(log.find("100.0%"), std::string::npos) << "the final progress line";
}

TEST_F(Provenance, TheEffectiveCaseListsTheDefaultsTheFileLeftOut) {
  ASSERT_EQ(run_->exit_code, 0) << run_->output;
  const auto sum = nlohmann::json::parse(test::read_file(out("summary.json")));
  const auto& e = sum["case_effective"];
  EXPECT_FALSE(sum["case"]["integrator"].contains("dt_safety"));
  ASSERT_TRUE(e["integrator"].contains("dt_safety")) << e.dump();
  EXPECT_GT(e["integrator"]["dt_safety"].get<double>(), 0.0);
  EXPECT_EQ(e["integrator"]["end_time"], 2e-5);  // (an override)
  EXPECT_EQ(e["contact"]["friction"], 0.3);
  EXPECT_TRUE(e["contact"].contains("restitution"));
  EXPECT_EQ(e["mesh"][0]["rake_angle"], 10.0);
  EXPECT_EQ(e["mesh"][0]["motion"], "velocity");
  EXPECT_EQ(e["group"][0]["name"], "base");
  EXPECT_TRUE(e["rod"].contains("youngs_modulus"));
}

}  // namespace
}  // namespace swarf

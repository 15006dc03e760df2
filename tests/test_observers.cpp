// test_observers.cpp: the run's observers (app/observers/): the series laid out by name, each
// observer's state under its own name in the checkpoint, a uniaxial run (whose prediction
// carries a plastic shift from step to step) continued bit-identically from a checkpoint, and
// older checkpoint layouts refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/observers/case_observers.h"
#include "app/observers/observer_set.h"
#include "app/observers/prefixed_archive.h"
#include "app/series_columns.h"
#include "io/h5file.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/simulation.h"
#include "test_helpers.h"

namespace swarf {
namespace {

// A small bar along y between two grips, pulled past yield and back: 96 particles, explicit steps.
const char* kBar = R"([workpiece]
cells = [2, 6, 2]
radius = 0.5e-3
[rod]
youngs_modulus = 200e9
yield_strain = 1e-3
hardening_modulus = 20e9
damping_ratio = 0.1
[uniaxial]
axis = "y"
strain_path = [0.0, 0.01, -0.004]
strain_rate = 100.0
[output]
plots = false
vtk = false
)";

TEST(Observers, LayTheSeriesOutByNameTimeFirst) {
  Model m = build_model(parse_case(kBar, "bar", {}));
  Simulation sim(m, m.step);
  ObserverSet observers(sim, observers_for(m));
  const std::vector<std::string> expected{"time",
                                          "strain",
                                          "stress",
                                          "stress_predicted",
                                          "stress_midplane",
                                          "step",
                                          "dt",
                                          "iterations",
                                          "kinetic_energy",
                                          "rotational_energy",
                                          "elastic_energy",
                                          "contact_energy",
                                          "contact_work",
                                          "potential_energy",
                                          "external_work",
                                          "plastic_work",
                                          "viscous_work",
                                          "fracture_energy",
                                          "energy_error",
                                          "broken_rods",
                                          "broken_fraction",
                                          "contacts",
                                          "reaction_grip_min_x",
                                          "reaction_grip_min_y",
                                          "reaction_grip_min_z",
                                          "reaction_grip_max_x",
                                          "reaction_grip_max_y",
                                          "reaction_grip_max_z"};
  EXPECT_EQ(observers.columns(), expected);
  observers.begin();
  for (int s = 0; s < 20; ++s) sim.step();
  const std::vector<double> row = observers.row();
  ASSERT_EQ(row.size(), expected.size());
  EXPECT_EQ(row[0], sim.time());
  EXPECT_EQ(row[5], 20.0);  // step
  EXPECT_TRUE(observers.has("uniaxial") && observers.has("energy") && !observers.has("cut"));
  // The series is read back by name, whatever the place of the column.
  const SeriesColumns series(expected, row);
  EXPECT_EQ(series["step"], std::vector<double>{20.0});
  EXPECT_EQ(series.rows(), 1u);
  EXPECT_THROW(series["no_such_column"], std::logic_error);
}

// An observer that counts the steps it sees, to show when it is registered.
struct StepCounting final : Observer, StepListener {
  explicit StepCounting(int& seen) : seen(seen) {}
  std::string_view name() const override { return "counting"; }
  void columns(std::vector<Column>& out) const override { out.push_back({"seen", "1", "steps seen"}); }
  void row(const Simulation&, std::vector<double>& values) override { values.push_back(seen); }
  StepListener* step_listener() override { return this; }
  void after_step(Simulation&) override { ++seen; }
  int& seen;
};

TEST(Observers, WatchEveryStepOnlyWhileTheirSetLives) {
  Model m = build_model(parse_case(kBar, "bar", {}));
  Simulation sim(m, m.step);
  int seen = 0;
  {
    std::vector<std::unique_ptr<Observer>> v;
    v.push_back(std::make_unique<StepCounting>(seen));
    ObserverSet observers(sim, std::move(v));
    for (int s = 0; s < 3; ++s) sim.step();
    EXPECT_EQ(observers.row().back(), 3.0);
  }
  sim.step();  // the set is gone: nothing calls into it
  EXPECT_EQ(seen, 3);
  // Two observers of one name would share a checkpoint group.
  int other = 0;
  std::vector<std::unique_ptr<Observer>> twins;
  twins.push_back(std::make_unique<StepCounting>(seen));
  twins.push_back(std::make_unique<StepCounting>(other));
  EXPECT_THROW(ObserverSet(sim, std::move(twins)), std::logic_error);
}

TEST(Observers, KeepTheirStateUnderTheirOwnNames) {
  // A prefixed archive files a field as prefix + name: the same hash as naming it so directly.
  double x = 1.5;
  std::int64_t n = 7;
  HashArchive direct, through;
  direct.scalar("uniaxial/x", x);
  direct.scalar("uniaxial/n", n);
  PrefixedArchive prefixed(through, "uniaxial/");
  prefixed.scalar("x", x);
  prefixed.scalar("n", n);
  EXPECT_EQ(direct.value(), through.value());
  EXPECT_FALSE(prefixed.loading());
}

// Runs DIR/bar.toml into DIR/a with a checkpoint every 2000 steps (past yield, and on the way
// back) and copies the last checkpoint into DIR/b.
test::CommandResult run_bar_with_checkpoints(const test::TempDir& dir) {
  test::write_file(dir / "bar.toml", kBar);
  auto a = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "bar.toml") + " --out " + (dir / "a") +
                             " --set output.checkpoint_every=2000 --threads 1");
  if (a.exit_code == 0) {
    std::filesystem::create_directories(dir / "b");
    std::filesystem::copy_file(dir / "a/checkpoint.h5", dir / "b/checkpoint.h5");
  }
  return a;
}

TEST(Restart, UniaxialRunContinuesBitIdenticallyWithItsPredictionAndLoop) {
  test::TempDir dir("restart_bar");
  auto a = run_bar_with_checkpoints(dir);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  {
    // Each part of the run's state is a named dataset: the loop's, and each observer's.
    H5File ck(dir / "b/checkpoint.h5", H5File::Mode::Read);
    for (const char* name : {"/run/loop/series_rows", "/run/loop/next_row_s", "/run/energy/initial_energy_J",
                             "/run/uniaxial/stress_predicted_Pa", "/run/uniaxial/prediction_plastic_shift"})
      EXPECT_TRUE(ck.has(name)) << name;
    EXPECT_FALSE(ck.has("/run/scalars"));
    std::size_t r = 0, c = 0;
    EXPECT_NE(ck.read_doubles("/run/uniaxial/prediction_plastic_shift", r, c).at(0), 0.0)
        << "the checkpoint is past yield: the prediction's plastic shift crosses the restart";
  }
  auto b = test::run_command(std::string(SWARF_BINARY) + " run --restart " + (dir / "b/checkpoint.h5") + " --threads 2");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_EQ(test::read_file(dir / "a/series.csv"), test::read_file(dir / "b/series.csv"));
  const auto sa = nlohmann::json::parse(test::read_file(dir / "a/summary.json"));
  const auto sb = nlohmann::json::parse(test::read_file(dir / "b/summary.json"));
  EXPECT_EQ(sa["state_hash"], sb["state_hash"]);
  EXPECT_EQ(sa["results"], sb["results"]);
  ASSERT_TRUE(sa["uniaxial"].contains("measured")) << sa["uniaxial"].dump(2);
  EXPECT_EQ(sa["uniaxial"], sb["uniaxial"]);  // the loop from all rows, before the restart and after
}

TEST(Restart, RefusesACheckpointOfAnOlderLayout) {
  test::TempDir dir("restart_layout");
  {
    H5File f(dir / "old.h5", H5File::Mode::Create);  // as swarf wrote them with /run/scalars
    f.write_attribute("format", 2.0);
    f.write_attribute("case_toml", std::string(kBar));
  }
  auto r = test::run_command(std::string(SWARF_BINARY) + " run --restart " + (dir / "old.h5"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("has layout 2 (this swarf reads 3)"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace swarf

// test_result_keys.cpp: the units of summary.json's results are declared in one table
// (src/setup/result_keys.cpp), which the study table reads instead of parsing the key names:
// every number that short runs put into the tabulated sections is declared, and a key no entry
// declares is marked "?" rather than guessed from its name.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenes/tiny_cut.h"
#include "scenes/tiny_uniaxial.h"
#include "setup/result_keys.h"
#include "study/study.h"
#include "study/study_record.h"
#include "study/study_table.h"
#include "test_helpers.h"

namespace swarf {
namespace {

TEST(StudyTable, ResultUnitsComeFromTheTable) {
  EXPECT_EQ(unit_of_key("cutting.cutting_force_per_width_mean_N_per_m"), "N/m");
  EXPECT_EQ(unit_of_key("results.reaction_grip_N.x"), "N") << "a group's name, a vector's component";
  EXPECT_EQ(unit_of_key("uniaxial.deviation_percent.yield_stress"), "%");
  EXPECT_EQ(unit_of_key("run.ns_per_particle_step"), "ns") << "a unit no suffix spelt";
  EXPECT_EQ(unit_of_key("results.some_new_number_m"), "?") << "undeclared: not guessed from the name";
  EXPECT_EQ(unit_of_key("results.reaction_grip_N.x.y"), "N");
  EXPECT_EQ(find_result_key("results.reaction_grip.x"), nullptr) << "'*' does not stand for the unit";
  EXPECT_EQ(ci95_key_of("chip.shear_angle_deg"), "chip.shear_angle_ci95_deg");
  EXPECT_EQ(ci95_key_of("chip.thickness_p10_m"), "") << "no interval declared";
}

// Short runs of each kind (a cut with Newton's solver and heat, which adds the chip, the
// temperatures and the solver's counts; a uniaxial loop), tabulated as a study of two cases: every metric
// column of study.csv and timing.csv has a declared unit.
TEST(StudyTable, EveryResultOfARunIsDeclared) {
  test::TempDir dir("result_keys");
  test::write_file(dir / "cut.toml", test::kTinyCut);
  test::write_file(dir / "bar.toml", test::kTinyUniaxial);
  const std::string bin = std::string(SWARF_BINARY) + " run ";
  const auto cut = test::run_command(bin + (dir / "cut.toml") + " --out " + (dir / "cut") +
                                     " --set integrator.solver=newton --set integrator.end_time=2e-5"
                                     " --set output.steady_from=1e-5"
                                     " --set heat.heat_capacity=486 --set heat.conductivity=50.7");
  ASSERT_EQ(cut.exit_code, 0) << cut.output;
  const auto bar = test::run_command(bin + (dir / "bar.toml") + " --out " + (dir / "bar") +
                                     " --set output.vtk=false --set output.plots=false");
  ASSERT_EQ(bar.exit_code, 0) << bar.output;
  // The two summaries as the cases of a study (case_status wants the case's own overrides).
  const Study study = parse_study("base = \"c.toml\"\n[grid]\nrod.damping_ratio = [0.1, 0.2]\n", "s.toml", dir.str());
  const std::string out = dir / "study";
  for (std::size_t k = 0; k < 2; ++k) {
    auto sum = nlohmann::json::parse(test::read_file(dir / (k == 0 ? "cut/summary.json" : "bar/summary.json")));
    sum["overrides"] = case_overrides(study, study.cases[k]);
    std::filesystem::create_directories(case_dir(out, study.cases[k]));
    test::write_file(case_dir(out, study.cases[k]) + "/summary.json", sum.dump());
  }
  std::vector<std::string> columns;
  for (const bool timing : {false, true}) {
    const StudyTable t = collect_table(study, out, timing);
    for (std::size_t c = t.first_metric; c < t.columns.size(); ++c) {
      columns.push_back(t.columns[c]);
      EXPECT_NE(t.units[c], "?") << t.columns[c] << " is not in result_keys.cpp";
    }
  }
  EXPECT_GE(columns.size(), 80u);
  for (const char* key : {"run.newton_solves", "chip.friction_angle_deg", "uniaxial.measured.youngs_modulus_Pa",
                          "results.reaction_base_N.x", "run.ns_per_particle_step", "heat.heat_plastic_J",
                          "chip.contact_length_m", "chip.rake_face_temperature_K"})
    EXPECT_NE(std::find(columns.begin(), columns.end(), key), columns.end()) << key << ": the runs did not reach it";
}

}  // namespace
}  // namespace swarf

// test_case_files.cpp: bad case files are rejected with the file, the key and the value
// named; overrides are checked like keys in the file; the CLI exits non-zero.
#include <gtest/gtest.h>

#include "case_errors.h"
#include "io/csv_cell.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "test_helpers.h"

namespace swarf {
namespace {

const std::string kGood = R"([workpiece]
cells = [4, 2, 2]
radius = 0.5e-3

[rod]
youngs_modulus = 200e9
yield_strain = 1e-3

[integrator]
end_time = 1e-5

[[group]]
name = "left"
side = "x-"
)";

using test::case_error;
using test::expect_mentions;

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

TEST(CaseFiles, GoodCaseParses) { EXPECT_EQ(case_error(kGood), ""); }

TEST(CaseFiles, UnknownKey) {
  expect_mentions(case_error(replace(kGood, "yield_strain", "yeild_strain")),
                  {"bad.toml:7", "unknown key", "rod.yeild_strain"});
}

TEST(CaseFiles, UnknownTable) { expect_mentions(case_error(kGood + "\n[solver]\nx = 1\n"), {"bad.toml", "solver"}); }

TEST(CaseFiles, WrongType) {
  expect_mentions(case_error(replace(kGood, "radius = 0.5e-3", "radius = \"big\"")),
                  {"bad.toml:3", "workpiece.radius", "\"big\"", "number"});
}

TEST(CaseFiles, NegativeRadius) {
  expect_mentions(case_error(replace(kGood, "radius = 0.5e-3", "radius = -0.5e-3")),
                  {"bad.toml:3", "workpiece.radius", "-0.0005", "positive"});
}

TEST(CaseFiles, HardeningNotBelowModulus) {
  expect_mentions(case_error(replace(kGood, "yield_strain = 1e-3", "yield_strain = 1e-3\nhardening_modulus = 3e11")),
                  {"rod.hardening_modulus", "300000000000", "below"});
}

TEST(CaseFiles, HardeningCurveAndFailureStrainReachTheRodLaw) {
  const std::string curve = replace(kGood, "yield_strain = 1e-3",
                                    "flow_plastic_strain = [0.0, 0.01, 0.1]\nflow_stress = [200e6, 300e6, 350e6]\n"
                                    "failure_strain = 0.5");
  ASSERT_EQ(case_error(curve), "");
  const Model m = build_model(parse_case(curve, "curve.toml", {}));
  const RodLaw& law = std::get<RodLaw>(m.derived.law);
  EXPECT_EQ(law.flow.points, 3);
  EXPECT_EQ(law.flow.plastic_strain[1], 0.01);
  EXPECT_EQ(law.flow.stress[2], 350e6);
  EXPECT_DOUBLE_EQ(law.yield_strain, 200e6 / 200e9);
  EXPECT_EQ(law.hardening, 0.0);
  EXPECT_EQ(law.failure_strain, 0.5);
  // Rods that can break no longer make "auto" the Newmark step (it costs 2.3-4.2 times Verlet on
  // the cut, validation/integrators/README.md); the Newton solver does, and "newmark" named does.
  EXPECT_FALSE(m.derived.implicit);
  EXPECT_TRUE(build_model(parse_case(curve, "curve.toml", {"integrator.solver=\"newton\""})).derived.implicit);
  EXPECT_TRUE(build_model(parse_case(curve, "curve.toml", {"integrator.scheme=\"newmark\""})).derived.implicit);
  EXPECT_FALSE(build_model(parse_case(curve, "curve.toml", {"integrator.scheme=\"verlet\""})).derived.implicit);
  EXPECT_EQ(std::get<RodLaw>(m.rods.law).flow.points, 3);
  // The rules between the keys.
  expect_mentions(case_error(replace(curve, "flow_stress = [200e6, 300e6, 350e6]\n", "")),
                  {"rod.flow_plastic_strain", "both"});
  expect_mentions(case_error(replace(curve, "[0.0, 0.01, 0.1]", "[0.001, 0.01, 0.1]")), {"first point must be 0"});
  expect_mentions(case_error(replace(curve, "[0.0, 0.01, 0.1]", "[0.0, 0.1, 0.01]")), {"strictly increasing"});
  expect_mentions(case_error(replace(curve, "[200e6, 300e6, 350e6]", "[200e6, 300e6]")), {"rod.flow_stress", "3"});
  expect_mentions(case_error(replace(curve, "[200e6, 300e6, 350e6]", "[200e6, 300e6, 250e6]")), {"must not decrease"});
  expect_mentions(case_error(replace(curve, "failure_strain = 0.5", "failure_strain = 0.5\nyield_strain = 1e-3")),
                  {"rod.yield_strain", "replaces"});
  expect_mentions(case_error(replace(curve, "[rod]", "[material]\nyoungs_modulus = 200e9\n[rod]")), {"[material]"});
}

TEST(CaseFiles, MissingLatticeFile) {
  expect_mentions(case_error(replace(kGood, "cells = [4, 2, 2]\nradius = 0.5e-3", "lattice_file = \"nope.h5\"")),
                  {"workpiece.lattice_file", "nope.h5", "not found"});
}

TEST(CaseFiles, LatticeFileAndCellsTogether) {
  expect_mentions(case_error(replace(kGood, "radius = 0.5e-3", "lattice_file = \"x.h5\"")), {"lattice_file", "either"});
}

TEST(CaseFiles, RadiusWithLatticeFile) {
  test::TempDir dir("case_lat");
  test::write_file(dir / "x.h5", "");
  const std::string text = replace(kGood, "cells = [4, 2, 2]", "lattice_file = \"" + (dir / "x.h5") + "\"");
  expect_mentions(case_error(text), {"bad.toml:3", "workpiece.radius", "lattice_file"});
}

TEST(CaseFiles, IgnoredKeyCombinationsRejected) {
  expect_mentions(case_error(replace(kGood, "side = \"x-\"", "side = \"x-\"\nvelocity = [1.0, 0.0, 0.0]")),
                  {"group.velocity", "not used with motion = \"fixed\""});
  expect_mentions(case_error(replace(kGood, "side = \"x-\"", "side = \"x-\"\nbox_max = [1.0, 1.0, 1.0]")),
                  {"group.box_max", "either"});
}

TEST(CaseFiles, UnstableStepRefused) {
  // The stable step of this lattice is about 1.2e-7 s.
  expect_mentions(case_error(replace(kGood, "end_time = 1e-5", "end_time = 1e-5\ndt = 1e-6")),
                  {"integrator.dt", "stable step", "allow_unstable_dt"});
  EXPECT_EQ(case_error(replace(kGood, "end_time = 1e-5", "end_time = 1e-5\ndt = 1e-6\nallow_unstable_dt = true")), "");
}

TEST(CaseFiles, MissingEndTime) {
  expect_mentions(case_error(replace(kGood, "end_time = 1e-5", "")), {"integrator.end_time"});
}

TEST(CaseFiles, SyntaxErrorNamesLine) {
  expect_mentions(case_error(replace(kGood, "radius = 0.5e-3", "radius = = 0.5e-3")), {"bad.toml:3", "syntax"});
}

TEST(CaseFiles, BadEnumValue) {
  expect_mentions(case_error(replace(kGood, "side = \"x-\"", "side = \"left\"")), {"group.side", "\"left\"", "x-"});
}

TEST(CaseFiles, NewmarkOptionsChecked) {
  EXPECT_EQ(case_error(replace(kGood, "end_time = 1e-5", "end_time = 1e-5\nscheme = \"newmark\"")), "");
  expect_mentions(case_error(replace(kGood, "end_time = 1e-5", "end_time = 1e-5\nscheme = \"newmark\"\nbeta = 0.7")),
                  {"integrator.beta", "0.7", "(0, 0.5]"});
  expect_mentions(case_error(replace(kGood, "end_time = 1e-5", "end_time = 1e-5\ndt_min = 1e-6\ndt_max = 1e-7")),
                  {"integrator.dt_min", "dt_max"});
  expect_mentions(case_error(replace(kGood, "end_time = 1e-5", "end_time = 1e-5\niterations_grow = 12")),
                  {"integrator.iterations_grow", "iterations_shrink"});
  // A first step outside [dt_min, dt_max] of the implicit scheme is named.
  expect_mentions(case_error(replace(kGood, "end_time = 1e-5", "end_time = 1e-5\nscheme = \"newmark\"\ndt = 1e-3")),
                  {"integrator.dt", "dt_max"});
}

TEST(CaseFiles, EmptyGroup) {
  expect_mentions(case_error(replace(kGood, "side = \"x-\"", "box_min = [1.0, 1.0, 1.0]")), {"left", "no particle"});
}

TEST(CaseFiles, OverridesApplyAndAreChecked) {
  const CaseSettings cs = parse_case(
      kGood, "bad.toml",
      {"integrator.dt=2e-9", "group.0.motion=velocity", "group.0.velocity=[1, 2, 3]", "rod.damping_ratio=0.1"});
  EXPECT_EQ(cs.integrator.dt, 2e-9);
  EXPECT_EQ(cs.groups[0].motion.kind, "velocity");
  EXPECT_EQ(cs.groups[0].motion.velocity[2], 3.0);
  EXPECT_EQ(cs.rod.damping_ratio, 0.1);
  expect_mentions(case_error(kGood, {"rod.yield_strain=-1"}),
                  {"--set rod.yield_strain", "-1", "must lie in (0, 100], or be inf"});
  expect_mentions(case_error(kGood, {"rod.yeild=1"}), {"--set rod.yeild", "unknown key"});
  expect_mentions(case_error(kGood, {"nonsense"}), {"--set", "nonsense", "key=value"});
  expect_mentions(case_error(kGood, {"group.5.x=1"}), {"--set", "group.5.x"});
  // One entry of an array: its index as the last component; the others stay.
  const CaseSettings one = parse_case(
      kGood, "bad.toml", {"group.0.motion=velocity", "group.0.velocity=[1, 2, 3]", "group.0.velocity.2=-4.5"});
  EXPECT_EQ(one.groups[0].motion.velocity[0], 1.0);
  EXPECT_EQ(one.groups[0].motion.velocity[1], 2.0);
  EXPECT_EQ(one.groups[0].motion.velocity[2], -4.5);
  expect_mentions(case_error(kGood, {"group.0.motion=velocity", "group.0.velocity=[1, 2, 3]", "group.0.velocity.3=1"}),
                  {"--set", "group.0.velocity.3", "'3' is not an index", "3 entries"});
  expect_mentions(
      case_error(kGood, {"group.0.motion=velocity", "group.0.velocity=[1, 2, 3]", "group.0.velocity.2=\"a\""}),
      {"group.velocity"});
}

// A velocity CSV's cells are numbers, whole: trailing junk, an empty cell, a fifth column or
// a fraction written wrong are refused with the file and line, not read as the number's start
// or as 0 (stream extraction stopped at the first character it could not use).
TEST(Motions, VelocityCsvRefusesBadCells) {
  test::TempDir dir("motions_csv");
  const std::string text = replace(kGood, "side = \"x-\"",
                                   "side = \"x-\"\nmotion = \"velocity_table\"\nvelocity_file = \"v.csv\"");
  const auto error = [&] {
    try {
      parse_case(text, "c.toml", {}, dir.str());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  for (const char* row : {"1e-3,2.0,0,0abc", "1e-3,2.0,,0", "1e-3,2.0,0,0,5", "1e-3,2..0,0,0", "1e-3,2.0,0"}) {
    test::write_file(dir / "v.csv", std::string("time,vx,vy,vz\n0,0,0,0\n") + row + "\n");
    expect_mentions(error(), {"velocity_file", "v.csv:3", "four finite numbers", row});
  }
  test::write_file(dir / "v.csv", "time,vx,vy,vz\r\n0,0,0,0\r\n1e-3, 2.0 ,0,0\r\n");  // (spaces and CRLF are fine)
  EXPECT_EQ(error(), "");
}

TEST(CsvCell, ReadsTheWholeCellOrNothing) {
  double v = -1;
  EXPECT_TRUE(parse_csv_number(" 2.5e-3\r", v));
  EXPECT_EQ(v, 2.5e-3);
  EXPECT_TRUE(parse_csv_number("nan", v));
  EXPECT_TRUE(std::isnan(v));
  for (const char* bad : {"", " ", "3abc", "3.7.1", "abc", "1e", "--1"}) EXPECT_FALSE(parse_csv_number(bad, v)) << bad;
}

TEST(Motions, RampAndVelocityTableIntegrateExactly) {
  test::TempDir dir("motions");
  test::write_file(dir / "v.csv", "time,vx,vy,vz\n0,0,0,0\n1e-3,2.0,0,0\n3e-3,2.0,0,-1.0\n");
  const std::string text = replace(kGood, "side = \"x-\"", R"(side = "x-"
motion = "ramp"
velocity = [3.0, 0.0, 0.0]
ramp_time = 2e-3
[[group]]
name = "right"
side = "x+"
motion = "velocity_table"
velocity_file = "v.csv"
[[mesh]]
name = "m"
origin = [0.0, 0.0, 1.0]
edge1 = [1.0, 0.0, 0.0]
edge2 = [0.0, 1.0, 0.0]
motion = "velocity_table"
table_time = [0.0, 1e-3]
table_velocity = [[1.0, 0.0, 0.0], [3.0, 0.0, 0.0]]
[contact]
)");
  const Model m = build_model(parse_case(text, "motions", {}, dir.str()));
  // Ramp: u = v t^2 / (2 T) up to T, then v (t - T/2).
  EXPECT_NEAR(m.groups[0].motion.displacement_at(1e-3)[0], 3.0 * 1e-6 / 4e-3, 1e-15);
  EXPECT_NEAR(m.groups[0].motion.displacement_at(5e-3)[0], 3.0 * (5e-3 - 1e-3), 1e-15);
  // Velocity table from CSV: exact integral of the piecewise-linear velocity; the last velocity holds.
  const Vec3 u = m.groups[1].motion.displacement_at(2e-3);
  EXPECT_NEAR(u[0], 0.5 * 2.0 * 1e-3 + 2.0 * 1e-3, 1e-15);
  EXPECT_NEAR(u[2], -0.5 * 1.0 * 1e-3 * 0.5, 1e-15);  // vz ramps 0 -> -1 over 2 ms: at 1 ms in, -0.25 m/s mean
  EXPECT_NEAR(m.groups[1].motion.displacement_at(4e-3)[2], -1.0 * 2e-3 / 2 - 1.0 * 1e-3, 1e-15);
  // Inline velocity table on a mesh: 1 -> 3 m/s over 1 ms covers 2 mm.
  EXPECT_NEAR(m.mesh_motion[0].displacement_at(1e-3)[0], 2e-3, 1e-15);
  // Keys of another motion are refused, and a table must start at 0 s.
  expect_mentions(case_error(replace(kGood, "side = \"x-\"",
                                     "side = \"x-\"\nmotion = \"velocity\"\n"
                                     "velocity = [1.0, 0.0, 0.0]\nramp_time = 1e-3")),
                  {"group.ramp_time", "not used with motion = \"velocity\""});
  expect_mentions(case_error(replace(kGood, "side = \"x-\"",
                                     "side = \"x-\"\nmotion = \"velocity_table\"\n"
                                     "table_time = [1e-3, 2e-3]\n"
                                     "table_velocity = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]")),
                  {"group.table_time", "start at 0 s"});
}

TEST(CaseFiles, CliExitsWithTwoAndNamesTheProblem) {
  test::TempDir dir("case_cli");
  test::write_file(dir / "bad.toml", replace(kGood, "radius = 0.5e-3", "radius = -1.0"));
  auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "bad.toml") + " --out " + (dir / "out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("workpiece.radius"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.toml:3"), std::string::npos) << r.output;
  r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "missing.toml") + " --out " + (dir / "out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("missing.toml"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace swarf

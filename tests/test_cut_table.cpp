// test_cut_table.cpp: [cut], a cut in cutting terms (setup/cut_case.h). The built-in default
// cut written as a [cut] table must build the model of the hand-written default; what [cut]
// prints must read back as the same case; keys the case gives must win; bad [cut] keys are
// refused by name; 'swarf run --check' and 'swarf case default' do what they say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "case_errors.h"
#include "io/h5file.h"
#include "postprocess/cut_report.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/laws/johnson_cook_rod_law.h"
#include "test_helpers.h"

namespace swarf {
namespace {

const MeshSettings& tool_of(const CaseSettings& cs) {
  for (const auto& m : cs.meshes)
    if (m.tool) return m;
  throw std::runtime_error("no tool");
}

// 'swarf run' of the [cut] example coarsened to 5 layers across h (some 2000 particles: a second
// or two), on one thread and without plots, into 'out', with the further options 'sets'.
test::CommandResult run_coarse_cut(const std::string& out, const std::string& sets) {
  return test::run_command(fmt::format(
      "timeout 300 {} run {}/examples/cut_c45.toml --out {} --set cut.layers=5 --set output.plots=false --threads 1 {}",
      SWARF_BINARY, SWARF_SOURCE_DIR, out, sets));
}

// The hand-written default rounds R to six digits (1.41421e-5 m for 1.41421356e-5) and the
// flow curve to four (5e-4 of a value at most): positions, lengths and masses agree to 3e-6 and 8e-6 of themselves
// (2.5e-6 in R, three times that in a^3), the rods' flow stresses to 1.2e-3 (399.2 against
// 398.8 MPa). Everything that is counted or chosen (particles, rods, group members, the
// tool's angles and path, the time keys) must be equal.
TEST(CutTable, TheDefaultCutAsACutTableBuildsTheDefaultModel) {
  const CaseSettings hand = parse_case(kDefaultCaseToml, "default", {});
  const CaseSettings cut = parse_case(kDefaultCutTableToml, "cut", {});
  ASSERT_TRUE(cut.cut.enabled);
  ASSERT_FALSE(hand.cut.enabled);
  const Model a = build_model(hand), b = build_model(cut);

  ASSERT_EQ(a.particles.size(), b.particles.size());
  const double size = 3.6e-3;  // m, the block's largest extent
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    ASSERT_NEAR(a.particles.position[i].x(), b.particles.position[i].x(), 3e-6 * size) << i;
    ASSERT_NEAR(a.particles.position[i].y(), b.particles.position[i].y(), 3e-6 * size) << i;
    ASSERT_NEAR(a.particles.position[i].z(), b.particles.position[i].z(), 3e-6 * size) << i;
    ASSERT_NEAR(a.particles.radius[i], b.particles.radius[i], 3e-6 * a.particles.radius[i]);
    ASSERT_NEAR(a.particles.mass[i], b.particles.mass[i], 8e-6 * a.particles.mass[i]);
  }
  ASSERT_EQ(a.rods.ends, b.rods.ends);
  for (std::size_t k = 0; k < a.rods.size(); ++k)
    ASSERT_NEAR(a.rods.rest_length[k], b.rods.rest_length[k], 3e-6 * a.rods.rest_length[k]);

  // Both on Johnson-Cook rods: the hand-written file gives C, m, T_melt and the reference rate
  // as a rod strain rate (0.333333 1/s: six digits of 1/3), the preset as an equivalent plastic
  // strain rate (1 1/s) with kappa = 3 (calibrated in tension); the rates they mean agree to 1e-6.
  const auto &ja = std::get<JohnsonCookRodLaw>(a.rods.law), &jb = std::get<JohnsonCookRodLaw>(b.rods.law);
  EXPECT_EQ(ja.rate_sensitivity, jb.rate_sensitivity);
  EXPECT_EQ(ja.softening_exponent, jb.softening_exponent);
  EXPECT_EQ(ja.melt_temperature, jb.melt_temperature);
  EXPECT_EQ(ja.reference_temperature, jb.reference_temperature);
  const double rate_a = ja.reference_rate / ja.rate_to_equivalent, rate_b = jb.reference_rate / jb.rate_to_equivalent;
  EXPECT_NEAR(rate_a, rate_b, 1.5e-6 * rate_b);
  const RodLaw &la = ja.base, &lb = jb.base;
  EXPECT_NEAR(la.youngs_modulus, lb.youngs_modulus, 1e-4 * la.youngs_modulus);
  EXPECT_EQ(la.failure_strain, lb.failure_strain);
  EXPECT_NEAR(la.viscosity, lb.viscosity, 1e-4 * la.viscosity);
  ASSERT_EQ(la.flow.points, lb.flow.points);
  for (int p = 0; p < la.flow.points; ++p) {
    EXPECT_NEAR(la.flow.plastic_strain[p], lb.flow.plastic_strain[p], 5e-4 * la.flow.plastic_strain[p]);
    EXPECT_NEAR(la.flow.stress[p], lb.flow.stress[p], 1.2e-3 * la.flow.stress[p]);
  }
  EXPECT_EQ(hand.rod.bond_overlap, cut.rod.bond_overlap);
  EXPECT_EQ(hand.rod.neighbour_exchange, cut.rod.neighbour_exchange);
  EXPECT_EQ(hand.material.density, cut.material.density);

  ASSERT_EQ(a.groups.size(), b.groups.size());
  for (std::size_t g = 0; g < a.groups.size(); ++g) {
    EXPECT_EQ(a.groups[g].name, b.groups[g].name);
    EXPECT_EQ(a.groups[g].members, b.groups[g].members) << a.groups[g].name;
    EXPECT_EQ(a.groups[g].dofs, b.groups[g].dofs);
  }
  EXPECT_EQ(a.periodic.on(), b.periodic.on());

  // The tool: the same angles, edge, faces, tip in the x-z plane and path. Its width and its
  // place along y differ (the hand-written tool spans the period with its own margin); along
  // the edge a plane-strain tool only has to cover the period.
  const MeshSettings &ta = tool_of(hand), &tb = tool_of(cut);
  EXPECT_EQ(ta.rake_angle, tb.rake_angle);
  EXPECT_EQ(ta.clearance_angle, tb.clearance_angle);
  EXPECT_EQ(ta.edge_radius, tb.edge_radius);
  EXPECT_EQ(ta.face_length, tb.face_length);
  EXPECT_NEAR(ta.origin[0], tb.origin[0], 1e-15);
  EXPECT_NEAR(ta.origin[2], tb.origin[2], 3e-6 * size);
  EXPECT_EQ(ta.motion.kind, tb.motion.kind);
  EXPECT_EQ(ta.motion.velocity, tb.motion.velocity);
  const double period = b.periodic.period;
  EXPECT_LE(tb.origin[1] - 0.5 * tb.width, 0.0);
  EXPECT_GE(tb.origin[1] + 0.5 * tb.width, period);

  EXPECT_EQ(hand.contact.youngs_modulus, cut.contact.youngs_modulus);
  EXPECT_EQ(hand.contact.poisson_ratio, cut.contact.poisson_ratio);
  EXPECT_EQ(hand.contact.restitution, cut.contact.restitution);
  EXPECT_EQ(hand.contact.friction, cut.contact.friction);
  // Sticking: k0 666.2 MPa by hand (four digits), (A + B)/sqrt 3 = 666.204 MPa from the preset.
  EXPECT_TRUE(hand.contact.sticking && cut.contact.sticking);
  EXPECT_NEAR(hand.contact.sticking_shear_strength, cut.contact.sticking_shear_strength, 1e-5 * 666e6);
  EXPECT_EQ(hand.contact.sticking_softening_exponent, cut.contact.sticking_softening_exponent);
  EXPECT_EQ(hand.contact.sticking_melt_temperature, cut.contact.sticking_melt_temperature);
  // Heat: the same c, k and clamps (the hand-written values are the preset's).
  EXPECT_TRUE(hand.heat.present && cut.heat.present);
  EXPECT_EQ(hand.heat.heat_capacity, cut.heat.heat_capacity);
  EXPECT_EQ(hand.heat.conductivity, cut.heat.conductivity);
  EXPECT_EQ(hand.heat.held_groups, cut.heat.held_groups);
  EXPECT_EQ(hand.integrator.scheme, cut.integrator.scheme);
  EXPECT_EQ(hand.integrator.dt_safety, cut.integrator.dt_safety);
  for (auto [x, y] : {std::pair{hand.integrator.end_time, cut.integrator.end_time},
                      std::pair{hand.output.steady_from, cut.output.steady_from},
                      std::pair{hand.output.frame_interval, cut.output.frame_interval},
                      std::pair{hand.output.series_interval, cut.output.series_interval}})
    EXPECT_NEAR(x, y, 1e-12 * x);
  EXPECT_NEAR(a.step.dt, b.step.dt, 1e-5 * a.step.dt);
}

// What [cut] prints is a case file: read back (without [cut]), it builds the same model, bit
// for bit (the printed numbers are the shortest exact form of the derived ones).
TEST(CutTable, ThePrintedDerivationReadsBackAsTheSameCase) {
  const std::string text =
      "[cut]\nuncut_chip_thickness = 0.1e-3\ncutting_speed = 2.0\nrake_angle = -5.0\nedge_radius = 5e-6\n"
      "material = \"Al2024-T351\"\nlayers = 6\nwidth = 0.3e-3\n";
  const CaseSettings cut = parse_case(text, "cut", {});
  ASSERT_FALSE(cut.cut_derived.empty());
  const CaseSettings again = parse_case(cut.cut_derived, "printed", {});
  EXPECT_FALSE(again.cut.enabled);
  const Model a = build_model(cut), b = build_model(again);
  ASSERT_EQ(a.particles.size(), b.particles.size());
  EXPECT_EQ(a.particles.position, b.particles.position);
  EXPECT_EQ(a.rods.ends, b.rods.ends);
  ASSERT_EQ(a.groups.size(), b.groups.size());
  for (std::size_t g = 0; g < a.groups.size(); ++g) EXPECT_EQ(a.groups[g].members, b.groups[g].members);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  EXPECT_EQ(a.meshes[0].mesh.vertices, b.meshes[0].mesh.vertices);
  EXPECT_EQ(cut.integrator.end_time, again.integrator.end_time);
  EXPECT_EQ(cut.output.steady_from, again.output.steady_from);
  // The derivation itself: R = h / (6 sqrt 2), free sides, the tip h below the top centres
  // and h/4 before the block, end time = length of cut (10 h) / v_c.
  const double h = 0.1e-3, R = h / (6 * std::sqrt(2.0)), s = std::sqrt(2.0) * R;
  EXPECT_DOUBLE_EQ(cut.workpiece.radius, R);
  EXPECT_FALSE(cut.workpiece.periodic_width);
  EXPECT_EQ(cut.workpiece.cells[1], static_cast<int>(std::lround(0.3e-3 / (2 * s))));
  const MeshSettings& t = tool_of(cut);
  EXPECT_DOUBLE_EQ(t.origin[2], (2 * cut.workpiece.cells[2] - 1) * s - h);
  EXPECT_DOUBLE_EQ(t.origin[0], -0.25 * h);
  EXPECT_DOUBLE_EQ(cut.integrator.end_time, 10 * h / 2.0);
  EXPECT_EQ(t.rake_angle, -5.0);
  EXPECT_EQ(cut.material.preset, "Al2024-T351");
  // Every particle in the end clamp lies in the last h/2 of the block and at least 0.4 h
  // below the tool's tip: the clamp never holds the layer being cut.
  for (const auto& g : a.groups)
    if (g.name == "end")
      for (auto i : g.members) {
        EXPECT_LT(a.particles.position[i].z(), t.origin[2] - 0.4 * h + 1e-12);
        EXPECT_GT(a.particles.position[i].x(), (2 * cut.workpiece.cells[0] - 1) * s - 0.5 * h - 1e-12);
      }
}

// Keys the case gives win over [cut], and what follows from them moves with them.
TEST(CutTable, KeysTheCaseGivesWinAndTheDerivationFollowsThem) {
  const std::string text = std::string(kDefaultCutTableToml) +
                           "[workpiece]\nradius = 2.0e-5\n"
                           "[[mesh]]\nname = \"tool\"\nface_length = 2.0e-3\n"
                           "[[group]]\nname = \"end\"\nside = \"x+\"\n";
  const CaseSettings cs = parse_case(text, "given", {"cut.rake_angle=20.0"});
  EXPECT_EQ(cs.workpiece.radius, 2.0e-5);
  const double s = std::sqrt(2.0) * 2.0e-5, h = 0.2e-3;
  EXPECT_EQ(cs.workpiece.cells[0], static_cast<int>(std::lround(17.6 * h / (2 * s))));
  const MeshSettings& t = tool_of(cs);
  EXPECT_EQ(t.face_length, 2.0e-3);
  EXPECT_EQ(t.rake_angle, 20.0);  // (the --set on [cut])
  EXPECT_DOUBLE_EQ(t.origin[2], (2 * cs.workpiece.cells[2] - 1) * s - h);
  EXPECT_EQ(cs.meshes.size(), 1u);
  ASSERT_EQ(cs.groups.size(), 2u);
  EXPECT_EQ(cs.groups[0].name, "base");
  EXPECT_EQ(cs.groups[1].name, "end");
  EXPECT_EQ(cs.groups[1].side, "x+");
  EXPECT_NE(cs.cut_derived.find("# radius = 2e-05  (given in the case)"), std::string::npos) << cs.cut_derived;
}

TEST(CutTable, BadCutKeysAreRefusedByName) {
  const std::string ok = "uncut_chip_thickness = 0.2e-3\ncutting_speed = 10.0\nrake_angle = 10.0\nmaterial = \"C45\"\n";
  const auto refused = [&](const std::string& text, std::initializer_list<std::string> words) {
    test::expect_mentions(test::case_error(text, {}, "c.toml"), words);
  };
  refused("[cut]\ncutting_speed = 10.0\nrake_angle = 10.0\nmaterial = \"C45\"\n",
          {"c.toml", "cut.uncut_chip_thickness", "required"});
  refused("[cut]\n" + ok + "edge_radius = 0.3e-3\n", {"c.toml:6", "cut.edge_radius", "below the depth of cut"});
  refused("[cut]\n" + ok + "steady_from = 5e-3\n", {"cut.steady_from", "below the length of cut"});
  refused("[cut]\n" + ok + "materail = \"C45\"\n", {"unknown key 'cut.materail'"});
  refused("[cut]\nuncut_chip_thickness = 0.2e-3\ncutting_speed = 10.0\nrake_angle = 10.0\nmaterial = \"steel\"\n",
          {"cut.material", "\"steel\"", "C45"});
  refused("[cut]\n" + ok + "workpiece_height = 1.5\n", {"cut.workpiece_height", "end clamp"});
  refused("[cut]\n" + ok + "workpiece_length = 5.0\n", {"cut.workpiece_length", "too short"});
  // With its own end clamp, the case's block need only outlast the tool; a low block is its business.
  const std::string
      own_end = "[[group]]\nname = \"end\"\nbox_min = [3.3e-3, -1.0, 0.05e-3]\nbox_max = [1.0, 1.0, 0.1e-3]\n";
  EXPECT_EQ(test::case_error("[cut]\n" + ok + "workpiece_height = 1.5\n" + own_end), "");
  refused("[cut]\n" + ok + "workpiece_length = 5.0\nlength_of_cut = 1.2e-3\n" + own_end,
          {"cut.workpiece_length", "beyond the block"});
  refused("[cut]\n" + ok + "[workpiece]\nsize = [1e-3, 1e-3, 1e-3]\n", {"workpiece.size", "[cut]"});
  refused("[cut]\n" + ok + "[uniaxial]\nstrain_path = [0.0, 0.01]\n", {"[cut]", "[uniaxial]"});
  refused("[cut]\n" + ok + "layers = 1\n", {"cut.layers", "[2, 200]"});
  // A tool from a file on the mesh [cut] makes its tool of: the keys [cut] set are named as its.
  refused("[cut]\n" + ok + "[[mesh]]\nname = \"tool\"\nfile = \"tool.stl\"\n",
          {"c.toml:8", "key 'mesh.file' = \"tool.stl\"", "[cut] set", "rake_angle = 10",
           "clearance_angle = ", "edge_radius", "origin", "[[mesh]] 'tool'"});
  // (found by the fuzzer: a width of 5e42 m made lround overflow under the FP traps)
  refused("[cut]\n" + ok + "width = 0.5e43\n", {"cut.width", "must lie in [0, 1000]", "0 to 1 km"});
  refused("[cut]\n" + ok + "width = 900.0\n", {"cut.width", "cells", "more than"});
  refused("[cut]\n" + ok + "inclination_angle = 20.0\n", {"cut.inclination_angle", "finite width"});
  refused("[cut]\n" + ok + "width = 0.6e-3\ninclination_angle = 50.0\n", {"cut.inclination_angle", "[-45, 45]"});
  refused(
      "[[mesh]]\nname = \"w\"\norigin = [0.0, 0.0, 0.0]\nedge1 = [1.0, 0.0, 0.0]\nedge2 = [0.0, 1.0, 0.0]\n"
      "inclination_angle = 10.0\n",
      {"mesh.inclination_angle", "tool key"});
}

// An oblique cut: the tool is the generated one turned by lambda, its edge 1/cos(lambda) longer so
// that it still overhangs the width, and its tip (the edge's middle) starts and ends the lead
// (b_c / 2) tan(lambda) further back (b_c the width between the side centres), the run that much
// longer, so that the leading corner enters the block where an orthogonal edge would and the
// middle cuts the length of cut; the steady window moves with the lead.
TEST(CutTable, AnInclinedEdgeStartsItsLeadBackAndIsLongerByOneOverCosine) {
  const std::string base =
      "[cut]\nuncut_chip_thickness = 0.2e-3\ncutting_speed = 10.0\nrake_angle = 10.0\n"
      "material = \"C45\"\nlayers = 5\nwidth = 0.6e-3\n";
  const CaseSettings straight = parse_case(base, "straight", {});
  const CaseSettings oblique = parse_case(base + "inclination_angle = 25.0\n", "oblique", {});
  const MeshSettings &t0 = tool_of(straight), &t1 = tool_of(oblique);
  const double l = 25.0 * M_PI / 180.0, s = std::sqrt(2.0) * oblique.workpiece.radius;
  const double y_last = (2 * oblique.workpiece.cells[1] - 1) * s, lead = 0.5 * y_last * std::tan(l);
  EXPECT_EQ(t1.inclination_angle, 25.0);
  EXPECT_EQ(t0.inclination_angle, 0.0);
  EXPECT_NEAR(t1.width, t0.width / std::cos(l), 1e-15);
  EXPECT_NEAR(t1.origin[0], t0.origin[0] - lead, 1e-15);
  EXPECT_EQ(t1.origin[1], t0.origin[1]);
  EXPECT_EQ(t1.origin[2], t0.origin[2]);
  const double v = 10.0;
  EXPECT_NEAR(oblique.integrator.end_time, straight.integrator.end_time + lead / v, 1e-15);
  EXPECT_NEAR(oblique.output.steady_from, straight.output.steady_from + lead / v, 1e-15);
}

// tool_stiffness makes the tool a rigid body on its holder's spring: per metre of width as
// the forces are, so the model's spring is k b and its mass m b with b the width the cut's
// forces are per (2 cells in plane strain); the damper is zeta of critical; the anchor starts
// at the tip and moves with the holder at the cutting speed. The printed derivation reads back
// as the same bodies; the mount's keys are refused without it, and a mount too stiff for the
// particles' step is refused by name.
TEST(CutTable, ACompliantToolIsARigidBodyOnItsHoldersSpring) {
  const std::vector<std::string> mount{"cut.tool_stiffness=1e10", "cut.tool_mass=0.025", "cut.tool_damping_ratio=0.05"};
  const CaseSettings cs = parse_case(kDefaultCutTableToml, "compliant", mount);
  const MeshSettings& t = tool_of(cs);
  EXPECT_EQ(t.dynamics, "rigid_body");
  const double b = 2 * cs.workpiece.cells[1] * std::sqrt(2.0) * cs.workpiece.radius;  // m
  EXPECT_DOUBLE_EQ(t.spring_stiffness[0], 1e10 * b);
  EXPECT_EQ(t.spring_stiffness[1], 0.0);
  EXPECT_DOUBLE_EQ(t.spring_stiffness[2], 1e10 * b);
  EXPECT_DOUBLE_EQ(t.mass, 0.025 * b);
  EXPECT_DOUBLE_EQ(t.damping, 2 * 0.05 * std::sqrt(1e10 * b * 0.025 * b));
  EXPECT_EQ(t.holder_velocity[0], cs.cut.cutting_speed);
  EXPECT_EQ(t.initial_velocity[0], cs.cut.cutting_speed);
  EXPECT_EQ(t.fixed, "y");
  EXPECT_EQ(t.rotation, "prescribed");
  const Model a = build_model(cs), again = build_model(parse_case(cs.cut_derived, "printed", {}));
  ASSERT_EQ(a.bodies.size(), 1u);
  ASSERT_EQ(again.bodies.size(), 1u);
  const RigidBody& rb = a.bodies[0];
  EXPECT_EQ(rb.load.anchor, Vec3(t.origin[0], t.origin[1], t.origin[2]));  // the tip
  EXPECT_EQ(rb.load.spring, again.bodies[0].load.spring);
  EXPECT_EQ(rb.mass, again.bodies[0].mass);
  EXPECT_EQ(rb.load.force_damping, again.bodies[0].load.force_damping);
  const auto refused = [&](std::vector<std::string> set, std::initializer_list<std::string> words) {
    test::expect_mentions(test::case_error(kDefaultCutTableToml, set, "c.toml"), words);
  };
  refused({"cut.tool_mass=0.025"}, {"cut.tool_mass", "tool_stiffness"});
  refused({"cut.tool_damping_ratio=0.1"}, {"cut.tool_damping_ratio", "tool_stiffness"});
  refused({"cut.tool_stiffness=1e10"}, {"cut.tool_stiffness", "tool_mass"});
  // 1e12 N/m/m on 1e-4 kg/m: a period of 63 ns, 53 steps of 1.18 ns: accepted; 1e14: 5 steps.
  EXPECT_EQ(test::case_error(kDefaultCutTableToml, {"cut.tool_stiffness=1e12", "cut.tool_mass=1e-4"}), "");
  refused({"cut.tool_stiffness=1e14", "cut.tool_mass=1e-4"}, {"'tool'", "spring_stiffness", "fewer than 30 steps"});
}

// 'swarf run --check' builds and prints without running or writing; 'swarf case default'
// prints the built-in case (and --cut the same cut as a [cut] table) as files that read back.
TEST(CutTable, RunCheckAndCaseDefault) {
  test::TempDir dir("cut_check");
  const auto r = test::run_command(fmt::format("timeout 120 {} run {}/examples/cut_c45.toml --check --out {}",
                                               SWARF_BINARY, SWARF_SOURCE_DIR, dir / "out"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("derived from [cut]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("group 'end': 130 particles"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("nothing was run"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));

  const auto d = test::run_command(fmt::format("{} case default", SWARF_BINARY));
  EXPECT_EQ(d.exit_code, 0);
  EXPECT_EQ(d.output, kDefaultCaseToml);
  const auto c = test::run_command(fmt::format("{} case default --cut", SWARF_BINARY));
  EXPECT_EQ(c.exit_code, 0);
  EXPECT_EQ(c.output, kDefaultCutTableToml);
  EXPECT_EQ(c.output, test::read_file(std::string(SWARF_SOURCE_DIR) + "/examples/cut_c45.toml"));
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// A run that ends before its steady window (issue 36, defect 2) has no steady force: null in
// summary.json with a note saying why, a warning, "none" in the table (it printed "0 +- 0 kN/m"),
// and the last line does not name a chip surface that was not written; 'swarf post' agrees.
TEST(CutTable, ARunThatEndsBeforeItsSteadyWindowReportsNoForce) {
  test::TempDir dir("cut_nosteady");
  const std::string out = dir / "out";
  const auto r = run_coarse_cut(out, "--set integrator.end_time=3e-6");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto check = [&](const std::string& output, const char* who) {
    const auto sum = nlohmann::json::parse(test::read_file(out + "/summary.json"));
    const auto& c = sum["cutting"];
    EXPECT_EQ(c["steady_samples"], 0) << who;
    for (const char* k : {"cutting_force_per_width_mean_N_per_m", "cutting_force_per_width_std_N_per_m",
                          "thrust_force_per_width_mean_N_per_m", "thrust_force_per_width_std_N_per_m"})
      EXPECT_TRUE(c[k].is_null()) << who << ": " << k << " = " << c[k];
    ASSERT_TRUE(c.contains("steady_note")) << who << ": " << c.dump(2);
    // (the run ends with the step that passes 3e-6 s: verlet does not shorten its last step)
    test::expect_mentions(c["steady_note"].get<std::string>(),
                          {"starts at 0.0001 s", "after the end of the run at 3.0"});
    test::expect_mentions(output, {"warning: the steady forces are missing", "note: the steady window starts at"});
    const std::string none = "none (no steady rows: see the note below)";
    const auto fc = output.find("Fc/w "), ft = output.find("Ft/w ");
    ASSERT_NE(fc, std::string::npos) << output;
    ASSERT_NE(ft, std::string::npos) << output;
    EXPECT_NE(output.substr(fc, output.find('\n', fc) - fc).find(none), std::string::npos) << output;
    EXPECT_NE(output.substr(ft, output.find('\n', ft) - ft).find(none), std::string::npos) << output;
    EXPECT_EQ(output.find("0 +- 0 kN/m"), std::string::npos) << who << ": " << output;
  };
  check(r.output, "run");
  EXPECT_NE(r.output.find("particles.pvd (open in ParaView)"), std::string::npos) << r.output;
  ASSERT_FALSE(std::filesystem::exists(out + "/chip_surface.vtp")) << "the case must end before the chip forms";
  EXPECT_EQ(r.output.find("chip_surface.vtp"), std::string::npos) << r.output;
  const auto p = test::run_command(fmt::format("{} post {}", SWARF_BINARY, out));
  ASSERT_EQ(p.exit_code, 0) << p.output;
  check(p.output, "post");
}

// Oxley's theory beside the cut: the C45 preset's material, the tool's speed, the measured
// depth of cut, the rake angle and the width go in; summary.json holds the solution and the
// terminal its table; 'swarf post' recomputes the same figures from results.h5.
TEST(CutTable, OxleysTheoryStandsBesideTheCut) {
  test::TempDir dir("cut_oxley");
  const std::string out = dir / "out";
  const auto r = run_coarse_cut(out, "--set integrator.end_time=3e-6 --set output.vtk=false");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto sum = nlohmann::json::parse(test::read_file(out + "/summary.json"));
  const auto& ox = sum["oxley"];
  ASSERT_TRUE(ox["solved"].get<bool>()) << ox.dump(2);
  EXPECT_EQ(ox["material"], "C45");
  EXPECT_EQ(ox["depth_of_cut_m"].get<double>(), sum["chip"]["depth_of_cut_m"].get<double>());
  EXPECT_EQ(ox["width_m"].get<double>(), sum["cutting"]["width_m"].get<double>());
  EXPECT_EQ(ox["rake_angle_deg"].get<double>(), sum["case"]["cut"]["rake_angle"].get<double>()) << sum["case"].dump();
  EXPECT_EQ(ox["speed_m_per_s"].get<double>(), sum["case"]["cut"]["cutting_speed"].get<double>());
  test::expect_mentions(r.output, {"Oxley's theory at this cut (C45,", "swarf/Oxley"});
  const auto p = test::run_command(fmt::format("{} post {}", SWARF_BINARY, out));
  ASSERT_EQ(p.exit_code, 0) << p.output;
  const auto post = nlohmann::json::parse(test::read_file(out + "/summary.json"));
  EXPECT_EQ(post["oxley"], ox);
}

// A cut stopped before the tool touches the block has no force, so no force direction: the
// friction angle and Merchant's angle are not measured (null), not the rake angle that
// atan2(0, 0) = 0 would make of them.
TEST(CutTable, ACutWithoutForceHasNoFrictionAngle) {
  test::TempDir dir("cut_noforce");
  const auto r = test::run_command(fmt::format(
      "timeout 120 {} run {}/examples/cut_c45.toml --out {} --set integrator.end_time=1e-8 --set output.plots=false "
      "--set output.vtk=false --threads 1",
      SWARF_BINARY, SWARF_SOURCE_DIR, dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ns per particle-step, 1 thread)"), std::string::npos) << r.output;  // (not "1 threads")
  const std::string summary = test::read_file(dir / "out/summary.json");
  EXPECT_NE(summary.find("\"friction_angle_deg\": null"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"merchant_shear_angle_deg\": null"), std::string::npos) << summary;
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// The broken-rod fraction counts the lattice's own rods only: 1 of the 3 own rods below is
// broken; the formed rods (one intact, one broken) are in neither count.
TEST(BrokenRodFraction, CountsTheLatticesOwnRodsOnly) {
  const std::vector<std::uint8_t> intact{1, 0, 1, 1, 0}, formed{0, 0, 0, 1, 1};
  EXPECT_EQ(broken_rod_fraction(intact, formed), 1.0 / 3.0);
  EXPECT_EQ(broken_rod_fraction(intact, {}), 2.0 / 5.0);  // (no formed flags: every rod is the lattice's)
  EXPECT_EQ(broken_rod_fraction({}, {}), 0.0);            // (no rods: 0, not NaN)
  EXPECT_THROW(broken_rod_fraction(intact, std::vector<std::uint8_t>{0, 1}), InputError);
}

// 'swarf post' on a finished [cut] run gives the run's broken-rod fraction, bit for bit: with
// bond formation the run divided by the lattice's own rods and post (before layout 4) by all
// rods, formed ones included (0.7312 % against 0.7365 % on this case). The coarse cut (5
// layers, 0.15 mm) breaks 56 rods and forms some 60.
TEST(CutTable, PostGivesTheRunsBrokenRodFraction) {
  test::TempDir dir("cut_post_broken");
  const std::string out = dir / "out";
  const auto r = run_coarse_cut(out, "--set cut.length_of_cut=0.15e-3 --set output.vtk=false");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto run = nlohmann::json::parse(test::read_file(out + "/summary.json"));
  ASSERT_GT(run["results"]["broken_rods"].get<long long>(), 0) << run["results"].dump(2);
  {
    H5File f(out + "/results.h5", H5File::Mode::Read);
    std::size_t rows = 0, cols = 0;
    const auto formed = f.read_ints("/bonds/formed", rows, cols);
    ASSERT_GT(std::count(formed.begin(), formed.end(), 1), 0) << "the case must form rods to test this";
  }
  const double fraction = run["cutting"]["broken_fraction"].get<double>();
  EXPECT_EQ(fraction, run["results"]["broken_fraction"].get<double>());
  const auto p = test::run_command(fmt::format("{} post {}", SWARF_BINARY, out));
  ASSERT_EQ(p.exit_code, 0) << p.output;
  const auto post = nlohmann::json::parse(test::read_file(out + "/summary.json"));
  EXPECT_EQ(post["cutting"]["broken_fraction"].get<double>(), fraction);
  const auto line = [](const std::string& text) {
    const auto at = text.find("broken-rod fraction");
    return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
  };
  EXPECT_EQ(line(p.output), line(r.output));
}

// contact.sticking_flow_zone reaches the contact law as f = (1 - s) 2 / (3 K) (sticking.h) and
// is refused by name without [heat] (the face's rise is the friction heat over K).
TEST(CutTable, TheFlowZoneNeedsHeatAndReachesTheStickingRule) {
  const Model m = build_model(parse_case(kDefaultCaseToml, "default", {"contact.sticking_flow_zone=true"}));
  EXPECT_NEAR(m.contact.sticking.flow_zone, (1.0 - 0.5) * 2.0 / (3.0 * 50.7), 1e-15);
  const Model off = build_model(parse_case(kDefaultCaseToml, "default", {}));
  EXPECT_EQ(off.contact.sticking.flow_zone, 0.0);
  test::expect_mentions(test::case_error(kDefaultCaseToml, {"contact.sticking_flow_zone=true", "heat.enabled=false"}),
                        {"bad.toml", "contact.sticking_flow_zone", "[heat]"});
}

// contact.tool_friction_* reach the contact law as the table they give (speed_friction.h), and a
// table that is not one is refused by name: unequal lengths, speeds not increasing, half a table,
// too many points, a table without a friction law.
TEST(CutTable, TheToolFrictionTableReachesTheContactLawAndBadTablesAreNamed) {
  const Model m = build_model(parse_case(
      kDefaultCaseToml, "default",
      {"contact.tool_friction_speeds=[1.0, 3.0, 6.0]", "contact.tool_friction_coefficients=[0.6, 0.45, 0.3]"}));
  ASSERT_EQ(m.contact.tool_friction.points, 3);
  EXPECT_EQ(m.contact.tool_friction.speed[2], 6.0);
  EXPECT_EQ(m.contact.tool_friction.mu[1], 0.45);
  EXPECT_NEAR(friction_at_speed(m.contact.tool_friction, m.contact.friction, 2.0), 0.525, 1e-15);
  EXPECT_EQ(build_model(parse_case(kDefaultCaseToml, "default", {})).contact.tool_friction.points, 0);
  test::expect_mentions(test::case_error(kDefaultCaseToml, {"contact.tool_friction_speeds=[1.0, 3.0]",
                                                            "contact.tool_friction_coefficients=[0.6]"}),
                        {"bad.toml", "contact.tool_friction_coefficients", "one coefficient per speed"});
  test::expect_mentions(test::case_error(kDefaultCaseToml, {"contact.tool_friction_speeds=[3.0, 1.0]",
                                                            "contact.tool_friction_coefficients=[0.6, 0.4]"}),
                        {"bad.toml", "contact.tool_friction_speeds", "strictly increasing"});
  test::expect_mentions(test::case_error(kDefaultCaseToml, {"contact.tool_friction_speeds=[3.0, 4.0]"}),
                        {"bad.toml", "contact.tool_friction_speeds", "tool_friction_coefficients"});
  test::expect_mentions(
      test::case_error(kDefaultCaseToml, {"contact.tool_friction_speeds=[3.0]",
                                          "contact.tool_friction_coefficients=[0.3]", "contact.friction_law=\"none\""}),
      {"bad.toml", "contact.tool_friction_speeds", "friction law"});
  test::expect_mentions(
      test::case_error(kDefaultCaseToml, {"contact.tool_friction_speeds=[1, 2, 3, 4, 5, 6, 7, 8, 9]",
                                          "contact.tool_friction_coefficients=[1, 1, 1, 1, 1, 1, 1, 1, 1]"}),
      {"bad.toml", "contact.tool_friction_speeds", "1 to 8"});
}

}  // namespace
}  // namespace swarf

// test_bad_inputs.cpp: inputs that used to hang, crash or give silent garbage (issue 18's
// matrix) stop with exit code 2 and a message that names what is wrong. Each test failed
// before its fix: the run hung (a NaN step retried for ever, an output interval below the
// time's rounding), crashed (--threads 100000) or completed with garbage (an OBJ index read
// as another, a truncated STL short of a facet, a doubled bond, a NaN checkpoint time).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "app/observers/energy_balance.h"
#include "io/h5file.h"
#include "io/mesh_file.h"
#include "lattice_gen/fcc_lattice.h"
#include "lattice_gen/lattice_file.h"
#include "scenes/pulled_bar.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "study/study.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"
#include "swarf/neighbors/neighbor_pairs.h"
#include "test_helpers.h"

namespace swarf {
namespace {

using test::run_command;
using test::TempDir;
using test::write_file;

const std::string kBar = test::pulled_bar_case({.cells = {4, 2, 2},
                                                .velocity = 1.0,
                                                .integrator = "end_time = 2e-6",
                                                .extra = "[output]\nvtk = false\nplots = false\n"});

// Runs 'swarf run' on kBar with the overrides, under a time limit (a hang fails the test
// instead of the suite); returns the result.
test::CommandResult run_bar(const TempDir& dir, const std::string& args) {
  write_file(dir / "bar.toml", kBar);
  return run_command(
      fmt::format("timeout 120 {} run {} --out {} {}", SWARF_BINARY, dir / "bar.toml", dir / "out", args));
}

void expect_refused(const test::CommandResult& r, const std::string& word) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(word), std::string::npos) << "the message should name '" << word << "':\n" << r.output;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BadInput, AbsurdSizesThatMakeTheStepNaNOrZeroAreRefusedNotRetriedForEver) {
  TempDir dir("bad_step");
  // Refused by the key's range before anything overflows, so the floating-point traps stay on
  // (before the ranges, 1e300 m overflowed in the lattice's pair search and 1e-300 kg/m^3 in
  // compute_derived, and the run was refused only when the step came out non-finite).
  expect_refused(run_bar(dir, "--set workpiece.radius=1e300"), "workpiece.radius");
  expect_refused(run_bar(dir, "--set workpiece.radius=1e-300"), "workpiece.radius");
  expect_refused(run_bar(dir, "--set material.density=1e-300"), "material.density");
  expect_refused(run_bar(dir, "--set material.density=1e300"), "material.density");
}

// A stream of spheres from an inflow box into an outflow below; a rigid box whose mass
// properties are given (issue 37's probe tables: [[inflow]], [[outflow]], rigid bodies).
const std::string kFlows =
    "[material]\ndensity = 2500.0\n[contact]\nyoungs_modulus = 1e8\n"
    "[[inflow]]\nbox_min = [0.0, 0.0, 0.0]\nbox_max = [0.01, 0.01, 0.002]\nrate = 2e4\nradius_min = 0.4e-3\n"
    "radius_max = 0.6e-3\nvelocity = [0.0, 0.0, -2.0]\n"
    "[[outflow]]\nplane_point = [0.0, 0.0, -0.01]\nplane_normal = [0.0, 0.0, -1.0]\n"
    "[integrator]\nscheme = \"verlet\"\nend_time = 2e-5\n[output]\nvtk = false\nplots = false\n";
const std::string kBody =
    "[[particle]]\nposition = [1.0, 1.0, 1.0]\nradius = 1e-3\n[material]\ndensity = 1000.0\n[contact]\n"
    "[integrator]\nend_time = 1e-5\n[output]\nvtk = false\nplots = false\n"
    "[[mesh]]\nname = \"b\"\ndynamics = \"rigid_body\"\nbox_size = [0.02, 0.04, 0.06]\norigin = [0.1, 0.2, 0.3]\n"
    "mass = 0.1\ncentre_of_mass = [0.1, 0.2, 0.3]\ninertia = [4e-5, 3e-5, 2e-5, 0.0, 0.0, 0.0]\n";

// 'swarf run' of 'text' (written as NAME) with the overrides, under a time limit.
test::CommandResult run_text(const TempDir& dir, const std::string& name, const std::string& text,
                             const std::string& args) {
  write_file(dir / name, text);
  return run_command(
      fmt::format("timeout 120 {} run {} --out {} --threads 1 {}", SWARF_BINARY, dir / name, dir / "out", args));
}

// Issue 37, classes B (nonsense accepted: exit 0 and a summary that looked complete) and C
// (input errors reported as blow-ups: exit 3 after stepping). Each is now refused before a
// step with exit 2 and a message naming the file, the key and the value; the values are this
// matrix's own, not the probe's. Each case runs as it is (exit 0) without the override.
TEST(BadInput, NonsenseAndInputErrorsAreRefusedBeforeSteppingByFileKeyAndValue) {
  TempDir dir("nonsense");
  ASSERT_EQ(run_bar(dir, "").exit_code, 0);
  ASSERT_EQ(run_text(dir, "flows.toml", kFlows, "").exit_code, 0);
  ASSERT_EQ(run_text(dir, "body.toml", kBody, "").exit_code, 0);
  const auto refused = [&](const test::CommandResult& r, std::initializer_list<std::string> words) {
    EXPECT_EQ(r.exit_code, 2) << r.output;
    for (const std::string& w : words)
      EXPECT_NE(r.output.find(w), std::string::npos) << "the message should name '" << w << "':\n" << r.output;
  };
  const auto bar = [&](const std::string& set) { return run_bar(dir, "--set " + set); };
  // (the bar with a flow curve in place of its yield strain and hardening modulus)
  std::string curved = kBar;
  for (const std::string line : {"yield_strain = 1e-3\n", "hardening_modulus = 20e9\n"})
    curved.erase(curved.find(line), line.size());
  const auto curve = [&](const std::string& set) { return run_text(dir, "bar.toml", curved, "--set " + set); };
  const auto flows = [&](const std::string& set) { return run_text(dir, "flows.toml", kFlows, "--set " + set); };
  const auto body = [&](const std::string& set) { return run_text(dir, "body.toml", kBody, "--set " + set); };
  const auto fine = curve("rod.flow_plastic_strain=[0.0,0.2] --set rod.flow_stress=[2e8,3e8]");
  ASSERT_EQ(fine.exit_code, 0) << fine.output;
  // B: a flow curve of zeros, of absurd stresses, one above E, one steeper than E.
  refused(curve("rod.flow_plastic_strain=[0.0,0.2] --set rod.flow_stress=[0.0,0.0]"),
          {"bar.toml", "rod.flow_stress", "[0, 0]", "entry 0 = 0"});
  refused(curve("rod.flow_plastic_strain=[0.0,0.2] --set rod.flow_stress=[3e250,3e250]"),
          {"bar.toml", "rod.flow_stress", "3e+250"});
  refused(curve("rod.flow_plastic_strain=[0.0,0.2] --set rod.flow_stress=[3e11,4e11]"),
          {"bar.toml", "rod.flow_stress", "below the Young's modulus rod.youngs_modulus = 200000000000 Pa"});
  refused(curve("rod.flow_plastic_strain=[0.0,1e-4] --set rod.flow_stress=[4e8,9e8]"),
          {"bar.toml", "rod.flow_stress", "rises by 500000000 Pa", "a hardening modulus above E"});
  refused(bar("material.youngs_modulus=7e250"), {"bar.toml", "material.youngs_modulus", "7e+250", "1e15"});
  // B: inflow boxes far away, too wide, of no volume; an outflow normal of subnormal length.
  refused(flows("inflow.0.box_min=[4e7,0.0,0.0]"), {"flows.toml", "inflow.box_min", "40000000", "within 1 km"});
  refused(flows("inflow.0.box_max=[3e5,0.01,0.002]"), {"flows.toml", "inflow.box_max", "300000"});
  refused(flows("inflow.0.box_max=[0.01,0.01,0.0]"), {"flows.toml", "inflow.box_max", "no volume"});
  refused(flows("outflow.0.plane_normal=[0.0,3e-315,0.0]"), {"flows.toml", "outflow.plane_normal", "3e-315"});
  refused(flows("outflow.0.plane_normal=[0.0,0.0,-2e-9]"), {"flows.toml", "outflow.plane_normal", "at least 1e-6"});
  // B: a rigid body of a negligible mass, or of an inertia that no body of its mass has.
  refused(body("mesh.0.mass=7e-150"), {"body.toml", "mesh.mass", "7e-150", "kg"});
  refused(body("mesh.0.inertia=[2e-230,2e-230,2e-230,0.0,0.0,0.0]"),
          {"body.toml", "'inertia'", "2e-230", "radius of gyration"});
  refused(body("mesh.0.inertia=[2e7,2e7,2e7,0.0,0.0,0.0]"), {"body.toml", "'inertia'", "2e+07", "radius of gyration"});
  // C: a negative flow stress, an inflow box across the doubles, a normal of length 1e-310.
  refused(curve("rod.flow_plastic_strain=[0.0,0.2] --set rod.flow_stress=[-2e8,3e8]"),
          {"bar.toml", "rod.flow_stress", "-200000000"});
  refused(flows("inflow.0.box_min=[-3e200,-3e200,-3e200] --set inflow.0.box_max=[3e200,3e200,3e200]"),
          {"flows.toml", "inflow.box_min", "-3e+200"});
  refused(flows("outflow.0.plane_normal=[0.0,0.0,-1e-310]"), {"flows.toml", "outflow.plane_normal", "-1e-310"});
  EXPECT_FALSE(std::filesystem::exists(dir / "out/summary.json.part"));
}

// Issue 37, class A: runs that could never finish started and sat silently. Those a single key
// makes so are refused by its range; the rest by the estimate before the first step: the step
// count over integrator.max_steps (--allow-long passes it), an inflow asking more particles in
// a step than its box holds, the particles of the inflows beyond the machine's memory.
TEST(BadInput, RunsThatCannotFinishAreRefusedBeforeTheFirstStep) {
  TempDir dir("cannot_finish");
  const auto bar = [&](const std::string& args) { return run_bar(dir, args); };
  const auto flows = [&](const std::string& args) { return run_text(dir, "flows.toml", kFlows, args); };
  const auto refused = [&](const test::CommandResult& r, std::initializer_list<std::string> words) {
    EXPECT_EQ(r.exit_code, 2) << r.output;
    for (const std::string& w : words)
      EXPECT_NE(r.output.find(w), std::string::npos) << "the message should name '" << w << "':\n" << r.output;
    EXPECT_EQ(r.output.find("steps (verlet)"), std::string::npos) << "it stepped:\n" << r.output;
  };
  // By the keys' ranges (a stable step of 1e-150 s, an end time or a step of denormals, an
  // iteration that cannot converge and a step that shrinks by 1e-6 a try).
  refused(bar("--set material.youngs_modulus=3e200"), {"material.youngs_modulus", "3e+200"});
  refused(bar("--set integrator.end_time=4e-320"), {"integrator.end_time", "4e-320"});
  refused(bar("--set integrator.scheme='\"verlet\"' --set integrator.dt=2e-318"), {"integrator.dt", "2e-318"});
  refused(bar("--set integrator.tolerance=1e-200"), {"integrator.tolerance", "1e-200"});
  refused(bar("--set integrator.reject_factor=0.9999"), {"integrator.reject_factor", "0.9999"});
  refused(bar("--set integrator.dt_min=3e-280"), {"integrator.dt_min", "3e-280"});
  // By the step count: a given step, the step control's largest step, a stable step made tiny
  // by an inflow's radius; each names the keys, the count and the time.
  refused(bar("--set integrator.scheme='\"verlet\"' --set integrator.dt=2e-15"),
          {"bar.toml", "integrator.end_time", "steps of 2e-15 s", "integrator.dt = 2e-15 s", "max_steps = 1e+08",
           "ns per particle-step", "--allow-long"});
  refused(bar("--set integrator.scheme='\"newmark\"' --set integrator.dt=2e-15 --set integrator.dt_min=1e-15 "
              "--set integrator.dt_max=3e-15"),
          {"integrator.dt_max = 3e-15 s", "steps of 3e-15 s"});
  refused(flows("--set inflow.0.radius_min=3e-9 --set integrator.end_time=1e-3"),
          {"flows.toml", "the stable step", "inflow radii", "3e-09 m"});
  // The limit is a key, and --allow-long passes it on purpose (the bar then runs to its end).
  const std::string verlet = "--set integrator.scheme='\"verlet\"' ";  // (some 30 steps of 6.6e-8 s)
  refused(bar(verlet + "--set integrator.max_steps=20"), {"integrator.max_steps = 20"});
  const auto on_purpose = bar(verlet + "--set integrator.max_steps=20 --allow-long");
  EXPECT_EQ(on_purpose.exit_code, 0) << on_purpose.output;
  // Inflows: more particles a step than the box holds; more over the run than the memory holds.
  refused(flows("--set inflow.0.rate=4e11"), {"flows.toml", "inflow.rate", "4e+11", "more than its box can hold"});
  refused(flows("--set integrator.end_time=5e4"), {"flows.toml", "inflow.rate", "integrator.end_time", "GB", "--force"});
  // Found by the case_model fuzzer: a [membrane] of 1e8 sites was built until the memory ran
  // out; a [cut]'s refusal named keys the cut had derived without saying so.
  const std::string sheet =
      "[membrane]\nlength = 4e-3\nwidth = 4e-3\nradius = 0.5e-3\nthickness = 1e-4\nyoungs_modulus = 1e9\n"
      "[integrator]\nend_time = 1e-5\n[output]\nvtk = false\nplots = false\n";
  refused(run_text(dir, "sheet.toml", sheet,
                   "--set membrane.length=0.2 --set membrane.width=0.2 "
                   "--set membrane.radius=1e-5"),
          {"sheet.toml", "membrane.length", "membrane.radius", "GB", "--force"});
  refused(run_text(dir, "sheet.toml", sheet, "--set membrane.length=0.4e-3 --set membrane.width=0.4e-3"),
          {"sheet.toml", "membrane.length", "membrane.width", "fewer than 3 sites"});
  refused(run_command(fmt::format("timeout 120 {} run {}/examples/cut_c45.toml --out {} --set cut.cutting_speed=1e-4",
                                  SWARF_BINARY, SWARF_SOURCE_DIR, dir / "cut")),
          {"cut_c45.toml", "integrator.end_time", "[cut] derived it from cut.length_of_cut over cut.cutting_speed"});
}

// Issue 37, class D: an outflow half-space that holds the inflow's box (every new particle
// removed one step after it came) stopped with "energy balance lost" and exit code 3, on both
// schemes, with gravity. It completes now; and a run where no particle was ever present
// writes a strict summary.json, its cost per particle-step null with the reason.
TEST(BadInput, AnOutflowHoldingTheInflowCompletesAndAnEmptyRunHasNullFigures) {
  TempDir dir("outflow_holds_inflow");
  std::string held = kFlows;
  const std::string plane = "plane_point = [0.0, 0.0, -0.01]";
  held.replace(held.find(plane), plane.size(), "plane_point = [0.0, 0.0, 0.5]");
  held += "[environment]\ngravity = [0.0, -3.0, -9.81]\n";
  for (const char* scheme : {"verlet", "newmark"}) {
    const auto r = run_text(dir, "held.toml", held,
                            fmt::format("--set integrator.scheme='\"{}\"' --set inflow.0.rate=3e3 "
                                        "--set integrator.end_time=2e-3",
                                        scheme));
    EXPECT_EQ(r.exit_code, 0) << scheme << "\n" << r.output;
    const auto summary = nlohmann::json::parse(test::read_file(dir / "out/summary.json"));
    EXPECT_GT(summary["flows"]["outflow_removed"].get<double>(), 2) << scheme;
  }
  const auto empty = run_text(dir, "held.toml", held, "--set inflow.0.rate=1.0 --set integrator.end_time=1e-4");
  ASSERT_EQ(empty.exit_code, 0) << empty.output;
  const std::string text = test::read_file(dir / "out/summary.json");
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  EXPECT_EQ(text.find("Infinity"), std::string::npos);
  const auto summary = nlohmann::json::parse(text);  // (strict: throws on anything but JSON)
  EXPECT_TRUE(summary["run"]["ns_per_particle_step"].is_null());
  EXPECT_NE(summary["run"]["ns_per_particle_step_reason"].get<std::string>().find("no particle"), std::string::npos);
}

TEST(BadInput, OutputIntervalsThatCouldNeverAdvanceAreRefused) {
  TempDir dir("bad_interval");
  expect_refused(run_bar(dir, "--set output.series_interval=1e-30"), "output.series_interval");
  expect_refused(run_bar(dir, "--set output.frame_interval=1e-30 --set output.vtk=true"), "output.frame_interval");
  expect_refused(run_bar(dir, "--set integrator.end_time=0"), "integrator.end_time");
}

TEST(BadInput, ThreadCountsOutOfRangeAreRefused) {
  TempDir dir("bad_threads");
  for (const char* t : {"0", "-1", "100000"}) expect_refused(run_bar(dir, std::string("--threads ") + t), "--threads");
}

// Started by mpirun on two ranks (its environment stands in for it: no launcher needed), 'swarf
// run' refuses before writing anything: each rank would run the whole case into one directory.
TEST(BadInput, ObjNumbersWithFractionsJunkOrOverflowAreRefused) {
  TempDir dir("bad_obj");
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (const std::string face :
       {"f 1 2 4294967299", "f 1 2 3.7", "f 1 2 3abc", "f 1 2 99999999999999999999", "f 1 2 4"}) {
    write_file(dir / "m.obj", v + face + "\n");
    EXPECT_NE(message_of([&] { read_mesh(dir / "m.obj"); }).find("face index"), std::string::npos) << face;
  }
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 0abc\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(message_of([&] { read_mesh(dir / "m.obj"); }).find("not a finite number"), std::string::npos);
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(message_of([&] { read_mesh(dir / "m.obj"); }).find("not a finite number"), std::string::npos);
  // Finite but absurd: its area overflowed (a floating-point trap) before the mesh was refused.
  write_file(dir / "m.obj", "v 0 0 0\nv 1e300 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(message_of([&] { read_mesh(dir / "m.obj"); }).find("lies beyond 1e+06 m"), std::string::npos);
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(message_of([&] { read_mesh(dir / "m.obj", 1e300); }).find("lies beyond 1e+06 m once scaled"),
            std::string::npos);
  write_file(dir / "m.obj", v + "f 1 2 3\nf -1 -2 -3\n");  // negative indices count back: still fine
  EXPECT_EQ(read_mesh(dir / "m.obj").triangles.size(), 2u);
}

TEST(BadInput, ATruncatedAsciiStlAndANaNVertexInABinaryStlAreRefused) {
  TempDir dir("bad_stl");
  const std::string
      facet = "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";
  write_file(dir / "whole.stl", "solid t\n" + facet + facet + "endsolid t\n");
  EXPECT_EQ(read_mesh(dir / "whole.stl").triangles.size(), 2u);
  const std::string cut = "solid t\n" + facet + facet.substr(0, facet.find("endloop"));
  write_file(dir / "cut.stl", cut);
  EXPECT_NE(message_of([&] { read_mesh(dir / "cut.stl"); }).find("truncated"), std::string::npos);
  write_file(dir / "cut2.stl", "solid t\n" + facet);  // every facet complete, but no endsolid
  EXPECT_NE(message_of([&] { read_mesh(dir / "cut2.stl"); }).find("truncated"), std::string::npos);
  // Binary: 80-byte header, count, 50 bytes per facet with a NaN in the second vertex.
  std::string bin(84 + 50, '\0');
  const std::uint32_t n = 1;
  std::memcpy(&bin[80], &n, 4);
  const float xyz[9] = {0, 0, 0, 1, NAN, 0, 0, 1, 0};
  std::memcpy(&bin[84 + 12], xyz, sizeof xyz);
  std::ofstream(dir / "nan.stl", std::ios::binary) << bin;
  EXPECT_NE(message_of([&] { read_mesh(dir / "nan.stl"); }).find("not finite"), std::string::npos);
}

TEST(BadInput, ALatticeFileListingABondTwiceIsRefused) {
  TempDir dir("bad_lattice");
  FccSpec spec;
  spec.radius = 0.5e-3;
  spec.cells = {2, 2, 2};
  Lattice lat = generate_fcc(spec);
  write_lattice(dir / "ok.h5", lat);
  EXPECT_EQ(read_lattice(dir / "ok.h5").rods.size(), lat.rods.size());
  lat.rods.push_back({lat.rods[3][1], lat.rods[3][0]});  // the same pair, ends swapped
  lat.rest_length.push_back(lat.rest_length[3]);
  write_lattice(dir / "twice.h5", lat);
  EXPECT_NE(message_of([&] { read_lattice(dir / "twice.h5"); }).find("each pair once"), std::string::npos);
}

// The message with which read_lattice refuses a one-cell lattice spoiled by 'spoil', written
// to DIR/l.h5.
std::string lattice_refusal(const TempDir& dir, const std::function<void(Lattice&)>& spoil) {
  FccSpec spec;
  spec.radius = 0.5e-3;
  spec.cells = {1, 1, 1};
  Lattice lat = generate_fcc(spec);
  spoil(lat);
  write_lattice(dir / "l.h5", lat);
  return message_of([&] { read_lattice(dir / "l.h5"); });
}

// Found by the lattice-file fuzzer: values a lattice file accepted as positive and finite
// overflowed (SIGFPE under the traps) or divided by zero when the model was built from them.
TEST(BadInput, ALatticeFileWithAbsurdRadiiLengthsOrPositionsOrNoParticlesIsRefused) {
  TempDir dir("absurd_lattice");
  auto refusal = [&](const std::function<void(Lattice&)>& spoil) { return lattice_refusal(dir, spoil); };
  EXPECT_NE(refusal([](Lattice& l) { l.radius[1] = 1e300; }).find("/particles/radius[1] = 1e+300"), std::string::npos);
  EXPECT_NE(refusal([](Lattice& l) { l.radius[1] = 1e-300; }).find("from 1e-09 to 1 m"), std::string::npos);
  EXPECT_NE(refusal([](Lattice& l) { l.rest_length[2] = 1e-300; }).find("/bonds/rest_length[2]"), std::string::npos);
  EXPECT_NE(refusal([](Lattice& l) { l.position[0][2] = 1e300; }).find("lies beyond"), std::string::npos);
  EXPECT_NE(refusal([](Lattice& l) { l.cell_edge = NAN; }).find("cell_edge = nan"), std::string::npos);
  EXPECT_NE(refusal([](Lattice& l) { l = Lattice{}; }).find("no particles"), std::string::npos);
}

// Found by the lattice-file fuzzer: a radius holding a signalling NaN (0xfff4fb0000e1e100)
// failed the bit test and was refused, but the message that named it handed the NaN to fmt,
// which raised FE_INVALID (SIGFPE under the traps; fmt signals on a signalling NaN even
// without a precision, and std::isnan does too). The values are named through nan_safe, which
// tests a NaN on its bits.
TEST(BadInput, ASignallingNaNInALatticeFileIsNamedNotTrapped) {
  TempDir dir("snan_lattice");
  const double snan = std::bit_cast<double>(std::uint64_t(0xfff4fb0000e1e100));
  std::string m = lattice_refusal(dir, [&](Lattice& l) { l.radius[1] = snan; });
  EXPECT_NE(m.find("/particles/radius[1] = nan is not a radius"), std::string::npos) << m;
  m = lattice_refusal(dir, [&](Lattice& l) { l.rest_length[2] = snan; });
  EXPECT_NE(m.find("/bonds/rest_length[2] = nan is not a length"), std::string::npos) << m;
  m = lattice_refusal(dir, [&](Lattice& l) { l.cell_edge = std::numeric_limits<double>::signaling_NaN(); });
  EXPECT_NE(m.find("cell_edge = nan is neither"), std::string::npos) << m;
  EXPECT_EQ(fmt::format("{:>5.3g}|{}|{}", nan_safe(snan), nan_safe(2.5), nan_safe(HUGE_VAL)), "  nan|2.5|inf");
}

// Found by the study-file fuzzer: toml++ converts a float with strtod, which raised
// FE_OVERFLOW on 31e308 (SIGFPE under the traps) inside the parser. Parsed with the
// exceptions held, the parser refuses the number itself (file, line, the literal); in an
// override it is read as a word, which the key refuses.
TEST(BadInput, AFloatBeyondTheDoublesInACaseOrStudyFileIsRefusedNotTrapped) {
  const std::string m = message_of([] { parse_case("[integrator]\nend_time = 1e309\n", "c.toml", {}); });
  EXPECT_NE(m.find("c.toml:2:"), std::string::npos) << m;
  EXPECT_NE(m.find("'1e309'"), std::string::npos) << m;
  // (the case-file fuzzer: toml++'s printer raised FE_INVALID on a NaN, writing the effective case)
  const std::string p = message_of([] {
    parse_case("[[particle]]\nposition = [nan, 0.0, 0.0]\nradius = 1e-3\n[contact]\n[integrator]\nend_time = 1e-4\n",
               "c.toml", {});
  });
  EXPECT_NE(p.find("particle.position"), std::string::npos) << p;
  EXPECT_NE(p.find("must be finite"), std::string::npos) << p;
}

// A TOML syntax error names the file, the line and the column, in the same words for a case
// file and a study file (one function, setup/toml_parse.h).
TEST(BadInput, ATomlSyntaxErrorNamesFileLineAndColumnInEitherFile) {
  const std::string c = message_of([] { parse_case("[rod]\nyield_strain = = 1\n", "c.toml", {}); });
  const std::string s = message_of([] { parse_study("base = \"c.toml\"\n[grid\n", "s.toml", "."); });
  EXPECT_EQ(c.rfind("c.toml:2:", 0), 0u) << c;
  EXPECT_EQ(s.rfind("s.toml:2:", 0), 0u) << s;
  for (const std::string& m : {c, s}) EXPECT_NE(m.find(": TOML syntax error: "), std::string::npos) << m;
}

// Found by the lattice-file fuzzer: two particles at one place have no contact normal, and the
// first contact evaluation divided by their zero distance (SIGFPE under the traps).
TEST(BadInput, TwoParticlesAtOnePlaceAreRefused) {
  const std::string m = message_of([] {
    build_model(
        parse_case("[[particle]]\nposition = [0.0, 0.0, 0.0]\nradius = 1e-3\n[[particle]]\nposition = [1e-3, "
                   "0.0, 0.0]\nradius = 1e-3\n[[particle]]\nposition = [0.0, 0.0, 0.0]\nradius = 1e-3\n"
                   "[contact]\n[integrator]\nend_time = 1e-4\n",
                   "c.toml", {}));
  });
  EXPECT_NE(m.find("particles 0 and 2 lie within"), std::string::npos) << m;
  // 1e-170 m apart: the squared distance underflows to 0 (the lattice-file fuzzer, again).
  const std::string u = message_of([] {
    build_model(
        parse_case("[[particle]]\nposition = [1e-170, 0.0, 0.0]\nradius = 1e-3\n[[particle]]\nposition = "
                   "[0.0, 0.0, 0.0]\nradius = 1e-3\n[contact]\n[integrator]\nend_time = 1e-4\n",
                   "c.toml", {}));
  });
  EXPECT_NE(u.find("particles 0 and 1 lie within 1e-09 m"), std::string::npos) << u;
  // The search itself: a close pair across a plane of equal x, and none in a lattice.
  std::vector<Vec3> plane;
  for (int k = 0; k < 2000; ++k) plane.emplace_back(0.0, 1e-3 * k, 0.0);
  EXPECT_EQ(find_coincident(plane, 1e-9)[0], -1);
  plane.emplace_back(1e-10, 1e-3 * 1234, 5e-10);
  EXPECT_EQ(find_coincident(plane, 1e-9), (std::array<std::int32_t, 2>{1234, 2000}));
  EXPECT_EQ(find_coincident(plane, 1e-10)[0], -1);
  const std::string o = message_of(
      [] { parse_case("[integrator]\nend_time = 1e-3\n", "c.toml", {"integrator.end_time=-1e400"}); });
  EXPECT_NE(o.find("integrator.end_time"), std::string::npos) << o;
}

TEST(BadInput, AMeshFileWithAnOriginIsRefusedAsTheDocsSay) {
  TempDir dir("bad_origin");
  write_file(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_file(dir / "c.toml",
             std::string(kBar) + "[[mesh]]\nname = \"wall\"\nfile = \"m.obj\"\norigin = [0.0, 0.0, 1.0]\n");
  const auto r = run_command(fmt::format("timeout 120 {} run {} --out {}", SWARF_BINARY, dir / "c.toml", dir / "out"));
  expect_refused(r, "mesh.origin");
}

// Sets the first entry of the dataset (of doubles) of an HDF5 file to 'value'.
void spoil_first_entry(const std::string& path, const std::string& dataset, double value) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  std::vector<double> a(std::size_t(H5Sget_simple_extent_npoints(space)));
  ASSERT_FALSE(a.empty()) << dataset;
  ASSERT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.data()), 0) << dataset;
  a[0] = value;
  ASSERT_GE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.data()), 0) << dataset;
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
}

TEST(BadInput, ACheckpointWithANaNTimeOrStateOrAnOutputTimeThatCannotAdvanceIsRefused) {
  TempDir dir("bad_ckpt");
  // (orientations written: the bar's particles cannot turn, so without them its checkpoint holds
  // no rotation arrays to spoil)
  const auto a = run_bar(dir, "--set output.checkpoint_every=20 --set output.orientations=true");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  // Each spoilt copy of the checkpoint: the dataset, its new first entry, the words refused.
  // (A NaN position trapped in the first step; a next row time of -1e300 hung the run loop,
  // which steps it past the time by the interval; an angular acceleration of -1e300, finite,
  // overflowed the first rotation update: all found by the checkpoint fuzzer.)
  const std::vector<std::tuple<std::string, double, std::string>> spoilt = {
      {"/sim/time", NAN, "'/sim/time' entry 0 = nan"},
      {"/sim/particles/position", NAN, "'/sim/particles/position' entry 0 = nan"},
      {"/sim/rods/stress", HUGE_VAL, "'/sim/rods/stress' entry 0 = inf"},
      {"/sim/particles/omega_dot", -1e300,
       "'/sim/particles/omega_dot' entry 0 = -1e+300 is not a finite number within +-1e+50"},
      {"/run/loop/next_row_s", -1e300, "next output times -1e+300 s (row)"},
      // (a step of 1 s, beyond the step control's range; the contact list's build positions
      // at 1e289 m, which did overflow the skin check, are the checkpoint fuzzer's input
      // contact_build_1e289 in tests/fuzz/regressions/: this bar has no contacts)
      {"/sim/dt", 1.0, "state field 'dt' = 1 s"}};
  for (const auto& [dataset, value, word] : spoilt) {
    std::filesystem::copy_file(dir / "out/checkpoint.h5", dir / "spoilt.h5",
                               std::filesystem::copy_options::overwrite_existing);
    spoil_first_entry(dir / "spoilt.h5", dataset, value);
    expect_refused(run_command(fmt::format("timeout 120 {} run --restart {}", SWARF_BINARY, dir / "spoilt.h5")), word);
  }
}

// A run holds the accumulated plastic strain's arrays only where an output field needs them, so
// its checkpoint holds them only then: a restart that asks for PEEQ from such a checkpoint would
// start it at 0 mid-run, and is refused by name; with the field from the start it continues.
TEST(BadInput, ARestartThatAddsPeeqToACheckpointWithoutItIsRefused) {
  TempDir dir("restart_peeq");
  for (const char* fields : {"[]", "[\"peeq\"]"}) {
    const auto a = run_bar(dir, fmt::format("--set output.checkpoint_at_end=true --set 'output.fields={}'", fields));
    ASSERT_EQ(a.exit_code, 0) << a.output;
    const auto r = run_command(fmt::format(
        "timeout 120 {} run --restart {} --out {} --set integrator.end_time=4e-6 --set 'output.fields=[\"peeq\"]'",
        SWARF_BINARY, dir / "out/checkpoint.h5", dir / "again"));
    if (std::string(fields) == "[]")
      expect_refused(r, "may not add 'peeq'");
    else
      EXPECT_EQ(r.exit_code, 0) << r.output;
  }
}

// A checkpoint written before the particles' plastic work was kept (2026-12-08) holds PEEQ but not
// it: a restart would start it at 0 mid-run, and is refused by name (the dataset is deleted from a
// fresh checkpoint to make such a file).
TEST(BadInput, ARestartFromACheckpointWithoutThePlasticWorkIsRefused) {
  TempDir dir("restart_plastic_work");
  const auto a = run_bar(dir, "--set output.checkpoint_at_end=true");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const std::string old = dir / "old.h5";
  std::filesystem::copy_file(dir / "out/checkpoint.h5", old, std::filesystem::copy_options::overwrite_existing);
  const hid_t f = H5Fopen(old.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  ASSERT_GE(H5Ldelete(f, "/sim/particles/plastic_work", H5P_DEFAULT), 0);
  H5Fclose(f);
  expect_refused(run_command(fmt::format("timeout 120 {} run --restart {} --out {} --set integrator.end_time=4e-6",
                                         SWARF_BINARY, old, dir / "again")),
                 "not the particles' plastic work");
  // The checkpoint as written restarts.
  const auto r = run_command(fmt::format("timeout 120 {} run --restart {} --out {} --set integrator.end_time=4e-6",
                                         SWARF_BINARY, dir / "out/checkpoint.h5", dir / "again2"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// A path the system cannot even look at (a name too long): std::filesystem's throwing calls
// escaped as an unexplained exception (the study-file fuzzer, through a study's case path).
TEST(BadInput, APathTooLongIsNamedNotThrownAsAFilesystemError) {
  const std::string long_path = std::string(300, 'a') + "/" + std::string(300, 'b') + ".toml";
  const std::string c = message_of([&] { load_case(long_path, {}); });
  EXPECT_NE(c.find("case file '" + long_path + "': File name too long"), std::string::npos) << c;
  const std::string m = message_of([&] {
    parse_case(
        "[[particle]]\nposition = [0.0, 0.0, 0.0]\nradius = 1e-3\n[contact]\n[[mesh]]\nname = \"m\"\nfile = "
        "\"" +
            long_path + "\"\n[integrator]\nend_time = 1e-4\n",
        "c.toml", {});
  });
  EXPECT_NE(m.find("key 'mesh.file'"), std::string::npos) << m;
  EXPECT_NE(m.find("File name too long"), std::string::npos) << m;
}

// A checkpoint holds the case text it was run with; an error in that text used to be named
// as if it were in the case file (which may have changed since): it names the checkpoint now.
TEST(BadInput, ABadCaseStoredInACheckpointIsBlamedOnTheCheckpoint) {
  TempDir dir("bad_ckpt_case");
  {
    H5File f(dir / "c.h5", H5File::Mode::Create);
    f.write_attribute("format", 3.0);
    f.write_attribute("case_toml", std::string(kBar) + "[environment]\ngravty = [0.0, 0.0, -9.81]\n");
    f.write_attribute("case_source", dir / "bar.toml");
    f.write_attribute("case_directory", dir.str());
    f.write_attribute("case_overrides", std::string());
    f.write_attribute("time_s", 0.0);
    f.write_attribute("steps", 0.0);
    f.close();
  }
  const auto r = run_command(fmt::format("timeout 120 {} run --restart {}", SWARF_BINARY, dir / "c.h5"));
  expect_refused(r, "environment.gravty");
  EXPECT_NE(r.output.find("--restart " + dir / "c.h5" + ": the case stored in the checkpoint"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// SIGTERM in the middle of the default cut: the run finishes its step, writes a checkpoint
// (checkpoints are on), says so and exits 143, leaving no summary.json; the restart then
// completes it with the very series the uninterrupted run writes (the golden reference).
TEST(Signals, SigtermEndsARunBetweenStepsWithACheckpointAndTheRestartCompletesIt) {
#if !defined(__FMA__) || defined(SWARF_SANITIZE_BUILD)
  GTEST_SKIP() << "the reference was written by a native Release build with fused multiply-adds";
#endif
  test::TempDir dir("sigterm");
  const std::string out = dir / "cut";
  const std::string script = fmt::format(
      "{} run {} --out {} --threads 1 --set integrator.end_time=3e-5 --set output.plots=false --set output.vtk=false "
      "--set output.checkpoint_every=200 > {} 2>&1 & pid=$!; "
      "n=0; while [ $(cat {}/series.csv.part 2>/dev/null | wc -l) -lt 12 ] && [ $n -lt 2400 ]; do sleep 0.05; "
      "n=$((n+1)); done; kill -TERM $pid; wait $pid; echo \"exit=$?\"",
      SWARF_BINARY, test::linear_cut_case(), out, dir / "log", out);
  const auto r = test::run_command("bash -c '" + script + "'");
  const std::string log = test::read_file(dir / "log");
  ASSERT_NE(r.output.find("exit=143"), std::string::npos) << r.output << log;
  EXPECT_NE(log.find("interrupted by SIGTERM"), std::string::npos) << log;
  EXPECT_NE(log.find("checkpoint written"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(out + "/summary.json"));
  EXPECT_FALSE(std::filesystem::exists(out + "/series.csv"));  // (still .part: incomplete)
  const auto b = test::run_command(fmt::format("{} run --restart {}/checkpoint.h5 --threads 1", SWARF_BINARY, out));
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_EQ(test::read_file(out + "/series.csv"),
            test::read_file(std::string(SWARF_SOURCE_DIR) + "/tests/data/golden/linear_cut_3e-5s_series.csv"));
}

// SIGKILL cannot be caught: a run killed at any moment must leave either no checkpoint or a
// whole one (a kill while one is written leaves its .part, never a broken checkpoint.h5),
// and continuing from whatever is left, killed again and again, must end with the very series
// the uninterrupted run writes. Here the default cut is killed at three points (after 6, 14
// and 22 of its 31 series rows, a checkpoint every 200 of its 4,042 steps; each point lands
// somewhere between two checkpoints, or on one being written), each time continued from the
// checkpoint the kill left, and then run to its end.
TEST(Signals, ARunKilledAtSeveralPointsAndRestartedEachTimeEndsBitIdentical) {
#if !defined(__FMA__) || defined(SWARF_SANITIZE_BUILD)
  GTEST_SKIP() << "the reference was written by a native Release build with fused multiply-adds";
#endif
  test::TempDir dir("sigkill");
  const std::string out = dir / "cut";
  // kill_at ROWS: waits until series.csv.part has ROWS lines (header included), then SIGKILL;
  // prints what the kill left.
  const std::string script = fmt::format(
      "kill_at() {{ n=0; while [ $(cat {1}/series.csv.part 2>/dev/null | wc -l) -lt $1 ] && [ $n -lt 6000 ]; do "
      "sleep 0.02; n=$((n+1)); done; kill -KILL $pid; wait $pid; echo \"killed=$? rows=$(cat {1}/series.csv.part | "
      "wc -l) checkpoint=$([ -e {1}/checkpoint.h5 ] && echo yes || echo no)\"; }}; "
      "{0} run {2} --out {1} --threads 1 --set integrator.end_time=3e-5 --set output.plots=false "
      "--set output.vtk=false --set output.checkpoint_every=200 > {3}/log0 2>&1 & pid=$!; kill_at 7; "
      "for k in 1 2; do {0} run --restart {1}/checkpoint.h5 --threads 1 > {3}/log$k 2>&1 & pid=$!; "
      "kill_at $((7 + 8 * k)); done; "
      "{0} run --restart {1}/checkpoint.h5 --threads 1 > {3}/log3 2>&1; echo \"last=$?\"",
      SWARF_BINARY, out, test::linear_cut_case(), dir.str());
  const auto r = test::run_command("bash -c '" + script + "'");
  std::string logs;
  for (int k = 0; k < 4; ++k) logs += test::read_file(dir / fmt::format("log{}", k));
  // Three kills, each of a run still going (137 = 128 + SIGKILL), each after a checkpoint.
  std::size_t kills = 0;
  for (std::size_t at = r.output.find("killed=137"); at != std::string::npos; at = r.output.find("killed=137", at + 1))
    ++kills;
  EXPECT_EQ(kills, 3u) << r.output << logs;
  EXPECT_EQ(r.output.find("checkpoint=no"), std::string::npos) << r.output;
  ASSERT_NE(r.output.find("last=0"), std::string::npos) << r.output << logs;
  EXPECT_EQ(test::read_file(out + "/series.csv"),
            test::read_file(std::string(SWARF_SOURCE_DIR) + "/tests/data/golden/linear_cut_3e-5s_series.csv"));
}

// SIGINT (Ctrl-C) as SIGTERM, with exit code 130; with checkpoints off the run says it is lost.
TEST(Signals, SigintEndsARunWithExitCode130AndSaysWhatIsLeft) {
  test::TempDir dir("sigint");
  const std::string out = dir / "cut";
  const std::string script = fmt::format(
      "{} run {} --out {} --threads 1 --set integrator.end_time=3e-5 --set output.plots=false --set output.vtk=false "
      "> {} 2>&1 & pid=$!; n=0; while [ $(cat {}/series.csv.part 2>/dev/null | wc -l) -lt 3 ] && [ $n -lt 2400 ]; do "
      "sleep 0.05; n=$((n+1)); done; kill -INT $pid; wait $pid; echo \"exit=$?\"",
      SWARF_BINARY, test::linear_cut_case(), out, dir / "log", out);
  const auto r = test::run_command("bash -c '" + script + "'");
  const std::string log = test::read_file(dir / "log");
  EXPECT_NE(r.output.find("exit=130"), std::string::npos) << r.output << log;
  EXPECT_NE(log.find("interrupted by SIGINT"), std::string::npos) << log;
  EXPECT_NE(log.find("no checkpoint"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(out + "/summary.json"));
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// A tool at 1e6 m/s jumped past the block in one step and reported a finished cut with no
// force. A mesh may now move no further in a step than a particle may: the explicit step
// stops, the Newmark step shrinks until dt_min and then stops, both naming the mesh. (1e6 m/s
// is now refused by mesh.velocity's range, 10 km/s: the limit of a step is lowered instead.)
TEST(BadInput, AMeshThatWouldJumpPastTheParticlesInOneStepStopsTheRun) {
  test::TempDir dir("fast_tool");
  for (const char* scheme : {"verlet", "newmark"}) {
    const auto r = run_command(
        fmt::format("timeout 120 {} run {} --out {} --threads 1 --set mesh.0.velocity=[1e4,0,0] --set "
                    "integrator.max_step_displacement=1e-3 "
                    "--set integrator.end_time=3e-6 "
                    "--set integrator.scheme='\"{}\"' --set output.plots=false --set output.vtk=false",
                    SWARF_BINARY, test::linear_cut_case(), dir / "cut", scheme));
    EXPECT_EQ(r.exit_code, 3) << scheme << "\n" << r.output;
    EXPECT_NE(r.output.find("mesh 'tool' moves"), std::string::npos) << scheme << "\n" << r.output;
  }
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// Two runs into one --out left one's summary beside the other's series: the second is now
// refused while the first runs, and a directory whose run has ended (even by a kill) is free.
TEST(BadInput, ASecondRunIntoADirectoryThatARunIsWritingIsRefused) {
  test::TempDir dir("lock");
  const std::string out = dir / "cut";
  const std::string script = fmt::format(
      "{0} run {2} --out {1} --threads 1 --set integrator.end_time=3e-4 --set output.plots=false --set "
      "output.vtk=false "
      "> /dev/null 2>&1 & pid=$!; n=0; while [ ! -e {1}/series.csv.part ] && [ $n -lt 2400 ]; do sleep 0.05; "
      "n=$((n+1)); done; {0} run --out {1} --set integrator.end_time=1e-6; echo \"second=$?\"; kill -KILL $pid; "
      "wait $pid; {0} run --out {1} --set integrator.end_time=1e-7 --set output.plots=false > /dev/null 2>&1; "
      "echo \"third=$?\"",
      SWARF_BINARY, out, test::linear_cut_case());
  const auto r = test::run_command("bash -c '" + script + "'");
  EXPECT_NE(r.output.find("second=2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("another swarf run"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("third=0"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// Messages that blamed the wrong thing: a misspelt key in [[group]] or [[mesh]] was blamed on
// a missing key, a directory read as an empty case, a huge lattice ended in a bare
// std::bad_alloc, an unknown command was "a subcommand is required".
TEST(BadInput, MessagesNameWhatIsActuallyWrong) {
  TempDir dir("messages");
  write_file(dir / "g.toml", std::string(kBar) + "[[group]]\nname = \"x\"\nsides = \"z-\"\n");
  write_file(dir / "m.toml", std::string(kBar) +
                                 "[[mesh]]\nname = \"t\"\nrake = 10.0\nwidth = 1e-3\nface_length = 1e-3\n"
                                 "[contact]\n");
  std::filesystem::create_directories(dir / "d.toml");
  write_file(dir / "md.toml", std::string(kBar) + "[[mesh]]\nname = \"w\"\nfile = \"d.toml\"\n[contact]\n");
  auto run = [&](const std::string& args) {
    return run_command(fmt::format("timeout 120 {} {} --out {}", SWARF_BINARY, args, dir / "out"));
  };
  expect_refused(run("run " + dir / "g.toml"), "unknown key 'group.sides'");
  expect_refused(run("run " + dir / "m.toml"), "unknown key 'mesh.rake'");
  expect_refused(run("run " + dir / "d.toml"), "is a directory");
  expect_refused(run("run " + dir / "md.toml"), "is a directory, not a mesh file");  // (was basic_filebuf::underflow)
  expect_refused(run("run --set workpiece.cells=[1000,1000,400]"), "workpiece.cells");
  // (the Newton solver's vectors and tangents are counted: the estimate says which solver)
  expect_refused(run("run --set workpiece.cells=[1000,1000,400] --set integrator.scheme='\"newmark\"' "
                     "--set integrator.solver='\"newton\"'"),
                 "with integrator.solver = \"newton\"");
  const auto r = run_command(fmt::format("{} frob", SWARF_BINARY));
  expect_refused(r, "unknown command 'frob'");
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// A small tmpfs that fills up during the run (root only: mount; skipped otherwise).
class FullDisk {
 public:
  FullDisk(const std::string& dir, const char* size) : dir_(dir) {
    std::filesystem::create_directories(dir);
    ok_ = ::geteuid() == 0 &&
          std::system(fmt::format("mount -t tmpfs -o size={} tmpfs {} 2>/dev/null", size, dir).c_str()) == 0;
  }
  ~FullDisk() {
    if (ok_) [[maybe_unused]]
      const int rc = std::system(fmt::format("umount {}", dir_).c_str());
  }
  bool ok() const { return ok_; }

 private:
  std::string dir_;
  bool ok_ = false;
};

// On a full disk a failed write used to be renamed into place (a good checkpoint replaced by
// one that does not open) or to crash at HDF5's close. Now the run stops with exit code 1
// naming the file, and the last good checkpoint stays (it opens and holds its step).
TEST(DiskFull, AFailedCheckpointNeverReplacesTheLastGoodOne) {
  test::TempDir dir("diskfull");
  FullDisk disk(dir / "tiny", "5m");
  if (!disk.ok()) GTEST_SKIP() << "needs root to mount a small tmpfs";
  const auto r = run_command(fmt::format(
      "timeout 300 {} run {} --out {} --threads 1 --set integrator.end_time=3e-5 --set output.checkpoint_every=300 "
      "--set output.vtk=false --set output.plots=false",
      SWARF_BINARY, test::linear_cut_case(), dir / "tiny/cut"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("disk full"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "tiny/cut/summary.json"));
  ASSERT_TRUE(std::filesystem::exists(dir / "tiny/cut/checkpoint.h5")) << r.output;
  H5File ck(dir / "tiny/cut/checkpoint.h5", H5File::Mode::Read);  // (throws if it does not open)
  std::size_t rows = 0, cols = 0;
  const auto steps = ck.read_ints("/sim/stats/accepted", rows, cols);
  ASSERT_EQ(steps.size(), 1u);
  EXPECT_EQ(steps[0] % 300, 0);
  EXPECT_GT(steps[0], 0);
}

// The same with frames: a frame that cannot be written stops the run and keeps its .part name.
TEST(DiskFull, AFrameThatCannotBeWrittenStopsTheRunAndIsNotRenamed) {
  test::TempDir dir("diskfull_frames");
  FullDisk disk(dir / "tiny", "3m");
  if (!disk.ok()) GTEST_SKIP() << "needs root to mount a small tmpfs";
  const auto r = run_command(fmt::format(
      "timeout 300 {} run {} --out {} --threads 1 --set integrator.end_time=3e-5 --set output.frame_interval=2e-6 "
      "--set output.plots=false",
      SWARF_BINARY, test::linear_cut_case(), dir / "tiny/cut"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("cannot write VTK file"), std::string::npos) << r.output;
  for (const auto& e : std::filesystem::directory_iterator(dir / "tiny/cut/frames")) {
    const std::string name = e.path().filename().string();
    if (name.find(".part") != std::string::npos) continue;
    // Every file under its final name is complete: VTK's XML ends with its closing tag.
    const std::string text = test::read_file(e.path().string());
    EXPECT_NE(text.rfind("</VTKFile>"), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// A study used to wait for ever on a case that hung; case_time_limit stops a case that runs
// longer (SIGTERM: it ends after its step) and records why, and the study goes on.
TEST(BadInput, AStudyCaseLongerThanItsTimeLimitIsStoppedAndRecorded) {
  TempDir dir("case_limit");
  write_file(dir / "s.toml", fmt::format("base = \"{}/validation/cutting/linear_cut.toml\"\ncase_time_limit = 1.0\n"
                                         "[set]\n\"output.plots\" = false\n\"output.vtk\" = false\n"
                                         "[grid]\n\"integrator.end_time\" = [3e-4]\n",
                                         SWARF_SOURCE_DIR));
  const auto r = run_command(
      fmt::format("timeout 120 {} sweep {} --out {} --threads 1", SWARF_BINARY, dir / "s.toml", dir / "st"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const std::string status = test::read_file(dir / "st/cases/0000/sweep_status.json");
  EXPECT_NE(status.find("case_time_limit"), std::string::npos) << status << r.output;
  EXPECT_NE(status.find("143"), std::string::npos) << status;
  write_file(dir / "bad.toml", "base = \"x.toml\"\ncase_time_limit = -1\n[grid]\n\"a.b\" = [1]\n");
  expect_refused(run_command(fmt::format("{} sweep {} --out {}", SWARF_BINARY, dir / "bad.toml", dir / "st2")),
                 "case_time_limit");
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// An error message that could not be written to stderr aborted the program (fmt throws; the
// handler threw again). It must still end with the error's exit code.
TEST(BadInput, AClosedOrFullStderrDoesNotAbortTheProgram) {
  for (const char* redirect : {"2>&-", "2>/dev/full"}) {
    const auto r = run_command(fmt::format("{} run --set foo.bar=1 {}; echo \"exit=$?\"", SWARF_BINARY, redirect));
    EXPECT_NE(r.output.find("exit=2"), std::string::npos) << redirect << ": " << r.output;
  }
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// Explicit Verlet forced to 3 times its stable step used to complete the pulled bar with an
// energy error 1e3 times the work (rods breaking, the lattice gaining energy from nothing).
// The balance each series row computes now stops it, with exit code 3 and the numbers named;
// the same bar at its own step completes (the check does not fire on a good run).
TEST(BadInput, AnExplicitStepForcedBeyondItsStableSizeStopsWhenTheEnergyBalanceIsLost) {
  TempDir dir("energy_lost");
  const auto ok = run_bar(dir, "--set integrator.scheme='\"verlet\"'");
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  // The stable step as the set-up prints it: "stable step 1.325e-07 s".
  const std::size_t at = ok.output.find("stable step ");
  ASSERT_NE(at, std::string::npos) << ok.output;
  const double dt_stable = std::stod(ok.output.substr(at + 12));
  const auto r = run_bar(dir, fmt::format("--set integrator.scheme='\"verlet\"' --set integrator.dt={:.6g} "
                                          "--set integrator.allow_unstable_dt=true",
                                          3 * dt_stable));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  for (const char* word :
       {"energy balance lost at t = ", "energy error", "external work", "allow_unstable_dt", "integrator.dt_safety"})
    EXPECT_NE(r.output.find(word), std::string::npos) << "the message should name '" << word << "':\n" << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out/summary.json"));
}

// The bound itself: an error up to the larger of |work| and the energy held passes, beyond it
// (or NaN) stops; a body at rest (every term 0 J) passes.
TEST(EnergyCheck, StopsOnlyWhenTheErrorExceedsTheWorkAndTheEnergyHeld) {
  EnergyBalanceNow b;
  EXPECT_NO_THROW(check_energy_balance(b, 0.0));
  b.external_work = 2.0;
  b.kinetic = 0.5;
  b.elastic = 0.5;
  b.error = -kMaxEnergyErrorRatio * 2.0;
  EXPECT_NO_THROW(check_energy_balance(b, 1.0));
  b.error = -kMaxEnergyErrorRatio * 2.0 * (1 + 1e-9);
  EXPECT_THROW(check_energy_balance(b, 1.0), SimulationError);
  b.external_work = -0.1;  // (negative work: its size counts) and energy held 3 J
  b.contact = 2.0;
  b.error = 2.9;
  EXPECT_NO_THROW(check_energy_balance(b, 1.0));
  b.error = 3.1;
  EXPECT_THROW(check_energy_balance(b, 1.0), SimulationError);
  b.error = std::nan("");
  EXPECT_THROW(check_energy_balance(b, 1.0), SimulationError);
  b.error = 3.1;
  std::string m = "(no error)";
  try {
    check_energy_balance(b, 2.5e-6);
  } catch (const SimulationError& e) {
    m = e.what();
  }
  EXPECT_NE(m.find("t = 2.5e-06 s"), std::string::npos) << m;
  EXPECT_NE(m.find("energy error 3.1 J"), std::string::npos) << m;
  EXPECT_NE(m.find("external work -0.1 J"), std::string::npos) << m;
}

}  // namespace
}  // namespace swarf

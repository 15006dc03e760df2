// Restart from checkpoints (bit-identical continuation), the short-cut run's progress, table
// and summary, and 'swarf post' reproducing the run's own analysis.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "io/h5file.h"
#include "study/hypre_amg.h"
#include "test_helpers.h"

namespace swarf {
namespace {

// A tiny orthogonal cut (288 particles): rods that yield and break, friction with history
// (Cundall-Strack springs), the Newmark step with its step control.
const char* kTinyCut = R"([workpiece]
cells = [6, 2, 3]
radius = 1e-4
[rod]
yield_strain = 1e-3
hardening_modulus = 2e10
tensile_strength = 3e8
[contact]
friction = 0.3
[[group]]
name = "base"
side = "z-"
[[mesh]]
name = "tool"
rake_angle = 10.0
width = 1.2e-3
face_length = 1e-3
origin = [-0.05e-3, 0.14e-3, 0.5e-3]
motion = "velocity"
velocity = [5.0, 0.0, 0.0]
[integrator]
scheme = "newmark"
end_time = 4e-5
[output]
plots = false
steady_from = 2e-5
series_interval = 1e-6
frame_interval = 1e-5
)";

std::vector<double> dataset(const std::string& file, const std::string& name) {
  H5File f(file, H5File::Mode::Read);
  std::size_t r = 0, c = 0;
  return f.read_doubles(name, r, c);
}

// Runs the case DIR/CASE into DIR/a with a checkpoint every 'every' steps on 'threads' threads
// and copies the last checkpoint (from the middle of the run) into DIR/b, as after moving it.
test::CommandResult run_and_keep_checkpoint(const test::TempDir& dir, const std::string& case_name, int every,
                                            int threads) {
  auto a = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / case_name) + " --out " + (dir / "a") +
                             " --set output.checkpoint_every=" + std::to_string(every) + " --threads " +
                             std::to_string(threads));
  if (a.exit_code == 0) {
    std::filesystem::create_directories(dir / "b");
    std::filesystem::copy_file(dir / "a/checkpoint.h5", dir / "b/checkpoint.h5");
  }
  return a;
}

// Continues DIR/b/checkpoint.h5 (in DIR/b) on 'threads' threads; returns the summaries of the
// uninterrupted run (DIR/a) and of the continued one, and checks that the two series agree.
std::pair<nlohmann::json, nlohmann::json> continue_on(const test::TempDir& dir, int threads) {
  auto b = test::run_command(std::string(SWARF_BINARY) + " run --restart " + (dir / "b/checkpoint.h5") + " --threads " +
                             std::to_string(threads));
  EXPECT_EQ(b.exit_code, 0) << b.output;
  EXPECT_EQ(test::read_file(dir / "a/series.csv"), test::read_file(dir / "b/series.csv"));
  return {nlohmann::json::parse(test::read_file(dir / "a/summary.json")),
          nlohmann::json::parse(test::read_file(dir / "b/summary.json"))};
}

TEST(Restart, ContinuesBitIdenticallyAndWhateverTheThreads) {
  test::TempDir dir("restart");
  test::write_file(dir / "c.toml", kTinyCut);
  const std::string bin = SWARF_BINARY;
  auto a = run_and_keep_checkpoint(dir, "c.toml", 300, 1);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  // Continue from the copy in its own directory (the default --out), with two threads, and
  // with a stale partial checkpoint lying around as a kill during a write would leave it.
  test::write_file(dir / "b/checkpoint.h5.part", "garbage from an interrupted write");
  H5File ck(dir / "b/checkpoint.h5", H5File::Mode::Read);
  const double ck_steps = ck.read_double_attribute("steps");
  const auto sa = nlohmann::json::parse(test::read_file(dir / "a/summary.json"));
  ASSERT_GT(ck_steps, 0.0);
  ASSERT_LT(ck_steps, sa["run"]["steps"].get<double>());
  auto b = test::run_command(bin + " run --restart " + (dir / "b/checkpoint.h5") + " --threads 2");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_NE(b.output.find("restarted from"), std::string::npos) << b.output;
  // Every series row (written before the checkpoint and after) and the final state agree bit for bit.
  EXPECT_EQ(test::read_file(dir / "a/series.csv"), test::read_file(dir / "b/series.csv"));
  for (const char* name : {"/particles/position", "/particles/velocity", "/bonds/plastic_shift", "/bonds/stress",
                           "/particles/broken_fraction"})
    EXPECT_EQ(dataset(dir / "a/results.h5", name), dataset(dir / "b/results.h5", name)) << name;
  const auto sb = nlohmann::json::parse(test::read_file(dir / "b/summary.json"));
  EXPECT_EQ(sa["state_hash"], sb["state_hash"]);  // every field of the final state
  EXPECT_EQ(sa["state_hash"].get<std::string>().size(), 16u);
  EXPECT_EQ(sa["results"], sb["results"]);
  EXPECT_EQ(sa["chip"], sb["chip"]);
  EXPECT_EQ(sa["cutting"], sb["cutting"]);
  EXPECT_GT(sa["results"]["broken_rods"].get<double>(), 0.0);  // breakage crossed the restart
  // The ParaView series goes on from the checkpoint's frames.
  EXPECT_NE(test::read_file(dir / "b/particles.pvd").find("particles_00004.vtu"), std::string::npos);
}

// A disordered workpiece (workpiece.disorder_seed) is rebuilt from the checkpoint's case with
// the same jitter: the continued run, on 2 threads, ends in the uninterrupted run's state.
TEST(Restart, ADisorderedWorkpieceContinuesBitIdentically) {
  test::TempDir dir("restart_disorder");
  const std::string head = "[workpiece]\n";
  test::write_file(dir / "c.toml", head + "disorder_seed = 4\nposition_jitter = 0.05\n" +
                                       (std::string(kTinyCut).substr(head.size()) + "vtk = false\n"));
  auto a = run_and_keep_checkpoint(dir, "c.toml", 300, 1);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  ASSERT_NE(a.output.find("disorder: seed 4"), std::string::npos) << a.output;
  const auto [sa, sb] = continue_on(dir, 2);
  EXPECT_EQ(sa["state_hash"], sb["state_hash"]);
  EXPECT_EQ(sb["derived"]["disorder_seed"], 4);
}

// Rods formed during the run (bond formation with neighbour exchange) are part of the state: a
// run restarted after formations, on 2 threads, ends in the uninterrupted run's state.
TEST(Restart, ACutThatFormsAndExchangesRodsContinuesBitIdentically) {
  test::TempDir dir("restart_formation");
  const std::string cut = kTinyCut, rod = "[rod]\n";
  const std::size_t at = cut.find(rod) + rod.size();
  test::write_file(dir / "c.toml", cut.substr(0, at) + "bond_overlap = 0.0\nneighbour_exchange = true\n" +
                                       cut.substr(at) + "vtk = false\n");
  auto a = run_and_keep_checkpoint(dir, "c.toml", 300, 1);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const auto [sa, sb] = continue_on(dir, 2);
  ASSERT_GT(sa["results"]["formed_rods"].get<double>(), 0.0);  // (else the test proves nothing)
  EXPECT_EQ(sa["state_hash"], sb["state_hash"]);
  EXPECT_EQ(sa["results"], sb["results"]);
}

// 'swarf bench' takes a checkpoint as its scene: the stored case, continued from the stored
// state, and only the steps after it are counted (a late part of a cut timed alone).
TEST(Restart, BenchContinuesACheckpointAndCountsOnlyItsOwnSteps) {
  test::TempDir dir("bench_checkpoint");
  test::write_file(dir / "c.toml", std::string(kTinyCut) + "vtk = false\n");
  auto a = run_and_keep_checkpoint(dir, "c.toml", 300, 1);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  auto b = test::run_command(std::string(SWARF_BINARY) + " bench " + (dir / "b/checkpoint.h5") +
                             " --steps 7 --threads 1 --repeats 1 --stages");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  // The row: | CHECKPOINT | scheme | particles | rods | steps | force evaluations | Newton
  // iterations | CG iterations | ...
  auto row_cells = [](const std::string& out) {
    std::vector<std::string> cells;
    const auto row = out.find("| CHECKPOINT | ");
    if (row == std::string::npos) return cells;
    std::size_t at = row + 1;
    for (int c = 0; c < 8; ++c) {
      const auto bar = out.find('|', at);
      cells.push_back(out.substr(at, bar - at));
      at = bar + 1;
    }
    return cells;
  };
  const auto cells = row_cells(b.output);
  ASSERT_EQ(cells.size(), 8u) << b.output;
  EXPECT_EQ(cells[4], " 7 ") << b.output;
  EXPECT_GE(std::stoll(cells[5]), 7) << b.output;  // (one evaluation per step at least)
  EXPECT_EQ(cells[6], " - ") << b.output;          // (no Newton iterations with this scheme)
  // The same state continued by the Newton solver: its iterations are counted from the
  // stored state on (at least one per step, and one CG iteration per Newton iteration).
  const auto newton_bench = [&](const std::string& extra) {
    return test::run_command(std::string(SWARF_BINARY) + " bench " + (dir / "b/checkpoint.h5") +
                             " --steps 3 --threads 1 --repeats 1 --set integrator.scheme='\"newmark\"'"
                             " --set integrator.solver='\"newton\"'" +
                             extra);
  };
  auto nb = newton_bench("");
  ASSERT_EQ(nb.exit_code, 0) << nb.output;
  const auto ncells = row_cells(nb.output);
  ASSERT_EQ(ncells.size(), 8u) << nb.output;
  EXPECT_EQ(ncells[1], " newmark ") << nb.output;
  const long long newton = std::stoll(ncells[6]), cg = std::stoll(ncells[7]);
  EXPECT_GE(newton, 3) << nb.output;
  EXPECT_GE(cg, newton) << nb.output;
  EXPECT_LT(newton, 3 * 25) << nb.output;  // (a sanity bound: max_iterations = 25 per try, one try per step)
  // hypre's BoomerAMG in place of the block-Jacobi: the same counts' columns and a line with its
  // hierarchies; on a scene Newton does not solve the option is refused by name.
  if (HypreAmg::available()) {
    auto amg = newton_bench(" --preconditioner amg");
    ASSERT_EQ(amg.exit_code, 0) << amg.output;
    const auto acells = row_cells(amg.output);
    ASSERT_EQ(acells.size(), 8u) << amg.output;
    EXPECT_GE(std::stoll(acells[7]), std::stoll(acells[6])) << amg.output;
    EXPECT_NE(amg.output.find("BoomerAMG: " + std::to_string(std::stoll(acells[6])) + " hierarchies"),
              std::string::npos)
        << amg.output;  // (one per Newton iteration at --amg-refresh 1)
  }
  auto verlet_amg = test::run_command(std::string(SWARF_BINARY) + " bench " + (dir / "b/checkpoint.h5") +
                                      " --steps 1 --threads 1 --repeats 1 --preconditioner amg");
  EXPECT_EQ(verlet_amg.exit_code, 2) << verlet_amg.output;
  EXPECT_NE(verlet_amg.output.find("--preconditioner amg"), std::string::npos) << verlet_amg.output;
  auto bad = test::run_command(std::string(SWARF_BINARY) + " bench " + (dir / "missing.h5") + " --steps 1");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("missing.h5"), std::string::npos) << bad.output;
}

// The bench's last column, the parallel efficiency, is (t_first x threads_first) / (t x
// threads) of the printed medians: 1.00 in the scene's first row. The check recomputes it from
// the printed times (3 decimals) and allows their rounding: a relative 0.5e-3 / t each, and the
// column's own 0.005.
TEST(Restart, BenchPrintsTheParallelEfficiencyOfItsMedians) {
  test::TempDir dir("bench_efficiency");
  test::write_file(dir / "c.toml", std::string(kTinyCut) + "vtk = false\n");
  auto b = test::run_command(std::string(SWARF_BINARY) + " bench " + (dir / "c.toml") +
                             " --steps 200 --threads 1,2 --repeats 1");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  ASSERT_NE(b.output.find("| parallel efficiency |"), std::string::npos) << b.output;
  std::vector<double> seconds, threads, efficiency;
  std::istringstream lines(b.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| C |", 0) != 0) continue;
    std::vector<std::string> cells;
    for (std::size_t at = 1, bar; (bar = line.find('|', at)) != std::string::npos; at = bar + 1)
      cells.push_back(line.substr(at, bar - at));
    ASSERT_EQ(cells.size(), 15u) << line;
    threads.push_back(std::stod(cells[8]));
    seconds.push_back(std::stod(cells[9]));  // (the median, before " (min-max)")
    efficiency.push_back(std::stod(cells[14]));
  }
  ASSERT_EQ(efficiency.size(), 2u) << b.output;
  EXPECT_EQ(efficiency[0], 1.0);
  ASSERT_GT(seconds[1], 0.0) << b.output;
  const double expected = seconds[0] * threads[0] / (seconds[1] * threads[1]);
  const double rounding = expected * (0.5e-3 / seconds[0] + 0.5e-3 / seconds[1]) + 0.005;
  EXPECT_NEAR(efficiency[1], expected, rounding) << b.output;
}

// A restart into another directory (--out) brings the frames written before the checkpoint
// along: every file particles.pvd lists is there, the earlier frames are copies and the later
// ones are computed again, bit for bit as the uninterrupted run wrote them.
TEST(Restart, IntoAnotherDirectoryTheSeriesOfFramesIsComplete) {
  test::TempDir dir("restart_frames");
  test::write_file(dir / "c.toml", kTinyCut);
  auto a = run_and_keep_checkpoint(dir, "c.toml", 300, 2);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  auto c = test::run_command(std::string(SWARF_BINARY) + " run --restart " + (dir / "a/checkpoint.h5") + " --out " +
                             (dir / "c"));
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_EQ(c.output.find("warning"), std::string::npos) << c.output;
  const std::string pvd = test::read_file(dir / "c/particles.pvd");
  const std::regex file_re("file=\"([^\"]+)\"");
  int listed = 0;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), file_re); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1].str();
    ASSERT_TRUE(std::filesystem::exists(dir / ("c/" + name))) << name;
    if (name.rfind("frames/", 0) == 0) {
      EXPECT_EQ(test::read_file(dir / ("a/" + name)), test::read_file(dir / ("c/" + name))) << name;
    }
    ++listed;
  }
  EXPECT_GE(listed, 3 * 5);  // particles, rods and the tool for frames 0 to 4 at least
  // A restart whose earlier frames are nowhere (the checkpoint alone was copied) says so.
  auto b = test::run_command(std::string(SWARF_BINARY) + " run --restart " + (dir / "b/checkpoint.h5"));
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_NE(b.output.find("frames written before the checkpoint are neither in"), std::string::npos) << b.output;
}

// The explicit scheme commits the friction histories in its only evaluation per step, and
// marks the contacts to end by their touch flags: a restart must carry both. A small granular
// gas (216 spheres with pseudo-random velocities) in a box of triangle walls, with friction.
TEST(Restart, ExplicitGranularGasContinuesBitIdentically) {
  test::TempDir dir("restart_gas");
  test::write_file(dir / "gas.toml", test::granular_gas_case(dir));
  const std::string bin = SWARF_BINARY;
  auto a = run_and_keep_checkpoint(dir, "gas.toml", 1000, 2);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  auto b = test::run_command(bin + " run --restart " + (dir / "b/checkpoint.h5") + " --threads 1");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  const std::string series = test::read_file(dir / "a/series.csv");
  EXPECT_EQ(series, test::read_file(dir / "b/series.csv"));
  for (const char* name : {"/particles/position", "/particles/velocity"})
    EXPECT_EQ(dataset(dir / "a/results.h5", name), dataset(dir / "b/results.h5", name)) << name;
  // The gas collides (contacts touch before and after the checkpoint at step 2,000) and loses energy.
  const auto sa = nlohmann::json::parse(test::read_file(dir / "a/summary.json"));
  EXPECT_GT(sa["results"]["contact_work_J"].get<double>(), 0.0) << sa["results"].dump();
  const auto sb = nlohmann::json::parse(test::read_file(dir / "b/summary.json"));
  EXPECT_EQ(sa["state_hash"], sb["state_hash"]);  // the contact lists and histories too
}

// A membrane (issue 16): a clamped, pre-tensioned sheet under gravity with a sphere dropped on
// it, run on one thread with a checkpoint after the sphere has landed, continued on two threads:
// every series row and the final state agree bit for bit with the uninterrupted run (the sheet's
// rods, its clamp group and the sphere's contact history cross the checkpoint).
// Particles that come and go (issue 15: "restart bit-identity with bodies and inflow"): a stream
// from an [[inflow]] falls on a paddle on a hinge and leaves through an [[outflow]]. The
// checkpoint holds fewer particles than the case builds at the start of a continued run (none)
// and than the end; continued on 2 threads, the run ends in the uninterrupted run's state and
// writes the same series rows.
TEST(Restart, AnInflowOntoARigidBodyContinuesBitIdenticallyOnTwoThreads) {
  test::TempDir dir("restart_inflow");
  test::write_file(dir / "w.toml", R"([material]
density = 2500.0
[[inflow]]
box_min = [1e-3, -1.5e-3, 6e-3]
box_max = [4e-3, 1.5e-3, 8e-3]
rate = 20000.0
radius_min = 0.4e-3
radius_max = 0.5e-3
velocity = [0.0, 0.0, -2.0]
seed = 3
[[outflow]]
box_min = [-1.0, -1.0, -1.0]
box_max = [1.0, 1.0, -6e-3]
[contact]
youngs_modulus = 1e8
restitution = 0.5
friction = 0.3
[[mesh]]
name = "paddle"
box_size = [10e-3, 4e-3, 1e-3]
dynamics = "rigid_body"
density = 1000.0
rotation = "hinge"
hinge_axis = [0.0, 1.0, 0.0]
fixed = "xyz"
torque_damping = 1e-7
[environment]
gravity = [0.0, 0.0, -9.81]
[integrator]
scheme = "verlet"
dt = 5e-7
end_time = 12e-3
[output]
plots = false
vtk = false
series_interval = 2e-4
)");
  auto a = run_and_keep_checkpoint(dir, "w.toml", 12000, 1);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const auto [sa, sb] = continue_on(dir, 2);
  // (else the test proves nothing: particles were removed and the paddle turned)
  ASSERT_GT(sa["flows"]["outflow_removed"].get<double>(), 0.0);
  ASSERT_GT(sa["flows"]["inflow_created"].get<double>(), sa["flows"]["particles_at_end"].get<double>());
  EXPECT_EQ(sa["state_hash"], sb["state_hash"]);
  EXPECT_EQ(sa["flows"], sb["flows"]);
}

TEST(Restart, AMembraneWithAContactContinuesBitIdenticallyOnTwoThreads) {
  test::TempDir dir("restart_membrane");
  test::write_file(dir / "m.toml", R"([membrane]
length = 10e-3
width = 10e-3
radius = 0.25e-3
thickness = 0.5e-3
youngs_modulus = 5e6
density = 1200.0
pre_tension = 10.0
damping_ratio = 0.1
clamp_edges = true
[[particle]]
position = [5e-3, 5e-3, 1.1e-3]
velocity = [0.0, 0.0, -1.0]
radius = 0.8e-3
[material]
density = 1200.0
[contact]
youngs_modulus = 5e6
friction = 0.3
[environment]
gravity = [0.0, 0.0, -9.81]
[integrator]
end_time = 4e-3
[output]
plots = false
vtk = false
series_interval = 1e-4
)");
  auto a = run_and_keep_checkpoint(dir, "m.toml", 400, 1);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const auto [sa, sb] = continue_on(dir, 2);
  EXPECT_EQ(sa["state_hash"], sb["state_hash"]);
  EXPECT_GT(sa["results"]["contact_work_J"].get<double>(), 0.0) << sa["results"].dump();  // the sphere landed
  // The effective case records the sheet with its defaults and the free particles' density.
  const auto& e = sa["case_effective"];
  EXPECT_EQ(e["membrane"]["pre_tension"], 10.0) << e.dump();
  EXPECT_TRUE(e["membrane"].contains("poisson_ratio")) << e.dump();
  EXPECT_EQ(e["material"]["density"], 1200.0) << e.dump();
  H5File ck(dir / "b/checkpoint.h5", H5File::Mode::Read);
  EXPECT_GT(ck.read_double_attribute("steps"), 0.0);
}

// Contacts are found by lists with a skin; which candidates a list holds (a larger skin, more
// frequent or rarer rebuilds) must not change any result: every touching contact is in
// every list, and a candidate that does not touch contributes nothing. A tiny cut with a
// honed edge (many thin facets) run with two skins prints the same series bit for bit.
TEST(ContactLists, ResultsDoNotDependOnTheSkin) {
  test::TempDir dir("skin");
  std::string honed = kTinyCut;
  honed.replace(honed.find("rake_angle = 10.0"), 17, "rake_angle = 10.0\nedge_radius = 2e-5");
  test::write_file(dir / "c.toml", honed);
  const std::string bin = SWARF_BINARY;
  for (const char* skin : {"0.2", "0.9"}) {
    auto r = test::run_command(bin + " run " + (dir / "c.toml") + " --out " + (dir / skin) +
                               " --set contact.skin=" + skin + " --set output.vtk=false --threads 1");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  EXPECT_EQ(test::read_file(dir / "0.2/series.csv"), test::read_file(dir / "0.9/series.csv"));
  const auto s = nlohmann::json::parse(test::read_file(dir / "0.2/summary.json"));
  EXPECT_GT(s["results"]["broken_rods"].get<double>(), 0.0);  // the tool cut: contacts and breaks happened
}

TEST(Restart, RejectsACaseFileAndFilesThatAreNotCheckpoints) {
  test::TempDir dir("restart_bad");
  test::write_file(dir / "c.toml", kTinyCut);
  test::write_file(dir / "not.h5", "not an HDF5 file");
  const std::string bin = SWARF_BINARY;
  auto r = test::run_command(bin + " run " + (dir / "c.toml") + " --restart " + (dir / "not.h5"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no case file"), std::string::npos) << r.output;
  r = test::run_command(bin + " run --restart " + (dir / "not.h5"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not.h5"), std::string::npos) << r.output;
  r = test::run_command(bin + " run --restart " + (dir / "missing.h5"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST(ShortCut, ShowsProgressPrintsTheTableAndPostReproducesTheSummary) {
  test::TempDir dir("short_cut");
  test::write_file(dir / "c.toml", kTinyCut);
  const std::string bin = SWARF_BINARY;
  auto r = test::run_command(bin + " run " + (dir / "c.toml") + " --out " + (dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Progress on stderr: percent, simulated time, ETA; the result table on stdout.
  EXPECT_NE(r.output.find("[100.0%]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ETA"), std::string::npos) << r.output;
  for (const char* row : {"cutting force per width Fc/w", "thrust force per width Ft/w", "chip thickness",
                          "friction angle", "broken-rod fraction", "particles.pvd"})
    EXPECT_NE(r.output.find(row), std::string::npos) << row << "\n" << r.output;
  auto sum = nlohmann::json::parse(test::read_file(dir / "out/summary.json"));
  ASSERT_TRUE(sum.contains("cutting") && sum.contains("chip")) << sum.dump(2);
  for (const char* k :
       {"cutting_force_per_width_mean_N_per_m", "thrust_force_per_width_std_N_per_m", "width_m", "broken_fraction"})
    EXPECT_TRUE(sum["cutting"].contains(k)) << k;
  for (const char* k : {"depth_of_cut_m", "friction_angle_deg", "merchant_shear_angle_deg", "chip_particles"})
    EXPECT_TRUE(sum["chip"].contains(k)) << k;
  // The tool's travel is in the series (m): 5 m/s for 40 us = 0.2 mm at the end.
  const auto series = test::read_file(dir / "out/series.csv");
  ASSERT_NE(series.find("tool_travel"), std::string::npos);
  // The chip surface opens in VTK's own reader with the triangles the summary counts, and
  // the ParaView series lists it at the last time step.
  ASSERT_TRUE(sum["chip"].contains("surface_file")) << sum["chip"].dump(2);
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((dir / "out/chip_surface.vtp").c_str());
    reader->Update();
    ASSERT_NE(reader->GetOutput(), nullptr);
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPolys(), sum["chip"]["surface_triangles"].get<long long>());
    EXPECT_GT(sum["chip"]["surface_volume_m3"].get<double>(), 0.0);
    EXPECT_NE(test::read_file(dir / "out/particles.pvd").find("chip_surface.vtp"), std::string::npos);
  }
  // 'swarf post' recomputes the same analysis from the files alone.
  const auto before = sum;
  auto p = test::run_command(bin + " post " + (dir / "out"));
  ASSERT_EQ(p.exit_code, 0) << p.output;
  sum = nlohmann::json::parse(test::read_file(dir / "out/summary.json"));
  EXPECT_EQ(before["cutting"], sum["cutting"]);
  EXPECT_EQ(before["chip"], sum["chip"]);
  // ... and refuses a directory without a finished run.
  auto bad = test::run_command(bin + " post " + (dir / "nothing"));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("did not finish"), std::string::npos) << bad.output;
  // ... and a series.csv with a cell that is not a number (once read as 0), naming line, column and cell.
  std::string csv = test::read_file(dir / "out/series.csv");
  const auto eol = csv.find('\n', csv.find('\n') + 1);  // the end of the first data row
  const auto comma = csv.rfind(',', eol);
  csv.replace(comma + 1, eol - comma - 1, "12x");
  test::write_file(dir / "out/series.csv", csv);
  auto cell = test::run_command(bin + " post " + (dir / "out"));
  EXPECT_EQ(cell.exit_code, 2) << cell.output;
  EXPECT_NE(cell.output.find("line 2 column"), std::string::npos) << cell.output;
  EXPECT_NE(cell.output.find("= '12x' is not a number"), std::string::npos) << cell.output;
}

// A restart that extends: a run to t1 with a checkpoint at its end, continued with a later
// end_time, ends bit-identically to one run to t2 (verlet: no step is shortened), with the same
// series rows; a key other than the end time and the outputs is refused by name, and so is an
// end time before the checkpoint's.
TEST(Restart, ExtendsAFinishedRunBitIdenticallyToOneLongRun) {
  test::TempDir dir("restart_extend");
  test::write_file(dir / "c.toml", kTinyCut);
  const std::string bin = SWARF_BINARY, c = dir / "c.toml";
  const std::string common =
      " --set integrator.scheme='\"verlet\"' --set output.vtk=false --set output.steady_from=1e-5 "
      "--set output.series_interval=1e-6";
  auto whole = test::run_command(bin + " run " + c + " --out " + (dir / "whole") + common);
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  auto first = test::run_command(bin + " run " + c + " --out " + (dir / "part") + common +
                                 " --set integrator.end_time=2e-5 --set output.checkpoint_at_end=true");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto s1 = nlohmann::json::parse(test::read_file(dir / "part/summary.json"));
  H5File ck(dir / "part/checkpoint.h5", H5File::Mode::Read);
  EXPECT_EQ(ck.read_double_attribute("steps"), s1["run"]["steps"].get<double>()) << "a checkpoint of the last step";

  auto bad = test::run_command(bin + " run --restart " + (dir / "part/checkpoint.h5") + " --set rod.yield_strain=2e-3");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("'rod.yield_strain' cannot change on a restart"), std::string::npos) << bad.output;
  auto early = test::run_command(bin + " run --restart " + (dir / "part/checkpoint.h5") +
                                 " --set integrator.end_time=1e-5");
  EXPECT_EQ(early.exit_code, 2) << early.output;
  EXPECT_NE(early.output.find("lies before the checkpoint's time"), std::string::npos) << early.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "part/summary.json")) << "a refused restart deletes nothing";

  auto ext = test::run_command(bin + " run --restart " + (dir / "part/checkpoint.h5") +
                               " --set integrator.end_time=4e-5 --threads 2");
  ASSERT_EQ(ext.exit_code, 0) << ext.output;
  const auto sw = nlohmann::json::parse(test::read_file(dir / "whole/summary.json"));
  const auto se = nlohmann::json::parse(test::read_file(dir / "part/summary.json"));
  EXPECT_EQ(sw["state_hash"], se["state_hash"]);
  EXPECT_EQ(sw["run"]["steps"], se["run"]["steps"]);
  EXPECT_EQ(test::read_file(dir / "whole/series.csv"), test::read_file(dir / "part/series.csv"));
  EXPECT_EQ(sw["cutting"], se["cutting"]);
  EXPECT_EQ(se["case_effective"]["integrator"]["end_time"], 4e-5);
}

}  // namespace
}  // namespace swarf

// test_outputs.cpp: a short uniaxial run through the CLI writes its outputs completely
// (series, summary, HDF5, ParaView series readable by VTK's own reader, plots), and a run
// that blows up stops with a message and leaves no file that looks complete.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "app/plots.h"
#include "io/h5file.h"
#include "scenes/tiny_cut.h"
#include "scenes/tiny_uniaxial.h"
#include "swarf/core/errors.h"
#include "test_helpers.h"

namespace swarf {
namespace {

TEST(Outputs, ShortUniaxialRunWritesEverything) {
  test::TempDir dir("outputs");
  test::write_file(dir / "tiny.toml", test::kTinyUniaxial);
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "tiny.toml") + " --out " +
                                   (dir / "out") + " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("stable step"), std::string::npos);
  EXPECT_NE(r.output.find("100.0%"), std::string::npos) << "progress line on stderr";

  // series.csv: the named columns, one row per interval, time ascending.
  const std::string csv = test::read_file(dir / "out/series.csv");
  ASSERT_EQ(csv.rfind("time,strain,stress,stress_predicted,stress_midplane,step,dt,", 0), 0u) << csv.substr(0, 200);
  const long rows = std::count(csv.begin(), csv.end(), '\n') - 1;
  EXPECT_GE(rows, 1500);  // default interval end_time/2000, rounded to whole steps

  // summary.json: complete, with the derived quantities and the loop measurement.
  const auto sum = nlohmann::json::parse(test::read_file(dir / "out/summary.json"));
  EXPECT_EQ(sum["status"], "completed");
  EXPECT_EQ(sum["counts"]["particles"], 96);
  EXPECT_GT(sum["derived"]["dt_stable_s"].get<double>(), 0.0);
  EXPECT_TRUE(sum["uniaxial"].contains("measured"));
  EXPECT_EQ(sum["case"]["rod"]["yield_strain"], 1e-3);
  EXPECT_FALSE(std::filesystem::exists(dir / "out/summary.json.part"));

  // results.h5: the final state.
  H5File h5(dir / "out/results.h5", H5File::Mode::Read);
  std::size_t rows_h5 = 0, cols_h5 = 0;
  auto pos = h5.read_doubles("/particles/position", rows_h5, cols_h5);
  EXPECT_EQ(rows_h5, 96u);
  EXPECT_EQ(cols_h5, 3u);
  auto shift = h5.read_doubles("/bonds/plastic_shift", rows_h5, cols_h5);
  bool plastic = false;
  for (double s : shift) plastic = plastic || s != 0;
  EXPECT_TRUE(plastic) << "the path goes beyond yield";

  // particles.pvd: every file it lists exists and VTK's reader opens it with the arrays.
  const std::string pvd = test::read_file(dir / "out/particles.pvd");
  std::regex file_re("file=\"([^\"]+)\"");
  int parts = 0;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), file_re); it != std::sregex_iterator(); ++it) {
    const std::string f = dir / ("out/" + (*it)[1].str());
    ASSERT_TRUE(std::filesystem::exists(f)) << f;
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(f.c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    EXPECT_EQ(g->GetNumberOfPoints(), 96);
    if (f.find("particles_") != std::string::npos) {
      EXPECT_EQ(g->GetNumberOfCells(), 96);
      EXPECT_NE(g->GetPointData()->GetArray("velocity"), nullptr);
      EXPECT_NE(g->GetPointData()->GetArray("displacement"), nullptr);
      EXPECT_NE(g->GetPointData()->GetArray("broken_fraction"), nullptr);
    } else {
      EXPECT_GT(g->GetNumberOfCells(), 96);
      EXPECT_NE(g->GetCellData()->GetArray("stress"), nullptr);
      EXPECT_NE(g->GetCellData()->GetArray("plastic_shift"), nullptr);
      EXPECT_NE(g->GetCellData()->GetArray("state"), nullptr);
    }
    ++parts;
  }
  EXPECT_GE(parts, 2 * 3);

  // Plots.
  EXPECT_TRUE(std::filesystem::exists(dir / "out/stress_strain.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out/energy.png"));
}

// output.orientations: the spheres' orientations (unit quaternions) and angular velocities go
// to results.h5 and the ParaView frames; without it neither is written (and the orientations
// are not integrated). A granular gas with friction, whose collisions spin the spheres.
TEST(Outputs, OrientationsAndAngularVelocitiesWhenAskedFor) {
  test::TempDir dir("orient");
  test::write_file(dir / "gas.toml", test::granular_gas_case(dir));
  for (const bool on : {true, false}) {
    const std::string out = dir / (on ? "on" : "off");
    const auto r = test::run_command(
        std::string(SWARF_BINARY) + " run " + (dir / "gas.toml") + " --out " + out +
        " --set integrator.end_time=5e-4 --set output.vtk=true --set output.orientations=" + (on ? "true" : "false"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    H5File h5(out + "/results.h5", H5File::Mode::Read);
    EXPECT_EQ(h5.has("/particles/orientation"), on);
    EXPECT_EQ(h5.has("/particles/angular_velocity"), on);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((out + "/frames/particles_00001.vtu").c_str());
    reader->Update();
    vtkDataArray* q = reader->GetOutput()->GetPointData()->GetArray("orientation");
    vtkDataArray* w = reader->GetOutput()->GetPointData()->GetArray("angular_velocity");
    EXPECT_EQ(q != nullptr, on);
    EXPECT_EQ(w != nullptr, on);
    if (!on) continue;
    std::size_t n = 0, c = 0;
    const auto qs = h5.read_doubles("/particles/orientation", n, c);
    ASSERT_EQ(n, 216u);
    ASSERT_EQ(c, 4u);
    ASSERT_EQ(q->GetNumberOfComponents(), 4);
    double turned = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double norm2 = qs[4 * i] * qs[4 * i] + qs[4 * i + 1] * qs[4 * i + 1] + qs[4 * i + 2] * qs[4 * i + 2] +
                           qs[4 * i + 3] * qs[4 * i + 3];
      EXPECT_NEAR(norm2, 1.0, 1e-12);  // unit quaternions (rescaled every step)
      turned = std::max(turned, 1.0 - std::abs(qs[4 * i]));
      EXPECT_EQ(q->GetComponent(static_cast<vtkIdType>(i), 0), qs[4 * i]);  // the frame holds the same state
    }
    EXPECT_GT(turned, 0.0) << "friction turned some spheres";
  }
}

// output.fields: only the chosen per-particle fields go to the frames and results.h5 (the
// positions, radii and groups always, and results.h5's broken_fraction for swarf post); an
// unknown name is refused naming the key, the value and the valid names.
TEST(Outputs, FieldsChooseThePerParticleArrays) {
  test::TempDir dir("fields");
  test::write_file(dir / "tiny.toml", test::kTinyUniaxial);
  const std::string run = std::string(SWARF_BINARY) + " run " + (dir / "tiny.toml") + " --set integrator.end_time=2e-5";
  const auto r = test::run_command(run + " --out " + (dir / "some") +
                                   " --set 'output.fields=[\"plastic_strain\", \"velocity\"]'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "some/frames/particles_00001.vtu").c_str());
  reader->Update();
  vtkPointData* pd = reader->GetOutput()->GetPointData();
  std::vector<std::string> arrays;
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a) arrays.push_back(pd->GetArrayName(a));
  std::sort(arrays.begin(), arrays.end());
  EXPECT_EQ(arrays, (std::vector<std::string>{"group", "id", "plastic_strain", "radius", "velocity"}));
  H5File h5(dir / "some/results.h5", H5File::Mode::Read);
  for (const char* kept : {"position", "radius", "group", "broken_fraction", "velocity", "plastic_strain"})
    EXPECT_TRUE(h5.has(std::string("/particles/") + kept)) << kept;
  for (const char* left :
       {"displacement", "stress", "von_mises_stress", "hydrostatic_stress", "peeq", "peeq_rate", "plastic_work"})
    EXPECT_FALSE(h5.has(std::string("/particles/") + left)) << left;
  const auto sum = nlohmann::json::parse(test::read_file(dir / "some/summary.json"));
  EXPECT_EQ(sum["case_effective"]["output"]["fields"], (nlohmann::json{"plastic_strain", "velocity"}));

  // A restart may choose other fields (the state does not depend on them).
  const auto first = test::run_command(run + " --out " + (dir / "ext") + " --set output.checkpoint_at_end=true");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto ext = test::run_command(std::string(SWARF_BINARY) + " run --restart " + (dir / "ext/checkpoint.h5") +
                                     " --set integrator.end_time=3e-5 --set 'output.fields=[\"velocity\"]'");
  ASSERT_EQ(ext.exit_code, 0) << ext.output;
  H5File h5ext(dir / "ext/results.h5", H5File::Mode::Read);
  EXPECT_TRUE(h5ext.has("/particles/velocity"));
  EXPECT_FALSE(h5ext.has("/particles/plastic_strain"));

  // The default writes every field.
  const auto all = test::run_command(run + " --out " + (dir / "all"));
  ASSERT_EQ(all.exit_code, 0) << all.output;
  H5File h5all(dir / "all/results.h5", H5File::Mode::Read);
  for (const char* f : {"velocity", "displacement", "broken_fraction", "stress", "von_mises_stress",
                        "hydrostatic_stress", "plastic_strain", "peeq", "peeq_rate", "plastic_work"})
    EXPECT_TRUE(h5all.has(std::string("/particles/") + f)) << f;

  // An unknown name: exit code 2, the key, the value and the valid names.
  const auto bad = test::run_command(run + " --out " + (dir / "bad") + " --set 'output.fields=[\"damage\"]'");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("(--set output.fields): key 'output.fields' = [\"damage\"]"), std::string::npos)
      << bad.output;
  EXPECT_NE(bad.output.find("\"damage\" is not one of the accepted values \"velocity\", \"displacement\", "
                            "\"broken_fraction\", \"stress\", \"von_mises_stress\", \"hydrostatic_stress\", "
                            "\"plastic_strain\""),
            std::string::npos)
      << bad.output;
  const auto twice = test::run_command(run + " --out " + (dir / "bad") +
                                       " --set 'output.fields=[\"velocity\", \"velocity\"]'");
  EXPECT_EQ(twice.exit_code, 2) << twice.output;
  EXPECT_NE(twice.output.find("\"velocity\" is given twice"), std::string::npos) << twice.output;
  const auto text = test::run_command(run + " --out " + (dir / "bad") + " --set output.fields=velocity");
  EXPECT_EQ(text.exit_code, 2) << text.output;
  EXPECT_NE(text.output.find("must be an array of strings"), std::string::npos) << text.output;
}

TEST(Outputs, BlowUpStopsWithMessageAndNoCompleteLookingFiles) {
  test::TempDir dir("blowup");
  // Three times the stable step, forced: the lattice explodes within a few steps.
  test::write_file(dir / "unstable.toml", test::kTinyUniaxial);
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "unstable.toml") + " --out " +
                                   (dir / "out") +
                                   " --set integrator.dt=3.6e-7 --set integrator.allow_unstable_dt=true");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("unstable"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("particle"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out/summary.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out/series.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out/results.h5"));
}

}  // namespace
}  // namespace swarf

#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

namespace swarf {
namespace {

TEST(Outputs, MeshesMoveInTheParaViewSeries) {
  test::TempDir dir("mesh_frames");
  test::write_file(dir / "m.toml", R"([[particle]]
position = [0.0, 0.0, 0.01]
radius = 1e-3
[contact]
[[mesh]]
name = "plate"
origin = [0.0, 0.0, 0.0]
edge1 = [0.01, 0.0, 0.0]
edge2 = [0.0, 0.01, 0.0]
motion = "velocity"
velocity = [2.0, 0.0, 0.0]
[integrator]
end_time = 1e-4
[output]
frame_interval = 5e-5
plots = false
)");
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "m.toml") + " --out " + (dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string pvd = test::read_file(dir / "out/particles.pvd");
  EXPECT_NE(pvd.find("name=\"plate\""), std::string::npos) << pvd;
  // The last frame (at the end time, which the fixed explicit step reaches or passes by less
  // than a step) shows the plate moved by 2 m/s times that time.
  double t_last = 0;
  std::regex ts_re("timestep=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), ts_re); it != std::sregex_iterator(); ++it)
    t_last = std::stod((*it)[1].str());
  EXPECT_NEAR(t_last, 1e-4, 1e-6);
  vtkNew<vtkXMLPolyDataReader> reader;
  const std::string last = dir / "out/frames/mesh_plate_00002.vtp";
  ASSERT_TRUE(std::filesystem::exists(last));
  reader->SetFileName(last.c_str());
  reader->Update();
  double x[3];
  reader->GetOutput()->GetPoint(0, x);
  EXPECT_NEAR(x[0], 2.0 * t_last, 1e-12);
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

TEST(Outputs, CuttingForceStatisticsMatchTheSeries) {
  test::TempDir dir("cut_stats");
  test::write_file(dir / "c.toml", test::kTinyCut);
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "c.toml") + " --out " + (dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto sum = nlohmann::json::parse(test::read_file(dir / "out/summary.json"));
  ASSERT_TRUE(sum.contains("cutting")) << sum.dump();
  // Recompute the mean over t >= steady_from from series.csv.
  std::istringstream csv(test::read_file(dir / "out/series.csv"));
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> head;
  {
    std::istringstream hs(line);
    std::string h;
    while (std::getline(hs, h, ',')) head.push_back(h);
  }
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(head.begin(), head.end(), name) - head.begin());
  };
  const std::size_t ct = col("time"), cf = col("cutting_force_per_width"), ch = col("chip_thickness");
  ASSERT_LT(cf, head.size());
  ASSERT_LT(ch, head.size()) << "cutting runs record the chip thickness per row";
  double s = 0;
  int n = 0;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::istringstream ls(line);
    std::string x;
    while (std::getline(ls, x, ',')) v.push_back(std::stod(x));
    EXPECT_GE(v[ch], 0.0);  // m; 0 = not measured (the chip has not left the edge region)
    if (v[ct] >= 2e-5) {
      s += v[cf];
      ++n;
    }
  }
  EXPECT_EQ(sum["cutting"]["steady_samples"].get<double>(), n);
  EXPECT_NEAR(sum["cutting"]["cutting_force_per_width_mean_N_per_m"].get<double>(), s / n, 1e-9 * std::abs(s / n));
  EXPECT_GT(s / n, 0.0);  // the tool is cutting: the workpiece pushes back against the motion
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// DIR/open_in_paraview.py (issue 17 item 3): a run with frames writes it with the run's values
// (fields, the tool, the depth of cut); /usr/bin/python3 compiles it; and run against a
// stand-in for ParaView's Python package (tests/data/paraview_stub: not ParaView, it only
// checks that every file the script opens exists) it opens the particles' and the tool's frame
// series through .series files with the frames' times, and the chip surface. Whether ParaView
// itself accepts every property is not tested here: python3-paraview conflicts with
// python3-vtk9 on Debian 12 (docs/outputs.md).
TEST(Outputs, ParaViewScriptWrittenAndRunsAgainstAStub) {
  test::TempDir dir("paraview");
  test::write_file(dir / "c.toml", test::kTinyCut);
  const std::string out = dir / "out";
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "c.toml") + " --out " + out +
                                   " --set integrator.end_time=1e-5 --set output.vtk=true" +
                                   " --set output.frame_interval=5e-6 --set 'output.fields=[\"plastic_strain\"]'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string script = test::read_file(out + "/open_in_paraview.py");
  EXPECT_NE(script.find("\nSWARF_RUN = {"), std::string::npos);
  EXPECT_NE(script.find("\"tool_mesh\":\"tool\""), std::string::npos) << script.substr(0, 3000);
  EXPECT_NE(script.find("\"fields\":[\"plastic_strain\"]"), std::string::npos);
  EXPECT_NE(script.find("\"depth_of_cut_m\":"), std::string::npos);
  // The copy carries the view's description (postprocess/chip_view.json) as it is, so that the
  // ParaView view and the pictures show the same units, ranges and colour maps.
  const std::string head = "\nSWARF_RUN = ";
  const auto at = script.find(head) + head.size();
  const auto run = nlohmann::json::parse(script.substr(at, script.find('\n', at) - at));
  EXPECT_EQ(run["view"],
            nlohmann::json::parse(test::read_file(std::string(SWARF_SOURCE_DIR) + "/postprocess/chip_view.json")));
  const auto compiled = test::run_command("/usr/bin/python3 -m py_compile " + out + "/open_in_paraview.py");
  EXPECT_EQ(compiled.exit_code, 0) << compiled.output;
  const auto ran = test::run_command("cd / && PYTHONDONTWRITEBYTECODE=1 PYTHONPATH=" + std::string(SWARF_SOURCE_DIR) +
                                     "/tests/data/paraview_stub /usr/bin/python3 " + out +
                                     "/open_in_paraview.py --screenshot " + out + "/pv.png");
  ASSERT_EQ(ran.exit_code, 0) << ran.output;
  EXPECT_NE(ran.output.find("wrote " + out + "/pv.png"), std::string::npos) << ran.output;
  const auto series = nlohmann::json::parse(test::read_file(out + "/particles.vtu.series"));
  ASSERT_EQ(series["files"].size(), 3u) << series.dump();  // t = 0, 5 us, 10 us
  EXPECT_EQ(series["files"][0]["name"], "frames/particles_00000.vtu");
  EXPECT_NEAR(series["files"][2]["time"].get<double>(), 1e-5, 1e-7);
  EXPECT_TRUE(std::filesystem::exists(out + "/tool.vtp.series"));
  EXPECT_TRUE(std::filesystem::exists(out + "/rods.vtu.series"));
}

// The ParaView script's docstring gives the stress view's unit as its colour bar does (it said
// "MPa scale" over a bar in Pa); the bar's unit is the view description's (chip_view.json).
TEST(Outputs, ParaViewScriptDocstringNamesTheStressBarsUnit) {
  const std::string script = test::read_file(std::string(SWARF_SOURCE_DIR) + "/postprocess/open_in_paraview.py");
  const auto view = nlohmann::json::parse(
      test::read_file(std::string(SWARF_SOURCE_DIR) + "/postprocess/chip_view.json"));
  std::string unit;
  for (const auto& f : view["fields"])
    if (f["field"] == "von_mises_stress") unit = f["unit"];
  ASSERT_FALSE(unit.empty()) << "chip_view.json describes no von_mises_stress view";
  const std::string doc = script.substr(0, script.find("\"\"\"", 3));
  EXPECT_NE(doc.find("stress (in " + unit + ","), std::string::npos)
      << "the bar is in " << unit << "; the docstring says: " << doc.substr(doc.find("von Mises"), 60);
}

// One look (issue 36 item 6): every field of the view description has a perceptually uniform
// colour map of its own samples (no rainbow), a unit, and a range rule both scripts know; a
// map's lightness rises monotonically from its low end to its high end (the property that makes
// viridis, cividis, plasma and inferno readable in grey and by colour-blind readers; an HSV
// rainbow fails it), checked on the samples with Rec. 709 luma.
TEST(Outputs, TheViewDescriptionHasPerceptualMapsUnitsAndRanges) {
  const auto view = nlohmann::json::parse(
      test::read_file(std::string(SWARF_SOURCE_DIR) + "/postprocess/chip_view.json"));
  ASSERT_GE(view["fields"].size(), 4u);
  for (const auto& f : view["fields"]) {
    const std::string name = f["field"];
    EXPECT_FALSE(f["unit"].get<std::string>().empty()) << name;
    const std::string range = f["range"];
    EXPECT_TRUE(range == "p99" || range == "max" || range == "min_max") << name << ": " << range;
    const auto& map = view["colour_maps"][f["colour_map"].get<std::string>()];
    ASSERT_GE(map.size(), 9u) << name;
    double luma = -1.0;
    for (const auto& rgb : map) {
      const double y = 0.2126 * rgb[0].get<double>() + 0.7152 * rgb[1].get<double>() + 0.0722 * rgb[2].get<double>();
      EXPECT_GT(y, luma) << name << ": lightness falls along " << f["colour_map"];
      luma = y;
    }
  }
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// The post-processing scripts start without a shell (posix_spawn): an argument reaches the
// script as it is, spaces, quotes and '$(...)' included, and nothing in it is run; stdout
// and stderr both come back, and the exit code decides 'ok'.
TEST(Scripts, ArgumentsReachTheScriptAsTheyAreWithoutAShell) {
  test::TempDir dir("spawn");
  test::write_file(dir / "echo_args.py",
                   "import sys\nfor a in sys.argv[1:]:\n    print('arg<' + a + '>')\n"
                   "print('to stderr', file=sys.stderr)\nsys.exit(3 if 'fail' in sys.argv else 0)\n");
  const char* before = std::getenv("SWARF_POSTPROCESS_DIR");
  const std::string saved = before ? before : "";
  ::setenv("SWARF_POSTPROCESS_DIR", dir.str().c_str(), 1);
  const std::string marker = dir / "ran";
  const ScriptRun r = run_postprocess_script("echo_args.py", {"a b", "it's", "$(touch " + marker + ")", ""});
  EXPECT_TRUE(r.ok) << r.output;
  EXPECT_NE(r.output.find("arg<a b>"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("arg<it's>"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("arg<$(touch " + marker + ")>"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("arg<>"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("to stderr"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(marker));
  EXPECT_FALSE(run_postprocess_script("echo_args.py", {"fail"}).ok);
  const ScriptRun missing = run_postprocess_script("no_such_script.py", {});
  EXPECT_FALSE(missing.ok);
  EXPECT_NE(missing.output.find("script not found"), std::string::npos);
  if (before)
    ::setenv("SWARF_POSTPROCESS_DIR", saved.c_str(), 1);
  else
    ::unsetenv("SWARF_POSTPROCESS_DIR");
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// H5File::write_strips (results.h5's particle fields): strips of 3 rows of a 10 x 2 dataset, the
// last one short, read back as one write would have stored them; a field that fails mid-way
// leaves an error, not a crash or a file that cannot be closed.
TEST(Outputs, AFieldWrittenInStripsReadsBackWhole) {
  test::TempDir dir("strips");
  const std::string path = dir / "s.h5";
  std::vector<std::pair<std::size_t, std::size_t>> asked;
  {
    H5File f(path, H5File::Mode::Create);
    f.write_strips("/particles/x", 10, 2, 3, [&](std::size_t b, std::size_t e, std::vector<double>& v) {
      asked.emplace_back(b, e);
      v.clear();
      for (std::size_t i = b; i < e; ++i) v.insert(v.end(), {double(i), -0.5 * double(i)});
    });
    f.write_strips("/particles/one", 4, 1, 65536,
                   [](std::size_t b, std::size_t e, std::vector<double>& v) { v.assign(e - b, 7.0); });
    EXPECT_THROW(f.write_strips("/particles/bad", 10, 1, 3,
                                [](std::size_t b, std::size_t, std::vector<double>&) {
                                  if (b >= 3) throw OutputError("no value");
                                }),
                 OutputError);
    f.close();
  }
  EXPECT_EQ(asked, (std::vector<std::pair<std::size_t, std::size_t>>{{0, 3}, {3, 6}, {6, 9}, {9, 10}}));
  H5File f(path, H5File::Mode::Read);
  std::size_t rows = 0, cols = 0;
  const std::vector<double> x = f.read_doubles("/particles/x", rows, cols);
  ASSERT_EQ(rows, 10u);
  ASSERT_EQ(cols, 2u);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(x[2 * i], double(i));
    EXPECT_EQ(x[2 * i + 1], -0.5 * double(i));
  }
  const std::vector<double> one = f.read_doubles("/particles/one", rows, cols);
  EXPECT_EQ(rows, 4u);
  EXPECT_EQ(one, std::vector<double>(4, 7.0));
}

}  // namespace
}  // namespace swarf

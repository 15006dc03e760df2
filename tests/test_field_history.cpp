// test_field_history.cpp: the frames' fields over time in results.h5 (/frames/NNNNN) and the
// XDMF sidecar results.xdmf (io/field_history.h), against the ParaView frames they come from,
// and what an interrupted run leaves.
//
// Tolerances: none. The history is the .vtu frames' float64 arrays copied (base64 of the same
// doubles, then HDF5 float64), its times are the doubles the .pvd lists, written with 17
// significant digits into the XDMF (a double round-trips through 17 digits): every comparison
// is exact equality.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkType.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUtilities.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "io/h5file.h"
#include "scenes/tiny_cut.h"
#include "test_helpers.h"

namespace swarf {
namespace {

namespace fs = std::filesystem;

// The tiny cut (144 particles) with its ParaView frames every 4 us over 2e-5 s: 6 frames.
test::CommandResult run_tiny_cut_with_frames(const test::TempDir& dir, const std::string& out,
                                             const std::string& extra = "") {
  test::write_file(dir / "c.toml", test::kTinyCut);
  return test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "c.toml") + " --out " + out +
                           " --threads 1 --set integrator.end_time=2e-5 --set output.vtk=true"
                           " --set output.frame_interval=4e-6" +
                           extra);
}

std::size_t count_frames(const std::string& out) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(out + "/frames"))
    if (e.path().filename().string().rfind("particles_", 0) == 0) ++n;
  return n;
}

std::string unit_label(vtkDataArray* a) {
  vtkInformation* info = a->GetInformation();
  return info->Has(vtkDataArray::UNITS_LABEL()) ? info->Get(vtkDataArray::UNITS_LABEL()) : "1";
}

class FieldHistory : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir("field_history");
    run_ = new test::CommandResult(run_tiny_cut_with_frames(*dir_, out()));
  }
  static void TearDownTestSuite() {
    delete run_;
    delete dir_;
  }
  static std::string out() { return *dir_ / "out"; }
  static test::TempDir* dir_;
  static test::CommandResult* run_;
};
test::TempDir* FieldHistory::dir_ = nullptr;
test::CommandResult* FieldHistory::run_ = nullptr;

// Every .vtu frame is in results.h5: its time (the frame's TimeValue), positions and every
// point array, value for value and with the array's unit; the ids of every frame are the same
// set (each id once), and the last frame's id -> position is the final state's.
TEST_F(FieldHistory, ResultsHoldEveryFrameWithTheVtuTimesAndValues) {
  ASSERT_EQ(run_->exit_code, 0) << run_->output;
  const std::size_t frames = count_frames(out());
  ASSERT_EQ(frames, 6u) << "0, 4, ..., 20 us";
  H5File h5(out() + "/results.h5", H5File::Mode::Read);
  EXPECT_EQ(h5.read_double_attribute("format"), 5.0);
  std::size_t rows = 0, cols = 0;
  const std::vector<double> times = h5.read_doubles("/frame_time", rows, cols);
  ASSERT_EQ(rows, frames);
  EXPECT_EQ(h5.dataset_attribute("/frame_time", "unit"), "s");
  ASSERT_EQ(h5.members("/frames").size(), frames);
  std::set<std::int64_t> first_ids;
  for (std::size_t k = 0; k < frames; ++k) {
    const std::string group = fmt::format("/frames/{:05d}", k);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(fmt::format("{}/frames/particles_{:05d}.vtu", out(), k).c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    vtkDataArray* tv = g->GetFieldData()->GetArray("TimeValue");
    ASSERT_NE(tv, nullptr) << k;
    EXPECT_EQ(unit_label(tv), "s");
    EXPECT_EQ(h5.read_double_attribute(group, "time_s"), tv->GetComponent(0, 0)) << k;
    EXPECT_EQ(times[k], tv->GetComponent(0, 0)) << k;
    if (k > 0) EXPECT_GT(times[k], times[k - 1]);
    const std::size_t n = static_cast<std::size_t>(g->GetNumberOfPoints());
    ASSERT_EQ(n, 144u);
    // Positions.
    const std::vector<double> pos = h5.read_doubles(group + "/position", rows, cols);
    ASSERT_EQ(rows, n);
    ASSERT_EQ(cols, 3u);
    EXPECT_EQ(h5.dataset_attribute(group + "/position", "unit"), "m");
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(pos[3 * i + c], g->GetPoint(static_cast<vtkIdType>(i))[c]) << k << " " << i;
    // Every point array, and nothing else in the group.
    vtkPointData* pd = g->GetPointData();
    std::set<std::string> names{"position"};
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a) {
      vtkDataArray* arr = pd->GetArray(a);
      const std::string name = arr->GetName(), set = group + "/" + name;
      names.insert(name);
      ASSERT_TRUE(h5.has(set)) << set;
      EXPECT_EQ(h5.dataset_attribute(set, "unit"), unit_label(arr)) << set;
      EXPECT_FALSE(h5.dataset_attribute(set, "description").empty()) << set;
      const std::size_t nc = static_cast<std::size_t>(arr->GetNumberOfComponents());
      if (arr->GetDataType() != VTK_DOUBLE && arr->GetDataType() != VTK_FLOAT) {
        const std::vector<std::int64_t> v = h5.read_ints(set, rows, cols);
        ASSERT_EQ(rows, n) << set;
        ASSERT_EQ(cols, nc) << set;
        for (std::size_t i = 0; i < n * nc; ++i)
          ASSERT_EQ(v[i], static_cast<std::int64_t>(arr->GetComponent(static_cast<vtkIdType>(i / nc), int(i % nc))))
              << set << " " << i;
      } else {
        const std::vector<double> v = h5.read_doubles(set, rows, cols);
        ASSERT_EQ(rows, n) << set;
        ASSERT_EQ(cols, nc) << set;
        for (std::size_t i = 0; i < n * nc; ++i)
          ASSERT_EQ(v[i], arr->GetComponent(static_cast<vtkIdType>(i / nc), int(i % nc))) << set << " " << i;
      }
    }
    for (const char* f : {"id", "velocity", "displacement", "radius", "broken_fraction", "stress", "von_mises_stress",
                          "hydrostatic_stress", "plastic_strain", "group"})
      EXPECT_TRUE(names.count(f)) << f << " in frame " << k;
    std::set<std::string> in_h5;
    for (const auto& m : h5.members(group)) in_h5.insert(m);
    EXPECT_EQ(in_h5, names) << group;
    EXPECT_EQ(h5.dataset_attribute(group + "/stress", "unit"), "Pa");
    EXPECT_EQ(h5.dataset_attribute(group + "/velocity", "unit"), "m/s");
    // The ids: each once, the same set in every frame.
    const std::vector<std::int64_t> ids = h5.read_ints(group + "/id", rows, cols);
    const std::set<std::int64_t> id_set(ids.begin(), ids.end());
    EXPECT_EQ(id_set.size(), n) << "an id twice in frame " << k;
    if (k == 0) first_ids = id_set;
    EXPECT_EQ(id_set, first_ids) << "frame " << k << " holds other particles than frame 0";
    if (k + 1 == frames) {  // the last frame is the final state: id -> position as /particles
      const std::vector<std::int64_t> fid = h5.read_ints("/particles/id", rows, cols);
      const std::vector<double> fpos = h5.read_doubles("/particles/position", rows, cols);
      std::map<std::int64_t, std::size_t> row_of;
      for (std::size_t i = 0; i < fid.size(); ++i) row_of[fid[i]] = i;
      for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(pos[3 * i + c], fpos[3 * row_of.at(ids[i]) + c]) << ids[i];
    }
  }
}

// results.xdmf parses as XML: a temporal collection with one Polyvertex grid per frame, its
// Time the frame's, and every data item names a dataset of results.h5 with its shape and number
// type; every dataset of the history is referenced.
TEST_F(FieldHistory, TheXdmfSidecarReferencesEveryDatasetWithItsShape) {
  ASSERT_EQ(run_->exit_code, 0) << run_->output;
  vtkXMLDataElement* root = vtkXMLUtilities::ReadElementFromFile((out() + "/results.xdmf").c_str());
  ASSERT_NE(root, nullptr) << "results.xdmf is not well-formed XML";
  H5File h5(out() + "/results.h5", H5File::Mode::Read);
  std::size_t rows = 0, cols = 0;
  const std::vector<double> times = h5.read_doubles("/frame_time", rows, cols);
  EXPECT_STREQ(root->GetName(), "Xdmf");
  vtkXMLDataElement* series = root->FindNestedElementWithName("Domain")->FindNestedElementWithName("Grid");
  ASSERT_NE(series, nullptr);
  EXPECT_STREQ(series->GetAttribute("GridType"), "Collection");
  EXPECT_STREQ(series->GetAttribute("CollectionType"), "Temporal");
  ASSERT_EQ(static_cast<std::size_t>(series->GetNumberOfNestedElements()), times.size());
  std::set<std::string> referenced;
  for (int k = 0; k < series->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* grid = series->GetNestedElement(k);
    EXPECT_EQ(std::strtod(grid->FindNestedElementWithName("Time")->GetAttribute("Value"), nullptr), times[k]) << k;
    vtkXMLDataElement* topo = grid->FindNestedElementWithName("Topology");
    EXPECT_STREQ(topo->GetAttribute("TopologyType"), "Polyvertex");
    EXPECT_STREQ(topo->GetAttribute("NumberOfElements"), "144");
    int items = 0;
    for (int e = 0; e < grid->GetNumberOfNestedElements(); ++e) {
      vtkXMLDataElement* holder = grid->GetNestedElement(e);
      vtkXMLDataElement* item = holder->FindNestedElementWithName("DataItem");
      if (!item) continue;
      ++items;
      EXPECT_STREQ(item->GetAttribute("Format"), "HDF");
      std::string ref = item->GetCharacterData();
      ref.erase(std::remove_if(ref.begin(), ref.end(), ::isspace), ref.end());
      ASSERT_EQ(ref.rfind("results.h5:", 0), 0u) << ref;
      const std::string set = ref.substr(std::string("results.h5:").size());
      ASSERT_TRUE(h5.has(set)) << set;
      referenced.insert(set);
      const bool integer = std::string(item->GetAttribute("NumberType")) == "Int";
      if (integer)
        h5.read_ints(set, rows, cols);
      else
        h5.read_doubles(set, rows, cols);
      EXPECT_EQ(std::string(item->GetAttribute("Dimensions")),
                cols == 1 ? std::to_string(rows) : fmt::format("{} {}", rows, cols))
          << set;
      // (the integer datasets are stored as int64, the real ones as float64)
      EXPECT_EQ(integer, set.ends_with("/id") || set.ends_with("/group")) << set;
      if (std::string(holder->GetName()) == "Attribute") {
        const std::string name = holder->GetAttribute("Name");
        EXPECT_TRUE(set.ends_with("/" + name)) << set;
        EXPECT_STREQ(holder->GetAttribute("Center"), "Node");
      } else {
        EXPECT_STREQ(holder->GetName(), "Geometry");
        EXPECT_TRUE(set.ends_with("/position")) << set;
      }
    }
    EXPECT_GE(items, 10) << "frame " << k;
  }
  root->Delete();
  for (const auto& s : h5.datasets())
    if (s.rfind("/frames/", 0) == 0) EXPECT_TRUE(referenced.count(s)) << s << " is not in results.xdmf";
}

// SIGTERM in the middle of a run with frames: the frames written so far stay, but neither
// results.h5 nor results.xdmf is there (the earlier, complete run's were removed when this
// one began), so nothing looks complete; the restart from the checkpoint ends with a history
// of every frame, the ones before the interrupt included.
TEST_F(FieldHistory, AnInterruptedRunLeavesNoCompleteLookingHistory) {
  test::TempDir dir("field_history_sigterm");
  const std::string out = dir / "out";
  const auto first = run_tiny_cut_with_frames(dir, out);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  ASSERT_TRUE(fs::exists(out + "/results.xdmf"));
  // The same cut, much longer (4e-3 s: 4,000 series rows), interrupted after 20 rows or more.
  const std::string script = fmt::format(
      "{} run {} --out {} --threads 1 --set integrator.end_time=4e-3 --set output.vtk=true "
      "--set output.frame_interval=4e-6 --set output.checkpoint_every=20 > {} 2>&1 & pid=$!; "
      "n=0; while [ $(cat {}/series.csv.part 2>/dev/null | wc -l) -lt 20 ] && [ $n -lt 2400 ]; do sleep 0.05; "
      "n=$((n+1)); done; kill -TERM $pid; wait $pid; echo \"exit=$?\"",
      SWARF_BINARY, dir / "c.toml", out, dir / "log", out);
  const auto r = test::run_command("bash -c '" + script + "'");
  const std::string log = test::read_file(dir / "log");
  ASSERT_NE(r.output.find("exit=143"), std::string::npos) << r.output << log;
  EXPECT_GE(count_frames(out), 4u) << "frames were written before the interrupt";
  EXPECT_FALSE(fs::exists(out + "/results.xdmf"));
  EXPECT_FALSE(fs::exists(out + "/results.xdmf.part"));
  EXPECT_FALSE(fs::exists(out + "/results.h5"));
  EXPECT_FALSE(fs::exists(out + "/summary.json"));

  // The restart, cut short to 10 us after the checkpoint (a restart may set the end time), completes it.
  const double t_checkpoint = H5File(out + "/checkpoint.h5", H5File::Mode::Read).read_double_attribute("time_s");
  const double end = t_checkpoint + 1e-5;
  const auto b = test::run_command(fmt::format(
      "{} run --restart {}/checkpoint.h5 --threads 1 --set integrator.end_time={:.17g}", SWARF_BINARY, out, end));
  ASSERT_EQ(b.exit_code, 0) << b.output;
  H5File h5(out + "/results.h5", H5File::Mode::Read);
  std::size_t rows = 0, cols = 0;
  const std::vector<double> times = h5.read_doubles("/frame_time", rows, cols);
  EXPECT_EQ(rows, count_frames(out));
  EXPECT_EQ(times.front(), 0.0);
  for (std::size_t k = 1; k < times.size(); ++k) EXPECT_GT(times[k], times[k - 1]);
  EXPECT_GE(times.back(), end * (1 - 1e-12));
  const std::string xdmf = test::read_file(out + "/results.xdmf");
  std::size_t grids = 0;
  for (std::size_t at = xdmf.find("<Time "); at != std::string::npos; at = xdmf.find("<Time ", at + 1)) ++grids;
  EXPECT_EQ(grids, rows);
}

}  // namespace
}  // namespace swarf

// test_run_directory.cpp: the run directory holds only this run's files. Every file a writer
// may write is declared (app/run_file.h); a run removes the declared files an earlier run left
// (a tool spectrum, a plot this case does not draw), and writes no file it has not declared.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include "app/run_directory.h"
#include "scenes/tiny_cut.h"
#include "test_helpers.h"

namespace swarf {
namespace {

namespace fs = std::filesystem;

std::set<std::string> declared_names() {
  std::set<std::string> names;
  for (const RunFile& f : run_directory_files()) names.insert(f.name);
  return names;
}

// A run with every output on (frames, plots and pictures, checkpoints, a compliant tool)
// writes only declared files (a NAME.part goes with NAME; none should be left anyway).
TEST(Outputs, EveryFileARunWritesIsDeclared) {
  test::TempDir dir("declared");
  test::write_file(dir / "c.toml", test::compliant_tiny_cut());
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "c.toml") + " --out " + (dir / "out") +
                                   " --set output.vtk=true --set output.plots=true --set output.frame_interval=1e-5"
                                   " --set output.checkpoint_every=50 --set output.checkpoint_at_end=true");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_TRUE(fs::exists(dir / "out/tool_spectrum.csv")) << "the compliant tool's spectrum (the case's point)";
  const std::set<std::string> declared = declared_names();
  std::size_t seen = 0;
  for (const auto& e : fs::directory_iterator(dir / "out")) {
    const std::string name = e.path().filename().string();
    ++seen;
    EXPECT_TRUE(declared.count(name)) << "'" << name << "' is written by the run but declared by no writer";
  }
  EXPECT_GE(seen, 10u);
}

// A rerun into a directory that holds every declared file of an earlier run (its contents
// "stale") leaves none of them: each is removed or written anew. The first three are the
// issue's: a tool spectrum and vibration plot of a compliant tool's run, and a column table.
TEST(Outputs, ARerunLeavesNoStaleDeclaredFile) {
  test::TempDir dir("stale");
  const std::set<std::string> declared = declared_names();
  for (const char* name : {"tool_spectrum.csv", "tool_vibration.png", "series_columns.csv"})
    EXPECT_TRUE(declared.count(name)) << name;
  const fs::path out = dir / "out";
  fs::create_directories(out / "frames");
  test::write_file((out / "frames/particles_00007.vtu").string(), "stale");
  for (const RunFile& f : run_directory_files()) {
    if (f.keep == RunFile::Keep::always || f.name == "frames") continue;
    test::write_file((out / f.name).string(), "stale");
    test::write_file((out / (f.name + ".part")).string(), "stale");
  }
  test::write_file(dir / "c.toml", test::kTinyCut);
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "c.toml") + " --out " + out.string() +
                                   " --set integrator.end_time=1e-5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    if (!e.is_regular_file()) continue;
    EXPECT_NE(test::read_file(e.path().string()), "stale") << e.path().filename() << " is left from the earlier run";
  }
  EXPECT_TRUE(fs::exists(out / "series_columns.csv")) << "written anew";
}

}  // namespace
}  // namespace swarf

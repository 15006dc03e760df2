// test_golden.cpp: the refactoring gate. The built-in default cut, run for 30 us (0.3 mm of
// tool travel, 31 series rows, the first chip rods breaking), must print the series that the
// build before the engine-library restructuring printed, byte for byte.
//
// This is a regression gate, not a physics test: it proves that a change meant to move code
// moved it without changing a single bit of any result. The reference was written by the
// Release build with -march=native (SWARF_NATIVE=ON, the default) on this project's machine
// kind (x86-64 with FMA); a portable build (SWARF_NATIVE=OFF) rounds fused multiply-adds
// differently and is skipped, as is a sanitizer build (SWARF_SANITIZE). A change that alters results on purpose writes
// the reference anew (tests/data/golden/README.md says how) and says so in its commit.
#include <gtest/gtest.h>

#include <sstream>

#include "test_helpers.h"

namespace swarf {
namespace {

using test::read_file;
using test::run_command;
using test::TempDir;

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string line; std::getline(ss, line);) out.push_back(line);
  return out;
}

TEST(Golden, DefaultCutSeriesIsByteIdenticalToTheReference) {
#if !defined(__FMA__) || defined(SWARF_SANITIZE_BUILD)
  GTEST_SKIP() << "the reference was written by a native Release build with fused multiply-adds";
#endif
  TempDir dir("golden");
  const auto r = run_command(
      fmt::format("{} run --out {} --threads 1 --set integrator.end_time=3e-5 "
                  "--set output.plots=false --set output.vtk=false",
                  SWARF_BINARY, dir / "cut"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string got = read_file(dir / "cut/series.csv");
  const std::string want = read_file(std::string(SWARF_SOURCE_DIR) + "/tests/data/golden/default_cut_3e-5s_series.csv");
  ASSERT_FALSE(want.empty());
  if (got == want) return;
  const auto g = lines_of(got), w = lines_of(want);
  for (std::size_t k = 0; k < std::min(g.size(), w.size()); ++k)
    ASSERT_EQ(g[k], w[k]) << "series.csv differs from the reference first at line " << k + 1;
  FAIL() << "series.csv has " << g.size() << " lines, the reference " << w.size();
}

}  // namespace
}  // namespace swarf

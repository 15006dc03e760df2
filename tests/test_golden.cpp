// test_golden.cpp: the refactoring gate. The built-in default cut (the C45 cut with heat) and
// the same cut without heat run for 15 us, and the linear-law cut that was the default before, run for 30 us (0.3 mm of
// tool travel, 31 series rows, the first chip rods breaking), must print the series of their references, byte for byte.
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

// The default cut's reference: its first 15 us (the tool's first 0.1 mm in the block).
constexpr const char* kDefaultCutTime = "1.5e-5";
constexpr const char* kDefaultCutReference = "default_cut_1.5e-5s_series.csv";

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string line; std::getline(ss, line);) out.push_back(line);
  return out;
}

// Runs 'swarf run CASE' for 'end_time' seconds on one thread and compares its series.csv with
// the reference line by line, so that a failure names the first line that differs.
void expect_series_is_the_reference(const std::string& case_args, const char* end_time, const std::string& reference) {
  TempDir dir("golden");
  const auto r = run_command(
      fmt::format("{} run {} --out {} --threads 1 --set integrator.end_time={} "
                  "--set output.plots=false --set output.vtk=false",
                  SWARF_BINARY, case_args, dir / "cut", end_time));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string got = read_file(dir / "cut/series.csv");
  const std::string want = read_file(std::string(SWARF_SOURCE_DIR) + "/tests/data/golden/" + reference);
  ASSERT_FALSE(want.empty()) << reference;
  if (got == want) return;
  const auto g = lines_of(got), w = lines_of(want);
  for (std::size_t k = 0; k < std::min(g.size(), w.size()); ++k)
    ASSERT_EQ(g[k], w[k]) << "series.csv differs from " << reference << " first at line " << k + 1;
  FAIL() << "series.csv has " << g.size() << " lines, " << reference << " " << w.size();
}

// The built-in default case (the C45 cut: Verlet, bond formation and neighbour exchange, heat,
// Johnson-Cook rods and sticking).
TEST(Golden, DefaultCutSeriesIsByteIdenticalToTheReference) {
#if !defined(__FMA__) || defined(SWARF_SANITIZE_BUILD)
  GTEST_SKIP() << "the reference was written by a native Release build with fused multiply-adds";
#endif
  expect_series_is_the_reference("", kDefaultCutTime, kDefaultCutReference);
}

// The default cut as it was before heat (the paper's rods with the C45 flow curve, no
// temperature): the reference the default had from 2026-12-02 to 2026-12-05, kept so that the
// cold path stays bit for bit.
TEST(Golden, ColdCutSeriesIsByteIdenticalToTheReference) {
#if !defined(__FMA__) || defined(SWARF_SANITIZE_BUILD)
  GTEST_SKIP() << "the reference was written by a native Release build with fused multiply-adds";
#endif
  expect_series_is_the_reference(test::cold_cut_case(), kDefaultCutTime, "cold_cut_1.5e-5s_series.csv");
}

// The linear-law steel cut that was the default before (Newmark with fixed-point sweeps and
// step control, rods that break by stress): its reference dates from before the
// engine-library restructuring.
TEST(Golden, LinearCutSeriesIsByteIdenticalToTheReference) {
#if !defined(__FMA__) || defined(SWARF_SANITIZE_BUILD)
  GTEST_SKIP() << "the reference was written by a native Release build with fused multiply-adds";
#endif
  expect_series_is_the_reference(test::linear_cut_case(), "3e-5", "linear_cut_3e-5s_series.csv");
}

}  // namespace
}  // namespace swarf

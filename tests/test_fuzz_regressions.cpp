// test_fuzz_regressions.cpp: every seed of the fuzzers (tests/fuzz/corpus/<target>/) and every
// input a fuzzer found (tests/fuzz/regressions/<target>/) fed to the same reader as the
// fuzzer feeds it (tests/fuzz/fuzz_targets.h): each must be accepted or refused with an
// InputError, never crash, trap a floating-point exception, hang or throw anything else.
// The files under regressions/ crashed, hung or threw before their fixes (named in their
// commits); scripts/fuzz.sh writes new findings to build-fuzz/findings/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "fuzz/fuzz_targets.h"
#include "setup/case_keys.h"

namespace swarf {
namespace {

std::string bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class FuzzInputs : public testing::TestWithParam<fuzz::Target> {};

}  // namespace

namespace fuzz {
// gtest prints a parameter in the test list (and ctest's names); without this, the struct's bytes.
void PrintTo(const Target& t, std::ostream* os) { *os << t.name; }
}  // namespace fuzz

namespace {

TEST_P(FuzzInputs, SeedsAndFoundInputsAreReadOrRefusedCleanly) {
  const fuzz::Target& t = GetParam();
  int files = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const std::filesystem::path dir = std::filesystem::path(SWARF_SOURCE_DIR) / "tests/fuzz" / kind / t.name;
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      const std::string data = bytes_of(e.path());
      SCOPED_TRACE(e.path().string());
      EXPECT_NO_THROW(t.run(reinterpret_cast<const std::uint8_t*>(data.data()), data.size()));
      ++files;
    }
  }
  EXPECT_GT(files, 0) << "no seeds for " << t.name;
}

// The case_model fuzzer reaches a key through its dictionary's override "table.key=": a key
// added to one of its tables without an entry would be fuzzed only by chance.
TEST(FuzzDictionary, CaseModelNamesEveryKeyOfItsTables) {
  const std::string dict = bytes_of(std::filesystem::path(SWARF_SOURCE_DIR) / "tests/fuzz/case_model.dict");
  ASSERT_FALSE(dict.empty());
  int keys = 0;
  for (const KeyRow& row : case_key_rows()) {
    static const std::set<std::string> tables{"cut",    "membrane", "heat", "contact",   "rod",
                                              "inflow", "outflow",  "mesh", "integrator"};
    if (!tables.contains(row.table)) continue;
    const bool array = row.table == "inflow" || row.table == "outflow" || row.table == "mesh";
    const std::string entry = "\"" + row.table + (array ? ".0." : ".") + row.name + "=\"";
    EXPECT_NE(dict.find(entry), std::string::npos) << "tests/fuzz/case_model.dict lacks " << entry;
    ++keys;
  }
  EXPECT_GT(keys, 90);
}

// The case_model fuzzer reaches the stepping only from valid bases: each base, unchanged, is
// built and stepped (a base refused by a later rule would leave the fuzzer at the reader).
TEST(FuzzDictionary, EveryCaseModelBaseIsBuiltAndStepped) {
  for (std::size_t k = 0; k < fuzz::case_model_bases(); ++k) {
    const std::uint8_t pick = static_cast<std::uint8_t>(k);
    EXPECT_EQ(fuzz::case_model_outcome(&pick, 1), fuzz::ModelOutcome::stepped) << "base " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Readers, FuzzInputs, testing::ValuesIn(fuzz::targets()),
                         [](const testing::TestParamInfo<fuzz::Target>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace swarf

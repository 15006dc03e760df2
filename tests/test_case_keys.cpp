// test_case_keys.cpp: the key table (src/setup/case_keys.cpp) is the one place a case key is
// written: docs/case-reference.md holds its generated tables, the reader reads every key it
// lists from the right table, every settings member has a key (or is listed as derived),
// and a key left out keeps the struct's default, which is what the docs show; summary.json
// echoes the case from the settings through the same table.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <variant>

#include "app/case_echo.h"
#include "scenes/tiny_cut.h"
#include "setup/case_config.h"
#include "setup/case_keys.h"
#include "setup/case_keys_doc.h"
#include "swarf/core/errors.h"
#include "test_helpers.h"

namespace swarf {
namespace {

const std::string kDoc = std::string(SWARF_SOURCE_DIR) + "/docs/case-reference.md";

TEST(CaseKeys, DocumentHoldsTheGeneratedTables) {
  const std::string doc = test::read_file(kDoc);
  ASSERT_FALSE(doc.empty()) << kDoc;
  const std::string diff = key_tables_difference(doc);
  EXPECT_TRUE(diff.empty()) << kDoc << ": " << diff;
  EXPECT_TRUE(update_key_tables(doc) == doc) << "regenerating the tables changes " << kDoc;
}

TEST(CaseKeys, DifferenceNamesTheFirstDifferingKey) {
  const std::string doc = test::read_file(kDoc);
  const std::string row = "| `dt_safety` | float | 1 | 0.5 |";
  const auto pos = doc.find(row);
  ASSERT_NE(pos, std::string::npos);
  std::string drifted = doc;
  drifted.replace(pos, row.size(), "| `dt_safety` | float | 1 | 0.6 |");
  const std::string diff = key_tables_difference(drifted);
  EXPECT_NE(diff.find("table 'integrator'"), std::string::npos) << diff;
  EXPECT_NE(diff.find("key 'dt_safety' differs"), std::string::npos) << diff;
  EXPECT_TRUE(update_key_tables(drifted) == doc) << "regenerating does not restore the document";
  // A key missing from the document is named, with the key found in its place.
  const std::string gone = "| `gamma` |";
  std::string missing = doc;
  const auto g = missing.find(gone);
  missing.erase(g, missing.find('\n', g) + 1 - g);
  EXPECT_NE(key_tables_difference(missing).find("has key 'tolerance' where the key table has key 'gamma'"),
            std::string::npos)
      << key_tables_difference(missing);
  // A table without its block is named.
  std::string unmarked = doc;
  const std::string marker = "<!-- keys:contact begin -->";
  unmarked.replace(unmarked.find(marker), marker.size(), "<!-- contact -->");
  EXPECT_NE(key_tables_difference(unmarked).find("'contact'"), std::string::npos) << key_tables_difference(unmarked);
}

TEST(CaseKeys, CliPrintsTheTables) {
  const auto r = test::run_command(std::string(SWARF_BINARY) + " case keys --markdown");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output, key_tables_markdown());
  const auto list = test::run_command(std::string(SWARF_BINARY) + " case keys");
  EXPECT_NE(list.output.find("integrator.dt_safety"), std::string::npos) << list.output;
}

// A case with every table, each with only the keys it needs ('p.txt' is the [particles] file).
const std::string kEveryTable = R"([workpiece]
cells = [2, 2, 2]
[material]
[rod]
[integrator]
end_time = 1e-5
[[group]]
side = "x-"
[uniaxial]
strain_path = [0.0, 1e-3]
[contact]
[heat]
heat_capacity = 486.0
conductivity = 50.7
[environment]
[[mesh]]
edge1 = [1.0, 0.0, 0.0]
edge2 = [0.0, 1.0, 0.0]
[[particle]]
position = [0.0, 0.0, 0.01]
radius = 1e-3
[particles]
file = "p.txt"
radius = 1e-3
[[inflow]]
box_min = [0.0, 0.0, 0.02]
box_max = [0.01, 0.01, 0.03]
rate = 1000.0
radius_min = 1e-3
[[outflow]]
box_min = [-1.0, -1.0, -1.0]
box_max = [1.0, 1.0, -0.5]
[output]
)";

// A [membrane] takes the place of the [workpiece] (a case has one or the other), with the keys
// it needs.
const std::string kMembraneCase = R"([membrane]
length = 1e-3
width = 1e-3
thickness = 1e-4
youngs_modulus = 1e6
[integrator]
end_time = 1e-5
)";

// A [cut] with its required keys (it cannot go with [uniaxial], so it has a case of its own).
const std::string kCutCase = R"([cut]
uncut_chip_thickness = 0.2e-3
cutting_speed = 10.0
rake_angle = 10.0
material = "C45"
)";

// kEveryTable (kMembraneCase for [membrane], kCutCase for [cut]) with 'line' added to 'table'.
std::string every_table_with(const std::string& table, const std::string& line) {
  const bool array = table == "group" || table == "mesh" || table == "particle" || table == "inflow" ||
                     table == "outflow";
  const std::string header = (array ? "[[" : "[") + table + (array ? "]]\n" : "]\n");
  std::string text = table == "membrane" ? kMembraneCase : table == "cut" ? kCutCase : kEveryTable;
  const auto pos = text.find(header);
  EXPECT_NE(pos, std::string::npos) << header;
  return text.insert(pos + header.size(), line + "\n");
}

TEST(CaseKeys, ReaderReadsEveryKeyOfTheTableFromItsTable) {
  test::TempDir dir("case_keys_read");
  test::write_file(dir / "p.txt", "0 0 0 0.02 0 0 0\n");
  auto error_in = [&](const std::string& text) {
    try {
      parse_case(text, "keys.toml", {}, dir.str());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  ASSERT_EQ(error_in(kEveryTable), "");
  // An inline table is no key's type: each key must fail its own type check, by its dotted
  // name. A key the base already gives is replaced (twice would be a TOML syntax error).
  std::size_t checked = 0;
  for (const KeyRow& row : case_key_rows()) {
    std::string text = every_table_with(row.table, row.name + " = {}");
    const auto added = text.find("\n" + row.name + " = {}");
    const auto table_end = text.find("\n[", added + 1);
    const auto again = text.find("\n" + row.name + " = ", added + 1);
    if (again < table_end) text.erase(again, text.find('\n', again + 1) - again);
    const std::string full = row.table + "." + row.name;
    const std::string msg = error_in(text);
    EXPECT_NE(msg.find("key '" + full + "' = {}: must be"), std::string::npos) << full << ": " << msg;
    ++checked;
  }
  EXPECT_GE(checked, 100u);
  // And a key that no entry lists is unknown in every table.
  for (const std::string& id : key_table_ids()) {
    const std::string table = id.substr(0, id.find(':'));
    const std::string msg = error_in(every_table_with(table, "no_such_key = 1"));
    EXPECT_NE(msg.find("unknown key '" + table + ".no_such_key'"), std::string::npos) << msg;
  }
}

// The number of members of an aggregate: the most initialisers it accepts. AnyMember
// converts to every member type; it is only named in unevaluated requires-expressions.
struct AnyMember {
  template <class T>
  operator T() const;
};
template <class T, class... A>
constexpr std::size_t member_count() {
  if constexpr (requires { T{A{}..., AnyMember{}}; })
    return member_count<T, A..., AnyMember>();
  else
    return sizeof...(A);
}

// Where a member lies in an S: members are told apart by their offsets.
template <class S, class M>
std::ptrdiff_t offset_of(const S& s, M S::*member) {
  return reinterpret_cast<const char*>(&(s.*member)) - reinterpret_cast<const char*>(&s);
}

// Every member of S is filled by exactly one key, or is one of 'derived' (set by the reader
// from other keys, or nested tables read with their own keys), which no key fills.
template <class S, class... Derived>
void expect_every_member_keyed(const char* table, const std::vector<Key<S>>& keys, Derived S::*... derived) {
  EXPECT_EQ(member_count<S>(), keys.size() + sizeof...(Derived)) << table << ": a member without a key";
  static const S s{};
  std::set<std::ptrdiff_t> filled{offset_of(s, derived)...};
  for (const Key<S>& k : keys)
    std::visit([&](auto member) { EXPECT_TRUE(filled.insert(offset_of(s, member)).second) << table << "." << k.name; },
               k.field);
}

TEST(CaseKeys, EverySettingsMemberHasAKey) {
  expect_every_member_keyed("cut", cut_keys(), &CutSettings::enabled);
  expect_every_member_keyed("workpiece", workpiece_keys(), &WorkpieceSettings::enabled);
  expect_every_member_keyed("membrane", membrane_keys(), &MembraneSettings::enabled);
  expect_every_member_keyed("material", material_keys(), &MaterialSettings::macroscopic, &MaterialSettings::flow_curve,
                            &MaterialSettings::johnson_cook_keys_given);
  expect_every_member_keyed("rod", rod_keys());
  expect_every_member_keyed("integrator", integrator_keys());
  expect_every_member_keyed("group", group_keys(), &GroupSettings::motion);
  expect_every_member_keyed("motion", motion_keys());
  expect_every_member_keyed("uniaxial", uniaxial_keys(), &UniaxialSettings::enabled);
  expect_every_member_keyed("contact", contact_keys(), &ContactSettings::enabled);
  expect_every_member_keyed("heat", heat_keys(), &HeatSettings::present);
  expect_every_member_keyed("mesh", mesh_keys(), &MeshSettings::tool, &MeshSettings::motion,
                            &MeshSettings::hinge_at_point, &MeshSettings::tool_from_file, &MeshSettings::file_tip);
  expect_every_member_keyed("particle", particle_keys());
  expect_every_member_keyed("particles", particles_file_keys());
  expect_every_member_keyed("inflow", inflow_keys());
  expect_every_member_keyed("outflow", outflow_keys());
  expect_every_member_keyed("output", output_keys());
  // CaseSettings: [environment] gravity; the tables; what the run records about its input.
  expect_every_member_keyed(
      "environment", environment_keys(), &CaseSettings::source, &CaseSettings::directory, &CaseSettings::workpiece,
      &CaseSettings::membrane, &CaseSettings::material, &CaseSettings::rod, &CaseSettings::integrator,
      &CaseSettings::groups, &CaseSettings::uniaxial, &CaseSettings::contact, &CaseSettings::heat,
      &CaseSettings::meshes, &CaseSettings::particles, &CaseSettings::particles_file, &CaseSettings::output,
      &CaseSettings::overrides, &CaseSettings::effective_toml, &CaseSettings::text, &CaseSettings::given,
      &CaseSettings::cut, &CaseSettings::cut_derived, &CaseSettings::inflows, &CaseSettings::outflows);
}

// Every key the case leaves out holds the default-constructed struct's value, which is the
// default the docs show; the reader substitutes none of its own.
template <class S>
void expect_defaults(const char* table, const std::vector<Key<S>>& keys, const S& parsed,
                     const std::set<std::string>& given) {
  const S defaults{};
  for (const Key<S>& k : keys) {
    if (given.count(std::string(k.name))) continue;
    std::visit([&](auto member) { EXPECT_EQ(parsed.*member, defaults.*member) << table << "." << k.name; }, k.field);
  }
}

TEST(CaseKeys, KeysLeftOutKeepTheStructDefaults) {
  test::TempDir dir("case_keys");
  test::write_file(dir / "p.txt", "0 0 0 0.02 0 0 0\n");
  const CaseSettings cs = parse_case(kEveryTable, "keys.toml", {}, dir.str());
  expect_defaults("workpiece", workpiece_keys(), cs.workpiece, {"cells"});
  expect_defaults("material", material_keys(), cs.material, {});
  expect_defaults("rod", rod_keys(), cs.rod, {});
  expect_defaults("integrator", integrator_keys(), cs.integrator, {"end_time"});
  // Names left out are documented as group<index> and mesh<index>.
  expect_defaults("group", group_keys(), cs.groups.at(0), {"side", "name"});
  EXPECT_EQ(cs.groups[0].name, "group0");
  expect_defaults("group", motion_keys(), cs.groups[0].motion, {});
  expect_defaults("uniaxial", uniaxial_keys(), cs.uniaxial, {"strain_path"});
  expect_defaults("contact", contact_keys(), cs.contact, {});
  expect_defaults("heat", heat_keys(), cs.heat, {"heat_capacity", "conductivity"});
  expect_defaults("environment", environment_keys(), cs, {});
  expect_defaults("mesh", mesh_keys(), cs.meshes.at(0), {"edge1", "edge2", "name"});
  EXPECT_EQ(cs.meshes[0].name, "mesh0");
  expect_defaults("mesh", motion_keys(), cs.meshes[0].motion, {});
  expect_defaults("particle", particle_keys(), cs.particles.at(0), {"position", "radius"});
  expect_defaults("particles", particles_file_keys(), cs.particles_file, {"file", "radius"});
  // (radius_max left out is radius_min, as its doc says: the reader sets it)
  expect_defaults("inflow", inflow_keys(), cs.inflows.at(0), {"box_min", "box_max", "rate", "radius_min", "radius_max"});
  EXPECT_EQ(cs.inflows[0].radius_max, cs.inflows[0].radius_min);
  expect_defaults("outflow", outflow_keys(), cs.outflows.at(0), {"box_min", "box_max"});
  expect_defaults("output", output_keys(), cs.output, {});
  const CaseSettings ms = parse_case(kMembraneCase, "keys.toml", {}, dir.str());
  expect_defaults("membrane", membrane_keys(), ms.membrane, {"length", "width", "thickness", "youngs_modulus"});
  const CaseSettings cs_cut = parse_case(kCutCase, "keys.toml", {}, dir.str());
  expect_defaults("cut", cut_keys(), cs_cut.cut, {"uncut_chip_thickness", "cutting_speed", "rake_angle", "material"});
}

TEST(CaseKeys, RangesKeepTheirMessagesAndDocs) {
  EXPECT_EQ(kPositive.problem(), "must be positive and finite");
  EXPECT_EQ(kPositiveOrInf.problem(), "must be positive (inf allowed)");
  EXPECT_EQ(kNonNegative.problem(), "must be >= 0 and finite");
  EXPECT_EQ(in(0, 0.2, "[)").problem(), "must lie in [0, 0.2)");
  EXPECT_EQ(in(-1, 0.5, "()").problem(), "must lie in (-1, 0.5)");
  EXPECT_EQ(in(2, 10000, "[]").integer_problem(), "must lie in [2, 10000]");
  EXPECT_EQ(kPositive.text(), "> 0, finite");
  EXPECT_EQ(kPositiveOrInf.text(), "> 0, `inf` allowed");
  EXPECT_EQ(in(0, 1, "(]").text(), "(0, 1]");
  EXPECT_TRUE(in(0, 1, "(]").contains(1.0));
  EXPECT_FALSE(in(0, 1, "(]").contains(0.0));
  EXPECT_FALSE(kPositive.contains(kInf));
  EXPECT_TRUE(kPositiveOrInf.contains(kInf));
  // A range that also takes inf ("never") or 0 ("derive it"), and nothing between its ends and those.
  const Range strain = or_inf(in(0, 100, "(]"));
  EXPECT_TRUE(strain.contains(kInf));
  EXPECT_TRUE(strain.contains(100.0));
  EXPECT_FALSE(strain.contains(1e300));
  EXPECT_EQ(strain.problem(), "must lie in (0, 100], or be inf");
  EXPECT_EQ(strain.text(), "(0, 100] or `inf`");
  const Range step = or_zero(in(1e-15, 1, "[]", "a step"));
  EXPECT_TRUE(step.contains(0.0));
  EXPECT_FALSE(step.contains(1e-320));  // (a denormal is not 0)
  EXPECT_EQ(step.problem(), "must lie in [1e-15, 1], or be 0 (a step)");
  EXPECT_EQ(step.text(), "[1e-15, 1] or 0");
  EXPECT_EQ(kModulus.problem(), "must lie in [1000, 1e15] (a modulus, 1 kPa to 1e15 Pa)");
}

// Issue 37: every number key has a physical range (a number array's applies to each entry), and
// the docs show it; "finite" alone, or nothing, admitted 1e300 and 1e-320.
TEST(CaseKeys, EveryNumberKeyHasARange) {
  int numbers = 0;
  for (const KeyRow& r : case_key_rows()) {
    if (r.type == "string" || r.type == "string[]" || r.type == "bool") continue;
    ++numbers;
    const std::string key = r.table + "." + r.name;
    EXPECT_FALSE(r.allowed.empty()) << key << " has no range";
    EXPECT_NE(r.allowed.rfind("finite", 0), 0u) << key << " is only 'finite': " << r.allowed;
    EXPECT_EQ(r.allowed.find(", finite"), std::string::npos) << key << " has an open end: " << r.allowed;
    EXPECT_EQ(r.allowed.find("`inf` allowed"), std::string::npos) << key << " has an open end: " << r.allowed;
  }
  EXPECT_GT(numbers, 150);
}

TEST(CaseKeys, UnitsOfEveryKey) {
  const auto units = case_key_units();
  EXPECT_EQ(units.at("integrator").at("dt"), "s");
  EXPECT_EQ(units.at("material").at("density"), "kg/m^3");
  EXPECT_EQ(units.at("mesh").at("velocity"), "m/s");
  EXPECT_EQ(units.at("output").at("vtk"), "");
  // Every number has a unit ("1" when dimensionless); text, lists of text and switches have none.
  for (const KeyRow& r : case_key_rows()) {
    const bool number = r.type != "string" && r.type != "string[]" && r.type != "bool";
    EXPECT_EQ(r.unit.empty(), !number) << r.table << "." << r.name << " (" << r.type << ")";
  }
}

// The keys a restart may --set are the rows flagged restartable: the end time and the outputs
// that made none of the checkpoint's state (app/run.cpp refuses the others by name).
TEST(CaseKeys, RestartableKeysAreFlaggedInTheTable) {
  EXPECT_EQ(restartable_keys(),
            (std::vector<std::string>{"integrator.end_time", "integrator.max_steps", "output.frame_interval",
                                      "output.series_interval", "output.plots", "output.progress", "output.steady_from",
                                      "output.checkpoint_every", "output.checkpoint_at_end", "output.fields"}));
  const std::string doc = test::read_file(kDoc);
  EXPECT_NE(doc.find("<!-- keys:restartable begin -->\n| key | unit |\n|---|---|\n| `integrator.end_time` | s |"),
            std::string::npos)
      << "docs/case-reference.md lists them in the Restart section";
}

// summary.json's "case" holds the keys the case gave (file and overrides), with their values
// from the settings through the key table: the same values as "case_effective", which fills
// in the rest, and no second reading of the TOML text.
TEST(CaseKeys, TheSummaryEchoesTheGivenKeysFromTheSettings) {
  CaseSettings cs = parse_case(test::kTinyCut, "tiny.toml", {"integrator.end_time=1e-5", "mesh.0.origin.2=0.6e-3"});
  cs.effective_toml = "[not toml";  // (the echo must not read it)
  const nlohmann::json c = case_json(cs), e = case_effective_json(cs);
  EXPECT_EQ(c["integrator"]["end_time"], 1e-5);
  EXPECT_FALSE(c["integrator"].contains("dt_safety")) << "not given";
  EXPECT_TRUE(e["integrator"].contains("dt_safety"));
  EXPECT_EQ(c["mesh"][0]["origin"], nlohmann::json({-0.05e-3, 0.14e-3, 0.6e-3}));
  EXPECT_EQ(c["mesh"][0]["motion"], "velocity");
  EXPECT_EQ(c["workpiece"]["cells"], nlohmann::json({6, 2, 3}));
  EXPECT_EQ(c["group"][0], nlohmann::json({{"name", "base"}, {"side", "z-"}}));
  EXPECT_EQ(c["rod"], nlohmann::json({{"tensile_strength", 3e8}}));
  for (const auto& [table, v] : c.items()) {
    const bool array = v.is_array();
    for (std::size_t i = 0; i < (array ? v.size() : 1); ++i)
      for (const auto& [key, value] : (array ? v[i] : v).items())
        EXPECT_EQ(value, array ? e[table][i][key] : e[table][key]) << table << "." << key;
  }
}

// [heat] is echoed like the other tables: the keys given in "case", every key in
// "case_effective" when the table is there, nothing of it when it is not.
TEST(CaseKeys, TheSummaryEchoesHeat) {
  const CaseSettings cold = parse_case(test::kTinyCut, "tiny.toml", {});
  EXPECT_FALSE(case_json(cold).contains("heat"));
  EXPECT_FALSE(case_effective_json(cold).contains("heat"));
  const CaseSettings hot = parse_case(
      std::string(test::kTinyCut) + "\n[heat]\nheat_capacity = 486.0\nconductivity = 50.0\n", "tiny.toml",
      {"heat.taylor_quinney=0.8"});
  const nlohmann::json c = case_json(hot), e = case_effective_json(hot);
  EXPECT_EQ(c["heat"], nlohmann::json({{"heat_capacity", 486.0}, {"conductivity", 50.0}, {"taylor_quinney", 0.8}}));
  ASSERT_TRUE(e.contains("heat"));
  EXPECT_EQ(e["heat"]["initial_temperature"], 293.15) << "the default, filled in";
  for (const auto& [key, value] : c["heat"].items()) EXPECT_EQ(e["heat"][key], value) << key;
}

}  // namespace
}  // namespace swarf

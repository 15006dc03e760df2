// case_config.cpp: reading a case file: parse_case calls each table's reader in order (most are in
// their modules, setup/modules/; [environment] and [output] here), then checks the rules between
// tables that no one module owns (see parse_case). A module's own rules on other tables stay in its
// reader ([heat]'s held groups, [membrane]'s on [workpiece], [rod] and [material], [uniaxial]'s grip
// names; the rods' in check_rods_across_tables).
#include "setup/case_config.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "io/path_kind.h"
#include "setup/case_override.h"
#include "setup/case_tables.h"
#include "setup/cut_case.h"
#include "setup/rod_laws/rod_laws.h"
#include "setup/toml_parse.h"
#include "swarf/core/errors.h"
#include "swarf/laws/flow_curve.h"

namespace swarf {
namespace {

// [environment]: present or not, no rules between its keys.
void read_environment(const CaseInput& in, CaseSettings& cs) {
  if (const toml::table* t = in.table("environment")) {
    TableReader r = in.reader(t, "environment");
    r.read(environment_keys(), cs);
    r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
  }
}

// The tables and keys the tree holds (CaseSettings::given); the top level is checked already.
std::set<std::string> given_keys(const toml::table& root) {
  std::set<std::string> given;
  auto add = [&](const toml::table& t, const std::string& path) {
    given.insert(path);
    for (const auto& [k, v] : t) given.insert(path + "." + std::string(k.str()));
  };
  for (const auto& [k, v] : root) {
    const std::string name(k.str());
    if (const toml::table* t = v.as_table()) {
      add(*t, name);
    } else if (const toml::array* a = v.as_array()) {
      for (std::size_t i = 0; i < a->size(); ++i)
        if (const toml::table* t = (*a)[i].as_table()) add(*t, name + "." + std::to_string(i));
    }
  }
  return given;
}

// Top level: only known tables, and tables where a table is expected.
void check_top_level(const toml::table& root, const std::string& source, const std::set<std::string>& ov) {
  const std::vector<std::string> tables{"cut",       "workpiece", "membrane", "material",    "rod",   "integrator",
                                        "group",     "uniaxial",  "contact",  "heat",        "mesh",  "particle",
                                        "particles", "inflow",    "outflow",  "environment", "output"};
  const std::set<std::string> arrays_of_tables{"group", "mesh", "particle", "inflow", "outflow"};
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    if (std::find(tables.begin(), tables.end(), key) == tables.end()) {
      std::string where = source;
      if (ov.count(key) || !v.source().begin.line)
        where += " (--set)";
      else
        where += ":" + std::to_string(v.source().begin.line);
      // (the list from the tables themselves: a hand-written one had lost heat, inflow and outflow)
      std::string known;
      for (const std::string& t : tables) known += (known.empty() ? "" : ", ") + t;
      throw InputError(fmt::format("{}: unknown table or key '{}' (known: {})", where, key, known));
    }
    if (!arrays_of_tables.count(key) && !v.is_table())
      throw InputError(fmt::format("{}: '{}' must be a table ([{}])", source, key, key));
  }
}

}  // namespace

// A hardening curve's points: 2 to FlowCurve::kMaxPoints (1 point would be perfectly plastic:
// the yield stress alone says that), increasing strains from 0, stresses that never fall.
// 'E' is the Young's modulus the curve goes with, Pa, named 'E_key' in messages.
void check_flow_curve(TableReader& r, const char* strain_key, const char* stress_key, const std::vector<double>& eps,
                      const std::vector<double>& sig, double E, const std::string& E_key) {
  if (eps.empty() || sig.empty()) {
    const char* given = eps.empty() ? stress_key : strain_key;
    r.fail(given, r.get(given),
           fmt::format("a hardening curve needs both {} (1) and {} (Pa); {} is not given", strain_key, stress_key,
                       eps.empty() ? strain_key : stress_key));
  }
  if (eps.size() != sig.size())
    r.fail(stress_key, r.get(stress_key),
           fmt::format("has {} values where {} has {}: one stress per point", sig.size(), strain_key, eps.size()));
  if (eps.size() < 2 || eps.size() > static_cast<std::size_t>(FlowCurve::kMaxPoints))
    r.fail(strain_key, r.get(strain_key),
           fmt::format("needs 2 to {} points, has {}", FlowCurve::kMaxPoints, eps.size()));
  if (eps[0] != 0.0) r.fail(strain_key, r.get(strain_key), "the first point must be 0 (plastic strain 0: the yield)");
  for (std::size_t i = 1; i < eps.size(); ++i) {
    if (!(eps[i] > eps[i - 1]))
      r.fail(strain_key, r.get(strain_key),
             fmt::format("must be strictly increasing: value {} is not above {}", eps[i], eps[i - 1]));
    if (!(sig[i] >= sig[i - 1]))
      r.fail(
          stress_key, r.get(stress_key),
          fmt::format("must not decrease (softening is not modelled): value {} Pa is below {} Pa", sig[i], sig[i - 1]));
  }
  // Rules between the curve and E (issue 37): each stress below E (an elastic strain below 1:
  // beyond it a rod's elastic stretch exceeds its length), and each segment rising by at most E
  // times its plastic strain range (a hardening modulus above the elastic one is no metal; a
  // judgement: the presets' Johnson-Cook curves, steepest on their first segment, rise at most 0.1 E there).
  for (std::size_t i = 0; i < sig.size(); ++i) {
    if (!(sig[i] < E))
      r.fail(stress_key, r.get(stress_key),
             fmt::format("value {} = {} Pa must lie below the Young's modulus {} = {} Pa (an elastic strain below 1)",
                         i, sig[i], E_key, E));
    if (i > 0 && !(sig[i] - sig[i - 1] <= E * (eps[i] - eps[i - 1])))
      r.fail(stress_key, r.get(stress_key),
             fmt::format("rises by {} Pa from value {} to {}, more than {} = {} Pa times its plastic strain range {} "
                         "(a hardening modulus above E)",
                         sig[i] - sig[i - 1], i - 1, i, E_key, E, eps[i] - eps[i - 1]));
  }
}

CaseSettings parse_case(const std::string& text, const std::string& source, const std::vector<std::string>& overrides,
                        const std::string& directory) {
  toml::table root = parse_toml_input(text, source);
  std::set<std::string> ov;
  for (const auto& o : overrides) apply_override(root, o, ov);

  CaseSettings cs;
  cs.text = text;
  cs.source = source;
  cs.directory = directory;
  cs.overrides = overrides;
  check_top_level(root, source, ov);
  std::set<std::string> derived;  // the keys [cut] put into the tree
  expand_cut(root, CaseInput{root, source, directory, ov}, cs, derived);
  cs.effective_toml = print_toml(root);
  cs.given = given_keys(root);
  const CaseInput in{root, source, directory, ov, &derived};
  read_workpiece(in, cs);
  read_membrane(in, cs);
  read_material(in, cs);
  read_rod(in, cs);
  read_integrator(in, cs);
  read_groups(in, cs);
  read_uniaxial(in, cs);
  read_contact(in, cs);
  read_heat(in, cs);
  check_flow_zone(in, cs);
  read_environment(in, cs);
  read_meshes(in, cs);
  read_particles(in, cs);
  read_flows(in, cs);
  read_particles_file(in, cs);
  // The rules between tables that no one module owns: they need several modules' settings at once,
  // read in full (the meshes with the outflows, the bodies with [contact], [uniaxial] with
  // [workpiece], any particles at all, and integrator.end_time with [uniaxial] after [output]).
  // A cutting run's analysis takes the workpiece as the first particles (Model::lattice_particles):
  // an outflow's removals would renumber them under it. (An inflow appends after them.)
  const bool cutting = cs.workpiece.enabled &&
                       std::any_of(cs.meshes.begin(), cs.meshes.end(), [](const MeshSettings& m) { return m.tool; });
  if (cutting && !cs.outflows.empty())
    throw InputError(fmt::format(
        "{}: [[outflow]] cannot go with a cutting run (a workpiece and a tool) yet: the chip analysis takes the "
        "workpiece as the first particles, and removals would renumber them",
        source));
  if ((!cs.meshes.empty() || !cs.particles.empty() || !cs.particles_file.file.empty()) && !cs.contact.enabled)
    throw InputError(
        fmt::format("{}: meshes and free particles interact only through contacts: add a [contact] "
                    "table (youngs_modulus, poisson_ratio, restitution, friction)",
                    source));
  if (cs.uniaxial.enabled && !cs.workpiece.enabled)
    throw InputError(fmt::format("{}: [uniaxial] needs a [workpiece] (the bar)", source));
  check_rods_across_tables(cs);
  if (!cs.workpiece.enabled && !cs.membrane.enabled && cs.particles.empty() && cs.particles_file.file.empty() &&
      cs.inflows.empty())
    throw InputError(fmt::format(
        "{}: no particles: give a [workpiece], a [membrane], [[particle]] tables, a [particles] file or an [[inflow]]",
        source));
  read_output(in, cs);
  if (!cs.uniaxial.enabled && !(cs.integrator.end_time > 0.0))
    throw InputError(
        fmt::format("{}: key 'integrator.end_time' must be set (s) when there is no [uniaxial] path", source));
  return cs;
}

CaseSettings load_case(const std::string& path, const std::vector<std::string>& overrides) {
  if (const PathKind k = path_kind(path); k.kind == PathKind::Directory)
    throw InputError(fmt::format("case file '{}' is a directory, not a case file (TOML)", path));
  else if (k.kind == PathKind::Unusable)
    throw InputError(fmt::format("case file '{}': {}", path, k.error));
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("case file '{}' cannot be read (missing or no permission)", path));
  std::stringstream ss;
  ss << in.rdbuf();
  auto dir = std::filesystem::path(path).parent_path();
  return parse_case(ss.str(), path, overrides, dir.empty() ? "." : dir.string());
}

}  // namespace swarf

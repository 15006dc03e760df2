// case_tables.h: what the readers of a case file's tables share, internal to setup/: the parsed
// tree (CaseInput) and the helpers of several tables.
//
// Each reader (a module's read_<name>, setup/modules/) reads its table's keys through the key
// table (type and range checks, unknown keys), then checks by hand the rules that involve several
// keys or files, in the order parse_case calls them (case_config.cpp).
#pragma once

#include <toml++/toml.h>

#include <set>
#include <string>
#include <vector>

#include "setup/case_config.h"
#include "setup/case_reader.h"
#include "tool_paths/tool_measure.h"

namespace swarf {

/// The parsed tree (overrides applied) and what the messages and paths need.
struct CaseInput {
  const toml::table& root;
  const std::string& source;     ///< names the case in messages
  const std::string& directory;  ///< relative paths resolve here
  const std::set<std::string>& overridden;
  const std::set<std::string>* derived = nullptr;  ///< the keys [cut] inserted (cut_case.h), or none

  const toml::table* table(const char* name) const { return root.get_as<toml::table>(name); }
  TableReader reader(const toml::table* t, const char* prefix) const {
    return {t, prefix, source, overridden, derived};
  }
};

/// 'file' relative to 'directory' unless it is absolute.
std::string resolve(const std::string& file, const std::string& directory);

/// The cutting tool in the mesh file 'path' (times 'scale') measured (tool_measure.h); a file that
/// cannot be read or does not measure as a tool fails the reader's 'key' with what was found.
ToolMeasure measure_tool_file(const TableReader& r, const char* key, const std::string& path, double scale);

/// A hardening curve's rules: 2 to FlowCurve::kMaxPoints points, strains increasing from 0,
/// stresses that never fall and stay below 'E' (named 'E_key' in messages), Pa.
void check_flow_curve(TableReader& r, const char* strain_key, const char* stress_key, const std::vector<double>& eps,
                      const std::vector<double>& sig, double E, const std::string& E_key);

// Helpers the bodies' tables share (case_bodies.cpp).

/// The entries of an array of tables ([[group]]), or none when the key is absent.
const toml::array* entries(const CaseInput& in, const char* name);

/// A [[group]]'s or [[mesh]]'s name: letters, digits, '_' and '-' (it names CSV columns).
void check_name(const TableReader& r, const std::string& name);

/// A direction (an axis, a normal): at least 1e-6 long (only its direction counts).
void check_direction(const TableReader& r, const char* key, const std::array<double, 3>& v);

}  // namespace swarf

// case_keys.h: the case file's schema, one entry per key (name, member, unit, range, doc line).
//
// Each key of a case file is written once, in case_keys.cpp or in its table's module
// (setup/modules/: every engine-facing table; a rod law's own keys in setup/rod_laws/), as a
// Key (key.h): the entry names the member of the settings struct it fills, so its type and its
// default come from the struct. The reader (case_reader.h) takes type and range checks from the entry, and
// rejects keys that no entry names; the key tables of docs/case-reference.md are generated
// from the entries (case_keys_doc.cpp), and a test fails when the document drifts.
// Rules between keys ("give either cells or size") stay hand-written in the readers; the
// entry's 'rule' states them for the docs.
#pragma once

#include <array>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "setup/case_config.h"
#include "setup/key.h"

namespace swarf {

// The keys of the tables that are not modules, in reading order. (The modules' are declared in
// their headers, setup/modules/; [[group]] and [[mesh]] read the motion keys of modules/motion.h too.)
const std::vector<Key<CutSettings>>& cut_keys();
const std::vector<Key<CaseSettings>>& environment_keys();

/// One key as text, for the docs and for the units in summary.json.
struct KeyRow {
  std::string table;    ///< TOML table: "integrator", "group" (for [[group]])
  std::string section;  ///< sub-table of the docs, or empty
  std::string name;
  std::string type;  ///< "float", "int", "bool", "string", "float[3]", "int[3]", "int[2]", "float[]",
                     ///< "array of float[3]", "string[]"
  std::string unit;
  std::string default_value;  ///< markdown
  std::string allowed;        ///< markdown: range or choices, then the hand-checked rule
  std::string doc;
  std::string shared_with;   ///< the table whose docs list this key ("group" for the motion keys of [[mesh]])
  bool restartable = false;  ///< Key::restartable
};

/// Every key of every table, in the order of the tables in a case file and of their keys.
/// The motion keys are listed under "group" and, once more, under "mesh".
std::vector<KeyRow> case_key_rows();

/// The keys a restart may change ("integrator.end_time", "output.plots", ...), in table order.
std::vector<std::string> restartable_keys();

/// The unit of every key, table -> key -> unit ("1" dimensionless, "" text and bool), for
/// a sibling of the case echo in summary.json.
std::map<std::string, std::map<std::string, std::string>> case_key_units();

}  // namespace swarf

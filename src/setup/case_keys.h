// case_keys.h: the case file's schema, one entry per key (name, member, unit, range, doc line).
//
// Each key of a case file is written once, in case_keys.cpp: the entry names the member of
// the settings struct (case_config.h) it fills, so its type and its default come from the
// struct. The reader (case_reader.h) takes type and range checks from the entry, and
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
#include "swarf/core/bounds.h"

namespace swarf {

/// The values a number key accepts: lo..hi, each end open or closed. A closed infinite end
/// admits inf; the default range admits every number (nan is always rejected).
struct Range {
  double lo = -kInf;
  double hi = kInf;
  bool lo_open = false;
  bool hi_open = false;
  std::string_view hint = {};  ///< appended to the error message in parentheses

  bool any() const { return lo == -kInf && hi == kInf && !lo_open && !hi_open; }
  bool contains(double v) const { return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi); }
  /// The error message, "must be positive and finite", "must lie in (0, 1]", ...
  std::string problem() const;
  /// The same for integer keys: "must lie in [2, 10000]".
  std::string integer_problem() const;
  /// For the docs: "> 0, finite", "[0, 0.2)", ...
  std::string text(bool integer = false) const;
};

/// lo..hi with the ends given as brackets, "[)" for [lo, hi).
constexpr Range in(double lo, double hi, const char (&ends)[3], std::string_view hint = {}) {
  return Range{lo, hi, ends[0] == '(', ends[1] == ')', hint};
}
inline constexpr Range kPositive{0.0, kInf, true, true};        ///< > 0, finite
inline constexpr Range kPositiveOrInf{0.0, kInf, true, false};  ///< > 0, inf allowed
inline constexpr Range kNonNegative{0.0, kInf, false, true};    ///< >= 0, finite
/// A particle radius, m: beyond these the derived step and the lattice's pair search overflow
/// (a radius of 1e300 m squares to inf) before any check could name the key.
inline constexpr Range kRadius{kMinRadius, kMaxRadius, false, false, "a positive length, 1 nm to 1 m"};
/// A density, kg/m^3 (the lightest foam to beyond the densest metal).
inline constexpr Range kDensity{1e-3, 1e6, false, false, "a positive density, 1e-3 to 1e6 kg/m^3"};

/// The member of S that a key fills; the alternative is the key's TOML type.
template <class S>
using Field = std::variant<double S::*, int S::*, bool S::*, std::string S::*, std::array<double, 3> S::*,
                           std::array<int, 3> S::*, std::array<int, 2> S::*, std::vector<double> S::*,
                           std::vector<std::array<double, 3>> S::*, std::vector<std::string> S::*>;

/// One key of a table whose settings struct is S. The members are in the order of the docs'
/// columns, so that entries written with designated initialisers read like a table row.
template <class S>
struct Key {
  std::string_view name = {};
  Field<S> field = {};
  std::string_view unit = {};          ///< SI unit of the value; "1" dimensionless; "" for text and bool
  bool no_default = false;             ///< the member's initial value only means "not given"
  std::string_view default_note = {};  ///< docs: follows the default, or replaces it when no_default
  Range range = {};                    ///< numbers (each entry of a number array) and integers
  std::vector<std::string_view> choices =
      {};                         ///< strings (and each of a string list): the accepted values; empty = any text
  std::string_view rule = {};     ///< docs: the conditions that the reader checks by hand
  std::string_view doc = {};      ///< docs: the meaning, one line
  std::string_view section = {};  ///< docs: the sub-table it is listed in ("newmark"); empty = the main one
  /// A restart may change it (--set with --restart): it made none of the state a checkpoint
  /// holds (the end time, the outputs). Every other key did, and a restart refuses it.
  bool restartable = false;
};

// The keys of each table, in reading order. [[group]] and [[mesh]] read the motion keys too.
const std::vector<Key<CutSettings>>& cut_keys();
const std::vector<Key<WorkpieceSettings>>& workpiece_keys();
const std::vector<Key<MembraneSettings>>& membrane_keys();
const std::vector<Key<MaterialSettings>>& material_keys();
const std::vector<Key<RodSettings>>& rod_keys();
const std::vector<Key<IntegratorSettings>>& integrator_keys();
const std::vector<Key<GroupSettings>>& group_keys();
const std::vector<Key<MotionSettings>>& motion_keys();
const std::vector<Key<UniaxialSettings>>& uniaxial_keys();
const std::vector<Key<ContactSettings>>& contact_keys();
const std::vector<Key<HeatSettings>>& heat_keys();
const std::vector<Key<CaseSettings>>& environment_keys();
const std::vector<Key<MeshSettings>>& mesh_keys();
const std::vector<Key<ParticleSettings>>& particle_keys();
const std::vector<Key<InflowSettings>>& inflow_keys();
const std::vector<Key<OutflowSettings>>& outflow_keys();
const std::vector<Key<ParticlesFileSettings>>& particles_file_keys();
const std::vector<Key<OutputSettings>>& output_keys();

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

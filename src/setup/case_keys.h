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
  bool or_inf = false;         ///< inf is accepted as well ("off": no yield, no failure)
  bool or_zero = false;        ///< 0 is accepted as well ("derive it", "none")

  bool any() const { return lo == -kInf && hi == kInf && !lo_open && !hi_open && !or_inf && !or_zero; }
  bool contains(double v) const {
    return (or_inf && v == kInf) || (or_zero && v == 0.0) ||
           ((lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi));
  }
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
/// The same range that also accepts inf, or 0.
constexpr Range or_inf(Range r) {
  r.or_inf = true;
  return r;
}
constexpr Range or_zero(Range r) {
  r.or_zero = true;
  return r;
}
inline constexpr Range kPositive{0.0, kInf, true, true};        ///< > 0, finite
inline constexpr Range kPositiveOrInf{0.0, kInf, true, false};  ///< > 0, inf allowed
inline constexpr Range kNonNegative{0.0, kInf, false, true};    ///< >= 0, finite
/// A particle radius, m: beyond these the derived step and the lattice's pair search overflow
/// (a radius of 1e300 m squares to inf) before any check could name the key.
inline constexpr Range kRadius{kMinRadius, kMaxRadius, false, false, "a positive length, 1 nm to 1 m"};
/// A density, kg/m^3 (the lightest foam to beyond the densest metal).
inline constexpr Range kDensity{1e-3, 1e6, false, false, "a positive density, 1e-3 to 1e6 kg/m^3"};

// Physical ranges (issue 37): wide enough for every real use, narrow enough that no accepted
// value overflows, underflows to a denormal or makes a figure meaningless. Where a bound is a
// judgement rather than physics, its hint says so.
/// A length, m: 1 nm (the smallest radius) to 1 km.
inline constexpr Range kLength{1e-9, 1e3, false, false, "a length, 1 nm to 1 km"};
/// A length that may be 0 ("none"), m.
inline constexpr Range kLengthOrZero{0.0, 1e3, false, false, "a length, 0 to 1 km"};
/// A coordinate, m (a judgement: a DEM scene is metres across; within 1 km the double's
/// spacing stays below 1e-13 m, far below the smallest radius).
inline constexpr Range kCoordinate{-1e3, 1e3, false, false, "a position within 1 km of the origin"};
/// A velocity component, m/s (a judgement: 10 km/s is beyond any cut or impact DEM models).
inline constexpr Range kVelocity{-1e4, 1e4, false, false, "a speed within 10 km/s"};
/// An angular velocity component, rad/s (a judgement: 1e7 rad/s spins a 1 nm sphere's surface at 1 cm/s
/// and a 1 mm one's at 10 km/s).
inline constexpr Range kAngularVelocity{-1e7, 1e7, false, false, "within 1e7 rad/s"};
/// A direction's component (normalised on reading), 1.
inline constexpr Range kDirection{-1e3, 1e3, false, false, "a direction's component within 1e3"};
/// An elastic modulus, Pa: 1 kPa (the softest foams and gels) to 1e15 Pa (a judgement: a thousand
/// times diamond's 1.2e12 Pa, for contacts made stiffer than any material to stand for a rigid wall).
inline constexpr Range kModulus{1e3, 1e15, false, false, "a modulus, 1 kPa to 1e15 Pa"};
/// A modulus that may be 0, Pa (a hardening modulus: perfectly plastic).
inline constexpr Range kModulusOrZero{0.0, 1e15, false, false, "a modulus, 0 to 1e15 Pa"};
/// A stress, Pa: up to 1e13 Pa (a judgement: a hundred times the ideal strength of any metal,
/// so that a strength written large to mean "never" passes; the flow curve is held below E).
inline constexpr Range kStress{0.0, 1e13, true, false, "a stress, above 0 and at most 1e13 Pa"};
/// A strain, 1 (a judgement: a rod stretched 100 times its length is not a material any more).
inline constexpr Range kStrain{0.0, 100.0, true, false, "a strain, above 0 and at most 100"};
/// A temperature, K (as [heat]'s temperatures: the hottest melt is below 1e4 K).
inline constexpr Range kTemperature{1.0, 1e4, false, false, "a temperature, 1 to 1e4 K"};
/// A time, s: 1 ps to 1e6 s (11.6 days; a judgement: DEM steps are ns to us).
inline constexpr Range kTime{1e-12, 1e6, false, false, "a time, 1 ps to 1e6 s"};
/// A strain rate, 1/s (a judgement: 1e-9 1/s is creep, 1e9 1/s beyond shock loading).
inline constexpr Range kStrainRate{1e-9, 1e9, false, false, "a strain rate, 1e-9 to 1e9 1/s"};
/// A mass, kg (a judgement: a rigid body from 1 ng to 1e9 kg).
inline constexpr Range kMass{1e-12, 1e9, false, false, "a mass, 1e-12 to 1e9 kg"};
/// A force component, N, and a torque component, N m (a judgement: 1e12 N is a 100 MN press ten thousand times over).
inline constexpr Range kForce{-1e12, 1e12, false, false, "within 1e12"};
/// A stiffness, N/m (a judgement: 1e15 N/m is 1e5 times a machine tool's spindle).
inline constexpr Range kStiffness{0.0, 1e15, false, false, "a stiffness, 0 to 1e15 N/m"};
/// A dimensionless scale factor.
inline constexpr Range kScale{1e-9, 1e9, false, false, "1e-9 to 1e9"};

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

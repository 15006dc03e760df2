// key.h: one key of a case file's table (name, member, unit, range, doc line) and the ranges
// its value may take: the row type of every key table (case_keys.h, cut_keys.cpp, and the
// modules' tables in setup/modules/). Apart from case_config.h so that a module's header can
// hold its settings struct and declare its key table without the whole case.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "swarf/core/bounds.h"

namespace swarf {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

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

}  // namespace swarf

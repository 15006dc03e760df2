// case_key_text.cpp: the key table as text: the phrases of a range (for error messages and
// the docs) and one row per key with its type, unit, default, allowed values and meaning.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "setup/case_keys.h"

namespace swarf {
namespace {

// A number for the docs: the shortest decimal that reads back to the same double, in
// scientific form outside [1e-2, 1e5) ("2e11", "1e-6"); floats keep a ".0" so that
// "7800.0" reads as a float where "25" is an int.
std::string doc_number(double v, bool mark_float) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  const double a = std::abs(v);
  if (a != 0.0 && (a >= 1e5 || a < 1e-2)) {
    std::string s;
    for (int p = 0; p <= 17; ++p) {
      s = fmt::format("{:.{}e}", v, p);
      if (std::stod(s) == v) break;
    }
    const auto e = s.find('e');
    std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent = exponent.substr(1);
    while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
    return mantissa + "e" + (negative ? "-" : "") + exponent;
  }
  std::string s = fmt::format("{}", v);
  if (mark_float && s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

// A bound of a range as messages and docs show it: "0.2", "-1", "10", "1e13" (not 10000000000000).
std::string bound(double v) { return doc_number(v, false); }

std::string type_name(double) { return "float"; }
std::string type_name(int) { return "int"; }
std::string type_name(bool) { return "bool"; }
std::string type_name(const std::string&) { return "string"; }
std::string type_name(const std::array<double, 3>&) { return "float[3]"; }
std::string type_name(const std::array<int, 3>&) { return "int[3]"; }
std::string type_name(const std::array<int, 2>&) { return "int[2]"; }
std::string type_name(const std::vector<double>&) { return "float[]"; }
std::string type_name(const std::vector<std::array<double, 3>>&) { return "array of float[3]"; }
std::string type_name(const std::vector<std::string>&) { return "string[]"; }

template <class Seq, class F>
std::string list(const Seq& values, F&& format) {
  std::string out = "[";
  for (const auto& v : values) out += (out.size() > 1 ? ", " : "") + format(v);
  return out + "]";
}

std::string value_text(double v) { return doc_number(v, true); }
std::string value_text(int v) { return std::to_string(v); }
std::string value_text(bool v) { return v ? "true" : "false"; }
std::string value_text(const std::string& v) { return "`\"" + v + "\"`"; }
template <std::size_t N>
std::string value_text(const std::array<double, N>& v) {
  return list(v, [](double x) { return doc_number(x, false); });
}
template <std::size_t N>
std::string value_text(const std::array<int, N>& v) {
  return list(v, [](int x) { return std::to_string(x); });
}
std::string value_text(const std::vector<double>& v) {
  return list(v, [](double x) { return doc_number(x, true); });
}
std::string value_text(const std::vector<std::array<double, 3>>& v) {
  return list(v, [](const std::array<double, 3>& x) { return value_text(x); });
}
std::string value_text(const std::vector<std::string>& v) {
  return "`" + list(v, [](const std::string& x) { return "\"" + x + "\""; }) + "`";
}

// What the type and range checks admit, before the hand-checked rule.
template <class S>
std::string checked_text(const Key<S>& k, double) {
  return k.range.text();
}
template <class S>
std::string checked_text(const Key<S>& k, int) {
  return k.range.text(true);
}
template <class S>
std::string checked_text(const Key<S>&, bool) {
  return "";
}
template <class S>
std::string checked_text(const Key<S>& k, const std::string&) {
  std::string out;
  for (const auto& c : k.choices) out += (out.empty() ? "`\"" : ", `\"") + std::string(c) + "\"`";
  return out;
}
template <class S>
std::string checked_text(const Key<S>& k, const std::vector<std::string>&) {
  return "each one of " + checked_text(k, std::string());
}
template <class S>
std::string checked_text(const Key<S>& k, const std::array<int, 3>&) {
  return "each in " + k.range.text(true);
}
template <class S>
std::string checked_text(const Key<S>& k, const std::array<int, 2>&) {
  return "whole numbers in " + k.range.text(true);
}
template <class S, class T>
std::string checked_text(const Key<S>& k, const T&) {
  if (k.range.any()) return "finite";
  const std::string r = k.range.text();
  return (r[0] == '>' || r[0] == '<' ? "each " : "each in ") + r;
}  // number arrays

template <class S>
void append(std::vector<KeyRow>& rows, std::string_view table, const std::vector<Key<S>>& keys,
            std::string_view shared_with = {}) {
  static const S defaults{};  // the defaults are the struct's default member initialisers
  for (const Key<S>& k : keys) {
    KeyRow row;
    row.table = table;
    row.section = k.section;
    row.name = k.name;
    row.unit = k.unit;
    row.doc = k.doc;
    row.shared_with = shared_with;
    row.restartable = k.restartable;
    std::visit(
        [&](auto member) {
          const auto& value = defaults.*member;
          row.type = type_name(value);
          if (k.no_default) {
            row.default_value = k.default_note.empty() ? "-" : std::string(k.default_note);
          } else {
            row.default_value = value_text(value);
            if (!k.default_note.empty()) row.default_value += " (" + std::string(k.default_note) + ")";
          }
          row.allowed = checked_text(k, value);
        },
        k.field);
    if (!k.rule.empty()) row.allowed += (row.allowed.empty() ? "" : "; ") + std::string(k.rule);
    rows.push_back(std::move(row));
  }
}

}  // namespace

std::string Range::problem() const {
  if (or_inf || or_zero) {
    Range plain = *this;
    plain.or_inf = plain.or_zero = false;
    plain.hint = {};
    std::string out = plain.problem() + (or_inf ? ", or be inf" : "") + (or_zero ? ", or be 0" : "");
    if (!hint.empty()) out += fmt::format(" ({})", hint);
    return out;
  }
  if (lo == 0.0 && lo_open && hi == kInf)
    return hi_open ? "must be positive and finite" : "must be positive (inf allowed)";
  if (lo == 0.0 && !lo_open && hi == kInf && hi_open) return "must be >= 0 and finite";
  std::string out = fmt::format("must lie in {}{}, {}{}", lo_open ? '(' : '[', bound(lo), bound(hi),
                                hi_open ? ')' : ']');
  if (!hint.empty()) out += fmt::format(" ({})", hint);
  return out;
}

std::string Range::integer_problem() const {
  return fmt::format("must lie in [{}, {}]", static_cast<long long>(lo), static_cast<long long>(hi));
}

std::string Range::text(bool integer) const {
  if (any()) return "";
  if (or_inf || or_zero) {
    Range plain = *this;
    plain.or_inf = plain.or_zero = false;
    return plain.text(integer) + (or_inf ? " or `inf`" : "") + (or_zero ? " or 0" : "");
  }
  if (integer) return fmt::format("[{}, {}]", static_cast<long long>(lo), static_cast<long long>(hi));
  if (hi == kInf && lo != -kInf)
    return fmt::format("{} {}, {}", lo_open ? ">" : ">=", bound(lo), hi_open ? "finite" : "`inf` allowed");
  return fmt::format("{}{}, {}{}", lo_open ? '(' : '[', bound(lo), bound(hi), hi_open ? ')' : ']');
}

std::vector<KeyRow> case_key_rows() {
  std::vector<KeyRow> rows;
  append(rows, "cut", cut_keys());
  append(rows, "workpiece", workpiece_keys());
  append(rows, "membrane", membrane_keys());
  append(rows, "material", material_keys());
  append(rows, "rod", rod_keys());
  append(rows, "integrator", integrator_keys());
  append(rows, "group", group_keys());
  append(rows, "group", motion_keys());
  append(rows, "uniaxial", uniaxial_keys());
  append(rows, "contact", contact_keys());
  append(rows, "heat", heat_keys());
  std::vector<KeyRow> mesh;
  append(mesh, "mesh", mesh_keys());
  append(mesh, "mesh", motion_keys(), "group");
  // (the mesh's sub-tables, shapes and rigid body, after its main table with the motion keys)
  std::stable_partition(mesh.begin(), mesh.end(), [](const KeyRow& r) { return r.section.empty(); });
  rows.insert(rows.end(), mesh.begin(), mesh.end());
  append(rows, "particle", particle_keys());
  append(rows, "particles", particles_file_keys());
  append(rows, "inflow", inflow_keys());
  append(rows, "outflow", outflow_keys());
  append(rows, "environment", environment_keys());
  append(rows, "output", output_keys());
  return rows;
}

std::vector<std::string> restartable_keys() {
  std::vector<std::string> keys;
  for (const auto& r : case_key_rows())
    if (r.restartable) keys.push_back(r.table + "." + r.name);
  return keys;
}

std::map<std::string, std::map<std::string, std::string>> case_key_units() {
  std::map<std::string, std::map<std::string, std::string>> units;
  for (const auto& r : case_key_rows()) units[r.table][r.name] = r.unit;
  return units;
}

}  // namespace swarf

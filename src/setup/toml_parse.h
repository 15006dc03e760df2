// toml_parse.h: TOML parsed and printed with the floating-point exceptions held.
//
// toml++ converts a float literal with strtod, which raises FE_OVERFLOW on 1e309, and its
// printer raises FE_INVALID on a NaN value: with the traps of the tests and of runs with
// SWARF_FP_TRAPS=1 on (app/fp_traps.h), a case or study file holding such a number ended in
// SIGFPE inside the library (found by the study-file and case-file fuzzers). These run with
// the exceptions held and their flags dropped; the value (a NaN, or the parser's own error)
// is then refused by the key's checks like any other.
#pragma once

#include <fenv.h>
#include <fmt/format.h>
#include <toml++/toml.h>

#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "swarf/core/errors.h"

namespace swarf {

/// Holds the floating-point exceptions while it lives: no trap, and the flags raised
/// meanwhile are dropped when the environment (traps included) comes back.
class FpExceptionsHeld {
 public:
  FpExceptionsHeld() { ::feholdexcept(&env_); }
  ~FpExceptionsHeld() { ::fesetenv(&env_); }
  FpExceptionsHeld(const FpExceptionsHeld&) = delete;
  FpExceptionsHeld& operator=(const FpExceptionsHeld&) = delete;

 private:
  fenv_t env_;
};

/// toml::parse(text, source) without raising a floating-point exception; throws toml::parse_error.
inline toml::table parse_toml(std::string_view text, std::string_view source = {}) {
  const FpExceptionsHeld held;
  return toml::parse(text, source);
}

/// A case or study file's text as TOML: as parse_toml, but a syntax error becomes InputError
/// "SOURCE:LINE:COLUMN: TOML syntax error: WHAT", the one wording of every file swarf reads.
inline toml::table parse_toml_input(std::string_view text, const std::string& source) {
  try {
    return parse_toml(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", source, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
}

/// One TOML value written alone ("2e-3", "[1, 2]", "\"verlet\"": an override's or a study
/// table's value text) as the key 'v' of a table (toml++ parses documents, not bare values);
/// nullopt when the text is no TOML value.
inline std::optional<toml::table> parse_toml_value(const std::string& text) {
  try {
    return parse_toml("v = " + text);
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

/// A node (a table, an array, a value) as toml++ prints it, without raising one.
inline std::string print_toml(const toml::node& n) {
  const FpExceptionsHeld held;
  std::ostringstream os;
  n.visit([&](auto&& v) { os << v; });
  return os.str();
}

}  // namespace swarf

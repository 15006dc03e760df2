// toml_parse.h: TOML text parsed with the floating-point exceptions held.
//
// toml++ converts a float literal with strtod, which raises FE_OVERFLOW on 1e309: with the
// traps of the tests and of runs with SWARF_FP_TRAPS=1 on (app/fp_traps.h), a case or study
// file holding such a number ended in SIGFPE inside the parser (found by the study-file
// fuzzer). The parse runs with the exceptions held and their flags dropped; what the number
// becomes (inf) is refused by the key's range like any other value.
#pragma once

#include <fenv.h>
#include <toml++/toml.h>

#include <string_view>

namespace swarf {

/// toml::parse(text, source) without raising a floating-point exception; throws toml::parse_error.
inline toml::table parse_toml(std::string_view text, std::string_view source = {}) {
  fenv_t env;
  ::feholdexcept(&env);  // (non-stop mode: no trap; the environment and its traps come back below)
  struct Restore {
    fenv_t* env;
    ~Restore() { ::fesetenv(env); }
  } restore{&env};
  return toml::parse(text, source);
}

}  // namespace swarf

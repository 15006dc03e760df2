// case_errors.h: the error a case text gives when it is read and built, and the check that a
// message names what it should (test_case_files.cpp, test_disorder.cpp).
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"

namespace swarf::test {

/// Parses 'text' as the case file 'source' with the overrides and builds it (which checks the
/// step and the groups); returns the InputError's message, or "" when there is none.
inline std::string case_error(const std::string& text, const std::vector<std::string>& overrides = {},
                              const std::string& source = "bad.toml") {
  try {
    build_model(parse_case(text, source, overrides));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Expects an error message that contains every one of 'parts'.
inline void expect_mentions(const std::string& msg, std::initializer_list<std::string> parts) {
  ASSERT_FALSE(msg.empty()) << "no error raised";
  for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' missing in: " << msg;
}

}  // namespace swarf::test

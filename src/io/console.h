// console.h: messages on stderr that cannot fail a run.
//
// fmt::print(stderr, ...) throws when stderr cannot be written (closed, a full pipe's reader
// gone, /dev/full); thrown again from an error handler it aborted the program. A message that
// cannot be shown is dropped instead: the exit code still tells.
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <string>

namespace swarf {

template <class... Args>
void eprint(fmt::format_string<Args...> format, Args&&... args) noexcept {
  try {
    const std::string s = fmt::format(format, std::forward<Args>(args)...);
    std::fwrite(s.data(), 1, s.size(), stderr);
    std::fflush(stderr);
  } catch (...) {
  }  // (nothing to do: the message is lost, the exit code is not)
}

}  // namespace swarf

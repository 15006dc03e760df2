// console.h: what a command prints, and the transcript that a run keeps of it (DIR/run.log).
//
// fmt::print(stderr, ...) throws when stderr cannot be written (closed, a full pipe's reader
// gone, /dev/full); thrown again from an error handler it aborted the program. A message that
// cannot be shown is dropped instead: the exit code still tells.
//
// Every line printed through say() (stdout) and eprint() (stderr) is also added to the
// transcript. Until a run opens its log (open_transcript) the transcript is held in memory,
// because the set-up is printed before the run directory exists; after that each message is
// appended and flushed as it comes, so a run that fails or is killed leaves the log of what it
// said up to then. The progress line (rewritten in place on a terminal) is not a message and
// is not kept. The transcript is process-wide state, as stdout and stderr themselves are.
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <string_view>

namespace swarf {

namespace console_detail {
struct Transcript {
  std::string held;     // what was said before the log opened
  FILE* log = nullptr;  // DIR/run.log once open
  bool quiet = false;   // say() prints and keeps nothing (the ranks of a run but the first)
};
inline Transcript& transcript() {
  static Transcript t;
  return t;
}
}  // namespace console_detail

/// Adds text to the transcript (held in memory, or appended to the open log). Never throws.
inline void transcript_add(std::string_view s) noexcept {
  auto& t = console_detail::transcript();
  try {
    if (t.log) {
      std::fwrite(s.data(), 1, s.size(), t.log);
      std::fflush(t.log);
    } else if (t.held.size() < (1u << 20)) {  // (a command that never opens a log holds at most 1 MB)
      t.held.append(s);
    }
  } catch (...) {
  }
}

/// Opens 'path' for the transcript (truncated, or appended to with 'append'), writes what was
/// held and keeps appending; false when the file cannot be opened (the caller says so).
inline bool open_transcript(const std::string& path, bool append = false) noexcept {
  auto& t = console_detail::transcript();
  if (t.log) std::fclose(t.log);
  t.log = std::fopen(path.c_str(), append ? "a" : "w");
  if (!t.log) return false;
  std::fwrite(t.held.data(), 1, t.held.size(), t.log);
  std::fflush(t.log);
  t.held.clear();
  return true;
}

/// Closes the log; later messages are held in memory again.
inline void close_transcript() noexcept {
  auto& t = console_detail::transcript();
  if (t.log) std::fclose(t.log);
  t.log = nullptr;
}

/// say() prints and keeps nothing from now on (true) or again (false): the ranks of a run over
/// MPI other than the first, which would print the same lines. Errors (eprint) still show.
inline void set_quiet(bool quiet) noexcept { console_detail::transcript().quiet = quiet; }

/// Prints on stdout and adds to the transcript.
template <class... Args>
void say(fmt::format_string<Args...> format, Args&&... args) {
  if (console_detail::transcript().quiet) return;
  const std::string s = fmt::format(format, std::forward<Args>(args)...);
  std::fwrite(s.data(), 1, s.size(), stdout);
  transcript_add(s);
}

/// Prints on stderr (flushed) and adds to the transcript; never throws.
template <class... Args>
void eprint(fmt::format_string<Args...> format, Args&&... args) noexcept {
  try {
    const std::string s = fmt::format(format, std::forward<Args>(args)...);
    std::fwrite(s.data(), 1, s.size(), stderr);
    std::fflush(stderr);
    transcript_add(s);
  } catch (...) {
  }  // (nothing to do: the message is lost, the exit code is not)
}

}  // namespace swarf

// progress.cpp: the progress line (see progress.h).
#include "app/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

#include "io/console.h"

namespace swarf {

Progress::Progress(bool enabled, double end_time)
    : enabled_(enabled),
      tty_(isatty(STDERR_FILENO)),
      end_time_(end_time),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

static std::string hms(double s) {
  if (!(s >= 0) || s > 1e7) return "--:--:--";
  long t = static_cast<long>(s + 0.5);
  return fmt::format("{:02d}:{:02d}:{:02d}", t / 3600, (t / 60) % 60, t % 60);
}

void Progress::print(double time, long long steps, bool final) {
  const double frac = end_time_ > 0 ? time / end_time_ : 1.0;
  const double el = elapsed();
  const double eta = frac > 0 ? el * (1.0 - frac) / frac : -1.0;
  const std::string line = fmt::format("[{:5.1f}%] t = {:.4e} s of {:.4e} s, step {}, elapsed {}, ETA {}", 100.0 * frac,
                                       time, end_time_, steps, hms(el), final ? hms(0) : hms(eta));
  if (tty_) {
    // (rewritten in place on the terminal: only the final line goes into the transcript)
    const std::string shown = "\r" + line + (final ? "\n" : "");
    std::fwrite(shown.data(), 1, shown.size(), stderr);
    if (final) transcript_add(line + "\n");
  } else {
    eprint("{}\n", line);
  }
  std::fflush(stderr);
}

void Progress::update(double time, long long steps) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double interval = tty_ ? 1.0 : 10.0;
  if (std::chrono::duration<double>(now - last_).count() < interval) return;
  last_ = now;
  print(time, steps, false);
}

void Progress::done(double time, long long steps) {
  if (enabled_) print(time, steps, true);
}

}  // namespace swarf

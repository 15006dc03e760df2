// progress.h: a progress line on stderr for long runs (percent, simulated time, ETA).
#pragma once

#include <chrono>
#include <string>

namespace swarf {

class Progress {
 public:
  explicit Progress(bool enabled, double end_time);
  /// Prints at most once per interval of wall time (1 s on a terminal, 10 s otherwise).
  void update(double time, long long steps);
  /// Prints the final line.
  void done(double time, long long steps);
  double elapsed() const;

 private:
  void print(double time, long long steps, bool final);
  bool enabled_;
  bool tty_;
  double end_time_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace swarf

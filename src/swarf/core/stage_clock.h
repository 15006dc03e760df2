// stage_clock.h: where a step's time goes, stage by stage (for 'swarf bench --stages').
//
// Off by default: a lap is then one predictable branch. On, each lap reads the steady clock
// once (some tens of ns), negligible against a step of thousands of particles.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>

namespace swarf {

enum class Stage : int { Prescribe, Integrate, Rods, Lists, Contacts, Gather, Commit, Account, Krylov, Count };

inline constexpr std::array<const char*, static_cast<std::size_t>(Stage::Count)> kStageNames{
    "prescribe", "integrate", "rod_forces", "contact_lists", "contact_forces",
    "gather",    "commit",    "account",    "krylov"};  // (krylov: the Newton solver's tangent set-up and CG iterations)

class StageClock {
 public:
  void enable(bool on) { on_ = on; }
  bool enabled() const { return on_; }
  /// Starts timing (the time up to the next lap belongs to that lap's stage).
  void start() {
    if (on_) last_ = std::chrono::steady_clock::now();
  }
  /// Charges the time since the last start or lap to 'stage'.
  void lap(Stage stage) {
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    seconds_[static_cast<std::size_t>(stage)] += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }
  double seconds(Stage stage) const { return seconds_[static_cast<std::size_t>(stage)]; }
  double total() const {
    double t = 0.0;
    for (double s : seconds_) t += s;
    return t;
  }

 private:
  bool on_ = false;
  std::chrono::steady_clock::time_point last_{};
  std::array<double, static_cast<std::size_t>(Stage::Count)> seconds_{};
};

}  // namespace swarf

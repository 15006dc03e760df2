// memory_archive.h: a state archive in memory (see state_archive.h): Simulation::visit_state
// saved into it, then loaded into another Simulation (the restart tests; a run over domains
// that starts from a serial Simulation's step state, domains/step_state.h).
//
// A name the 'skip' predicate returns true for is neither kept nor given back (its array stays
// as the loading Simulation has it); a name not kept is left as it is on load.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "swarf/core/state_archive.h"

namespace swarf {

class MemoryArchive final : public StateArchive {
 public:
  explicit MemoryArchive(std::function<bool(std::string_view)> skip = {}) : skip_(std::move(skip)) {}
  bool loading() const override { return loading_; }
  void set_loading(bool l) { loading_ = l; }
  bool keeps(std::string_view n) const override { return !(skip_ && skip_(n)); }
  void array(std::string_view n, std::vector<double>& v, std::size_t) override { io(n, d_, v); }
  void array(std::string_view n, std::vector<Vec3>& v, std::size_t) override { io(n, v3_, v); }
  void array(std::string_view n, std::vector<Quat>& v, std::size_t) override { io(n, q_, v); }
  void array(std::string_view n, std::vector<std::uint8_t>& v, std::size_t) override { io(n, u8_, v); }
  void array(std::string_view n, std::vector<std::int32_t>& v, std::size_t) override { io(n, i32_, v); }
  void array(std::string_view n, std::vector<std::int64_t>& v, std::size_t) override { io(n, i64_, v); }
  void scalar(std::string_view n, double& v) override { io(n, sd_, v); }
  void scalar(std::string_view n, std::int64_t& v) override { io(n, si_, v); }
  /// Replaces a kept field (between a save and a load).
  void set(const std::string& name, double v) { sd_[name] = v; }
  void set(const std::string& name, std::int64_t v) { si_[name] = v; }
  void set(const std::string& name, const std::vector<Vec3>& v) { v3_[name] = v; }

 private:
  template <class T>
  void io(std::string_view n, std::map<std::string, T>& store, T& v) {
    if (skip_ && skip_(n)) return;
    if (!loading_)
      store[std::string(n)] = v;
    else if (const auto it = store.find(std::string(n)); it != store.end())
      v = it->second;
  }

  std::function<bool(std::string_view)> skip_;
  bool loading_ = false;
  std::map<std::string, std::vector<double>> d_;
  std::map<std::string, std::vector<Vec3>> v3_;
  std::map<std::string, std::vector<Quat>> q_;
  std::map<std::string, std::vector<std::uint8_t>> u8_;
  std::map<std::string, std::vector<std::int32_t>> i32_;
  std::map<std::string, std::vector<std::int64_t>> i64_;
  std::map<std::string, double> sd_;
  std::map<std::string, std::int64_t> si_;
};

}  // namespace swarf

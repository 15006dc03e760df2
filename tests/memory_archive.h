// memory_archive.h: a state archive in memory (Simulation::visit_state saved, then loaded
// into another Simulation), for the restart tests that need no file.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "swarf/core/state_archive.h"

namespace swarf::test {

class MemoryArchive final : public StateArchive {
 public:
  bool loading() const override { return loading_; }
  void set_loading(bool l) { loading_ = l; }
  void array(std::string_view n, std::vector<double>& v, std::size_t) override { io(d_[std::string(n)], v); }
  void array(std::string_view n, std::vector<Vec3>& v, std::size_t) override { io(v3_[std::string(n)], v); }
  void array(std::string_view n, std::vector<Quat>& v, std::size_t) override { io(q_[std::string(n)], v); }
  void array(std::string_view n, std::vector<std::uint8_t>& v, std::size_t) override { io(u8_[std::string(n)], v); }
  void array(std::string_view n, std::vector<std::int32_t>& v, std::size_t) override { io(i32_[std::string(n)], v); }
  void array(std::string_view n, std::vector<std::int64_t>& v, std::size_t) override { io(i64_[std::string(n)], v); }
  void scalar(std::string_view n, double& v) override { io(sd_[std::string(n)], v); }
  void scalar(std::string_view n, std::int64_t& v) override { io(si_[std::string(n)], v); }

 private:
  template <class T>
  void io(T& stored, T& v) {
    if (loading_)
      v = stored;
    else
      stored = v;
  }
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

}  // namespace swarf::test

// prefixed_archive.h: a state archive that files every field under a prefix.
//
// The checkpoint's /run/ part holds the loop's record and each observer's state side by
// side; wrapping the archive once per observer ("uniaxial/" + its own names) keeps each
// observer's names its own: two observers may both call a field "shift", and an observer
// needs to know nothing of where in the file it is kept.
#pragma once

#include <string>

#include "swarf/core/state_archive.h"

namespace swarf {

class PrefixedArchive final : public StateArchive {
 public:
  /// Fields named N go to 'inner' as prefix + N (e.g. "uniaxial/" + "predicted").
  PrefixedArchive(StateArchive& inner, std::string prefix) : inner_(inner), prefix_(std::move(prefix)) {}
  bool loading() const override { return inner_.loading(); }
  void array(std::string_view name, std::vector<double>& v, std::size_t n) override { inner_.array(key(name), v, n); }
  void array(std::string_view name, std::vector<Vec3>& v, std::size_t n) override { inner_.array(key(name), v, n); }
  void array(std::string_view name, std::vector<Quat>& v, std::size_t n) override { inner_.array(key(name), v, n); }
  void array(std::string_view name, std::vector<std::uint8_t>& v, std::size_t n) override {
    inner_.array(key(name), v, n);
  }
  void array(std::string_view name, std::vector<std::int32_t>& v, std::size_t n) override {
    inner_.array(key(name), v, n);
  }
  void int32_pairs(std::string_view name, const std::vector<std::array<std::int32_t, 2>>& v) override {
    inner_.int32_pairs(key(name), v);
  }
  void array(std::string_view name, std::vector<std::int64_t>& v, std::size_t n) override {
    inner_.array(key(name), v, n);
  }
  void scalar(std::string_view name, double& v) override { inner_.scalar(key(name), v); }
  void scalar(std::string_view name, std::int64_t& v) override { inner_.scalar(key(name), v); }
  using StateArchive::scalar;  // (bool, int, size_t through the int64 one)

 private:
  std::string key(std::string_view name) const { return prefix_ + std::string(name); }
  StateArchive& inner_;
  std::string prefix_;
};

}  // namespace swarf

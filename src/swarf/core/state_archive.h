// state_archive.h: one visit of the step's state for saving, loading and hashing it.
//
// Simulation::visit_state names each field of the state once, in one order (as Jolt's
// StateRecorder and Box2D's world snapshot): a checkpoint writer, a checkpoint reader and a
// hash are archives that the same visit walks. The engine knows no file format; io/ brings
// the HDF5 archives.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "swarf/core/quat.h"
#include "swarf/core/vec3.h"

namespace swarf {

class StateArchive {
 public:
  /// 'expected' of an array: any stored length is taken (the visit checks it itself).
  static constexpr std::size_t kAnySize = std::numeric_limits<std::size_t>::max();

  virtual ~StateArchive() = default;
  /// True when the visit writes into the state (a load); false when it reads it (save, hash).
  virtual bool loading() const = 0;
  /// False for a field this archive neither keeps nor gives back (a domain's step state leaves
  /// the particle, rod and contact arrays to records: MemoryArchive's skip): a visit whose load
  /// derives more from such fields skips that too.
  virtual bool keeps(std::string_view /*name*/) const { return true; }
  /// On load: whether the archive holds the field (a checkpoint of a run that held fewer
  /// optional particle arrays, particles.h's ParticleLayout, does not hold theirs).
  virtual bool has(std::string_view /*name*/) const { return true; }

  // On save and hash the array is read; on load it is replaced by the stored one, whose
  // length must be 'expected' (elements) unless that is kAnySize: an archive of another
  // World fails with the field named (InputError).
  virtual void array(std::string_view name, std::vector<double>& v, std::size_t expected) = 0;
  virtual void array(std::string_view name, std::vector<Vec3>& v, std::size_t expected) = 0;
  virtual void array(std::string_view name, std::vector<Quat>& v, std::size_t expected) = 0;
  virtual void array(std::string_view name, std::vector<std::uint8_t>& v, std::size_t expected) = 0;
  virtual void array(std::string_view name, std::vector<std::int32_t>& v, std::size_t expected) = 0;
  virtual void array(std::string_view name, std::vector<std::int64_t>& v, std::size_t expected) = 0;
  virtual void scalar(std::string_view name, double& v) = 0;
  virtual void scalar(std::string_view name, std::int64_t& v) = 0;
  /// Save and hash only: index pairs (the rods' ends) as one int32 array of 2 n values, i j per
  /// pair, the field a load reads back with array(). This copies them into such an array; an
  /// archive that can read them where they are (the hash, a checkpoint's writer) does so, the
  /// same bytes without the copy's 8 B per pair (at the end of a run, when the summary's state
  /// hash is taken, that copy was the run's peak: validation/bench/README.md).
  virtual void int32_pairs(std::string_view name, const std::vector<std::array<std::int32_t, 2>>& v) {
    std::vector<std::int32_t> flat(2 * v.size());
    for (std::size_t k = 0; k < v.size(); ++k) {
      flat[2 * k] = v[k][0];
      flat[2 * k + 1] = v[k][1];
    }
    array(name, flat, flat.size());
  }

  void scalar(std::string_view name, bool& b) {
    std::int64_t v = b ? 1 : 0;
    scalar(name, v);
    b = v != 0;
  }
  void scalar(std::string_view name, int& i) {
    std::int64_t v = i;
    scalar(name, v);
    i = static_cast<int>(v);
  }
  void scalar(std::string_view name, std::size_t& n) {
    std::int64_t v = static_cast<std::int64_t>(n);
    scalar(name, v);
    n = static_cast<std::size_t>(v);
  }
};

/// A 64-bit FNV-1a hash of every field's name, length and bytes, in visit order: two states
/// hash alike only if every field is bit-identical (up to the hash's collisions).
class HashArchive final : public StateArchive {
 public:
  bool loading() const override { return false; }
  void array(std::string_view name, std::vector<double>& v, std::size_t) override { add(name, v); }
  void array(std::string_view name, std::vector<Vec3>& v, std::size_t) override { add(name, v); }
  void array(std::string_view name, std::vector<Quat>& v, std::size_t) override { add(name, v); }
  void array(std::string_view name, std::vector<std::uint8_t>& v, std::size_t) override { add(name, v); }
  void array(std::string_view name, std::vector<std::int32_t>& v, std::size_t) override { add(name, v); }
  void array(std::string_view name, std::vector<std::int64_t>& v, std::size_t) override { add(name, v); }
  void scalar(std::string_view name, double& v) override { add_named(name, &v, sizeof v, 1); }
  void scalar(std::string_view name, std::int64_t& v) override { add_named(name, &v, sizeof v, 1); }
  void int32_pairs(std::string_view name, const std::vector<std::array<std::int32_t, 2>>& v) override {
    static_assert(sizeof(std::array<std::int32_t, 2>) == 2 * sizeof(std::int32_t));
    add_named(name, v.data(), v.size() * sizeof(v[0]), 2 * v.size());  // (the flat array's count and bytes)
  }
  std::uint64_t value() const { return h_; }

 private:
  template <class T>
  void add(std::string_view name, const std::vector<T>& v) {
    add_named(name, v.data(), v.size() * sizeof(T), v.size());
  }
  void add_named(std::string_view name, const void* data, std::size_t bytes, std::size_t count) {
    bytes_of(name.data(), name.size());
    bytes_of(&count, sizeof count);
    bytes_of(data, bytes);
  }
  void bytes_of(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) h_ = (h_ ^ b[k]) * 0x100000001b3ull;
  }
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace swarf

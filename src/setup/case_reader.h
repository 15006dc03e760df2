// case_reader.h: reads one TOML table of a case file through its key table (case_keys.h).
//
// The reader knows the keys of the tables it has read and rejects every other key; each
// error names the file and line (or the --set override), the dotted key and the value.
// Internal to setup/: only the case readers include it.
#pragma once

#include <toml++/toml.h>

#include <array>
#include <set>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "setup/case_keys.h"

namespace swarf {

class TableReader {
 public:
  /// 't' may be null (the table is absent: every key keeps its default). 'prefix' names the
  /// table in messages ("group" for every [[group]]); 'overridden' holds the --set keys.
  /// 'derived' (may be null) holds the keys that [cut] put into the tree (cut_case.h).
  TableReader(const toml::table* t, std::string prefix, const std::string& source,
              const std::set<std::string>& overridden, const std::set<std::string>* derived = nullptr)
      : t_(t), prefix_(std::move(prefix)), source_(source), overridden_(overridden), derived_(derived) {}

  /// Makes the keys known to has(), get() and finish() without reading them, for a rule that
  /// must come before their type checks (a key that is not allowed at all, whatever its value).
  template <class S>
  void know(const std::vector<Key<S>>& keys) {
    for (const Key<S>& k : keys) known_.insert(k.name);
  }
  /// Reads every key of 'keys' that the table gives into 's' (type and range checked);
  /// absent keys keep the value 's' has. The keys become known as with know().
  template <class S>
  void read(const std::vector<Key<S>>& keys, S& s) {
    know(keys);
    for (const Key<S>& k : keys) std::visit([&](auto member) { read_value(k, s.*member); }, k.field);
  }

  /// Whether the table gives the key; the key must be one of the tables read.
  bool has(std::string_view key) const;
  /// The key's node or null; the key must be one of the tables read.
  const toml::node* get(std::string_view key) const;
  /// Whether the table's key was put there by [cut] (cut_case.h), not written in the case or
  /// given by --set.
  bool from_cut(std::string_view key) const;
  /// The key's value as a message shows it ("" when absent).
  std::string value_text(std::string_view key) const;
  /// Throws InputError "FILE:LINE: key 'TABLE.KEY' = VALUE: PROBLEM" (no value when n is null).
  [[noreturn]] void fail(std::string_view key, const toml::node* n, const std::string& problem) const;
  /// Rejects every key of the table that no key table read names.
  void finish() const;

 private:
  template <class S>
  void read_value(const Key<S>& k, double& v) {
    number(k.name, k.range, v);
  }
  template <class S>
  void read_value(const Key<S>& k, int& v) {
    integer(k.name, k.range, v);
  }
  template <class S>
  void read_value(const Key<S>& k, bool& v) {
    boolean(k.name, v);
  }
  template <class S>
  void read_value(const Key<S>& k, std::string& v) {
    string(k.name, k.choices, v);
  }
  template <class S>
  void read_value(const Key<S>& k, std::array<double, 3>& v) {
    vec3(k.name, k.range, v);
  }
  template <class S>
  void read_value(const Key<S>& k, std::array<int, 3>& v) {
    ivec3(k.name, k.range, v);
  }
  template <class S>
  void read_value(const Key<S>& k, std::array<int, 2>& v) {
    ivec2(k.name, k.range, v);
  }
  template <class S>
  void read_value(const Key<S>& k, std::vector<double>& v) {
    numbers(k.name, k.range, v);
  }
  template <class S>
  void read_value(const Key<S>& k, std::vector<std::array<double, 3>>& v) {
    triples(k.name, k.unit, k.range, v);
  }
  template <class S>
  void read_value(const Key<S>& k, std::vector<std::string>& v) {
    strings(k.name, k.choices, v);
  }

  void number(std::string_view key, const Range& range, double& v) const;
  void integer(std::string_view key, const Range& range, int& v) const;
  void boolean(std::string_view key, bool& v) const;
  void string(std::string_view key, const std::vector<std::string_view>& choices, std::string& v) const;
  // (number arrays: 'range' applies to each entry)
  void numbers(std::string_view key, const Range& range, std::vector<double>& v) const;
  void vec3(std::string_view key, const Range& range, std::array<double, 3>& v) const;
  void ivec3(std::string_view key, const Range& range, std::array<int, 3>& v) const;
  void ivec2(std::string_view key, const Range& range, std::array<int, 2>& v) const;
  void triples(std::string_view key, std::string_view unit, const Range& range,
               std::vector<std::array<double, 3>>& v) const;
  /// An array of strings, each one of 'choices' (when not empty) and none twice.
  void strings(std::string_view key, const std::vector<std::string_view>& choices, std::vector<std::string>& v) const;

  std::string where(const std::string& full, const toml::node* n) const;
  void check_known(std::string_view key) const;

  const toml::table* t_;
  std::string prefix_;
  const std::string& source_;
  const std::set<std::string>& overridden_;
  const std::set<std::string>* derived_;
  std::set<std::string_view> known_;  // the names live in the static key tables
};

}  // namespace swarf

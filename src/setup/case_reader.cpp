// case_reader.cpp: type and range checks of one TOML table's keys (see case_reader.h).
#include "setup/case_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "setup/toml_parse.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

// The value as the user wrote it (floats in their shortest form), cut to one line's worth.
std::string repr(const toml::node& n) {
  std::string out;
  if (auto s = n.as_string())
    out = '"' + s->get() + '"';
  else if (auto f = n.as_floating_point())
    out = fmt::format("{}", f->get());
  else if (auto a = n.as_array()) {  // (on one line, numbers in their shortest form; print_toml breaks lines)
    out = "[";
    for (std::size_t k = 0; k < a->size(); ++k) out += (k ? ", " : "") + repr(*a->get(k));
    out += "]";
  } else
    out = print_toml(n);
  if (out.size() > 80) out = out.substr(0, 77) + "...";
  return out;
}

}  // namespace

std::string TableReader::where(const std::string& full, const toml::node* n) const {
  std::string w = source_;
  if (overridden_.count(full)) {
    w += fmt::format(" (--set {})", full);
  } else if (n && n->source().begin.line > 0) {
    w += fmt::format(":{}", n->source().begin.line);
  } else if (derived_ && derived_->count(full)) {
    w += " (derived from [cut])";
  }
  return w;
}

void TableReader::check_known(std::string_view key) const {
  // A hand-written rule that asks for a key no key table lists would accept an undocumented key.
  if (!known_.count(key))
    throw std::logic_error(
        fmt::format("case reader: key '{}.{}' is not in its key table (case_keys.cpp)", prefix_, key));
}

bool TableReader::has(std::string_view key) const {
  check_known(key);
  return t_ && t_->contains(key);
}

const toml::node* TableReader::get(std::string_view key) const {
  check_known(key);
  return t_ ? t_->get(key) : nullptr;
}

bool TableReader::from_cut(std::string_view key) const {
  const toml::node* n = get(key);
  const std::string full = prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
  return n && n->source().begin.line == 0 && !overridden_.count(full) && derived_ && derived_->count(full);
}

std::string TableReader::value_text(std::string_view key) const {
  const toml::node* n = get(key);
  return n ? repr(*n) : std::string();
}

void TableReader::fail(std::string_view key, const toml::node* n, const std::string& problem) const {
  const std::string full = prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
  if (n) throw InputError(fmt::format("{}: key '{}' = {}: {}", where(full, n), full, repr(*n), problem));
  throw InputError(fmt::format("{}: key '{}': {}", where(full, n), full, problem));
}

void TableReader::finish() const {
  if (!t_) return;
  for (const auto& [k, v] : *t_) {
    if (known_.count(k.str())) continue;
    const std::string full = prefix_.empty() ? std::string(k.str()) : prefix_ + "." + std::string(k.str());
    throw InputError(fmt::format("{}: unknown key '{}' (see docs/case-reference.md)", where(full, &v), full));
  }
}

void TableReader::number(std::string_view key, const Range& range, double& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  if (auto f = n->as_floating_point())
    v = f->get();
  else if (auto i = n->as_integer())
    v = static_cast<double>(i->get());
  else
    fail(key, n, "must be a number");
  if (std::isnan(v)) fail(key, n, "must not be nan");
  if (!range.contains(v)) fail(key, n, range.problem());
}

void TableReader::integer(std::string_view key, const Range& range, int& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  auto i = n->as_integer();
  if (!i) fail(key, n, "must be an integer");
  if (!range.contains(static_cast<double>(i->get()))) fail(key, n, range.integer_problem());
  v = static_cast<int>(i->get());
}

void TableReader::boolean(std::string_view key, bool& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  auto b = n->as_boolean();
  if (!b) fail(key, n, "must be true or false");
  v = b->get();
}

namespace {

// "\"a\", \"b\", \"c\"": the accepted values, for a message.
std::string choice_list(const std::vector<std::string_view>& choices) {
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
  return list;
}

bool is_choice(const std::vector<std::string_view>& choices, const std::string& s) {
  if (choices.empty()) return true;
  for (const auto& c : choices)
    if (c == s) return true;
  return false;
}

}  // namespace

void TableReader::string(std::string_view key, const std::vector<std::string_view>& choices, std::string& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  auto s = n->as_string();
  if (!s) fail(key, n, "must be a string");
  if (!is_choice(choices, s->get())) fail(key, n, "must be one of " + choice_list(choices));
  v = s->get();
}

void TableReader::strings(std::string_view key, const std::vector<std::string_view>& choices,
                          std::vector<std::string>& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  auto a = n->as_array();
  if (!a) fail(key, n, "must be an array of strings, e.g. [" + choice_list(choices) + "]");
  std::vector<std::string> out;
  for (const auto& e : *a) {
    auto s = e.as_string();
    if (!s) fail(key, n, "every entry must be a string in quotes");
    if (!is_choice(choices, s->get()))
      fail(key, n, fmt::format("\"{}\" is not one of the accepted values {}", s->get(), choice_list(choices)));
    if (std::find(out.begin(), out.end(), s->get()) != out.end())
      fail(key, n, fmt::format("\"{}\" is given twice", s->get()));
    out.push_back(s->get());
  }
  v = std::move(out);
}

void TableReader::numbers(std::string_view key, const Range& range, std::vector<double>& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  auto a = n->as_array();
  if (!a) fail(key, n, "must be an array of numbers");
  std::vector<double> out;
  for (const auto& e : *a) {
    if (auto f = e.as_floating_point())
      out.push_back(f->get());
    else if (auto i = e.as_integer())
      out.push_back(static_cast<double>(i->get()));
    else
      fail(key, n, "must be an array of numbers");
    if (!std::isfinite(out.back())) fail(key, n, "entries must be finite");
    if (!range.contains(out.back()))
      fail(key, n, fmt::format("entry {} = {}: each entry {}", out.size() - 1, out.back(), range.problem()));
  }
  v = std::move(out);
}

void TableReader::vec3(std::string_view key, const Range& range, std::array<double, 3>& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  std::vector<double> x;
  numbers(key, range, x);
  if (x.size() != 3) fail(key, n, "must be an array of three numbers");
  v = {x[0], x[1], x[2]};
}

void TableReader::ivec3(std::string_view key, const Range& range, std::array<int, 3>& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  auto a = n->as_array();
  if (!a || a->size() != 3) fail(key, n, "must be an array of three integers");
  std::array<int, 3> out{};
  for (int c = 0; c < 3; ++c) {
    auto i = (*a)[c].as_integer();
    if (!i || !range.contains(static_cast<double>(i->get()))) fail(key, n, "must be three positive integers");
    out[c] = static_cast<int>(i->get());
  }
  v = out;
}

void TableReader::ivec2(std::string_view key, const Range& range, std::array<int, 2>& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  // Whole numbers written as floats (2.0) are accepted, as for every number.
  std::vector<double> x;
  numbers(key, Range{}, x);
  if (x.size() != 2 || !range.contains(x[0]) || !range.contains(x[1]) || x[0] != std::floor(x[0]) ||
      x[1] != std::floor(x[1]))
    fail(key, n, "must be two positive integers [n1, n2]");
  v = {static_cast<int>(x[0]), static_cast<int>(x[1])};
}

void TableReader::triples(std::string_view key, std::string_view unit, const Range& range,
                          std::vector<std::array<double, 3>>& v) const {
  const toml::node* n = get(key);
  if (!n) return;
  auto a = n->as_array();
  if (!a) fail(key, n, fmt::format("must be an array of [x, y, z] in {}", unit));
  std::vector<std::array<double, 3>> out;
  for (const auto& row : *a) {
    auto ra = row.as_array();
    if (!ra || ra->size() != 3) fail(key, n, fmt::format("every entry must be [x, y, z] in {}", unit));
    std::array<double, 3> x{};
    for (int c = 0; c < 3; ++c) {
      if (auto f = (*ra)[c].as_floating_point())
        x[c] = f->get();
      else if (auto i = (*ra)[c].as_integer())
        x[c] = static_cast<double>(i->get());
      else
        fail(key, n, "entries must be numbers");
      if (!std::isfinite(x[c])) fail(key, n, "entries must be finite");
      if (!range.contains(x[c]))
        fail(key, n, fmt::format("row {} entry {} = {}: each entry {}", out.size(), c, x[c], range.problem()));
    }
    out.push_back(x);
  }
  v = std::move(out);
}

}  // namespace swarf

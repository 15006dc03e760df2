// study_file.cpp: study files and their expansion into cases (see study.h, docs/studies.md).
#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spawn.h>
#include <sys/wait.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "io/atomic_file.h"
#include "setup/case_config.h"
#include "setup/toml_parse.h"
#include "study/study.h"
#include "study/study_table.h"
#include "study/study_text.h"
#include "study/sweep_mpi.h"
#include "swarf/core/errors.h"

namespace swarf {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace study_text;

namespace {

std::string fnv1a_hex(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

// A float as TOML text that parses back to the same double (and stays a float).
std::string float_text(double v) {
  std::array<char, 64> buf{};
  const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);  // shortest, either notation
  std::string s = fmt::format("{}", v);                                    // fixed notation for exponents in [-4, 16)
  if (std::string sci(buf.data(), res.ptr); sci.size() + 3 <= s.size()) s = sci;  // 2e+11, not 200000000000
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string toml_string(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    if (c == '\n')
      q += "\\n";
    else if (c == '\t')
      q += "\\t";
    else
      q += c;
  }
  return q + "\"";
}

// Where a node stands, for messages: "study.toml:12".
std::string at(const std::string& source, const toml::node& n) {
  return n.source().begin.line > 0 ? fmt::format("{}:{}", source, n.source().begin.line) : source;
}

std::string shown(const toml::node& n) {
  if (n.is_table()) return "(a table)";
  return print_toml(n);
}

[[noreturn]] void bad(const std::string& source, const toml::node& n, const std::string& key, const std::string& why) {
  throw InputError(fmt::format("{}: key '{}' = {}: {}", at(source, n), key, shown(n), why));
}

// The TOML value text of a case value (what --set parses back to the same value).
std::string value_text(const std::string& source, const toml::node& n, const std::string& key) {
  if (auto i = n.as_integer()) return fmt::format("{}", i->get());
  if (auto f = n.as_floating_point()) return float_text(f->get());
  if (auto b = n.as_boolean()) return b->get() ? "true" : "false";
  if (auto s = n.as_string()) return toml_string(s->get());
  if (auto a = n.as_array()) {
    std::string out = "[";
    for (std::size_t k = 0; k < a->size(); ++k) out += (k ? ", " : "") + value_text(source, *a->get(k), key);
    return out + "]";
  }
  bad(source, n, key, "dates, times and inline tables are not case values");
}

bool valid_key(const std::string& key) {
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos) return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

// Flattens nested tables into dotted keys: [grid] mesh.0.rake_angle = [...] and
// [grid] "mesh.0.rake_angle" = [...] are the same key.
void flatten(const std::string& source, const toml::table& t, const std::string& prefix,
             std::vector<std::pair<std::string, const toml::node*>>& out) {
  for (const auto& [k, v] : t) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (auto sub = v.as_table()) {
      flatten(source, *sub, key, out);
      continue;
    }
    if (!valid_key(key)) bad(source, v, key, "not a case key (letters, digits, '_', '-' and '.' only)");
    out.emplace_back(key, &v);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}

const toml::table& table_at(const std::string& source, const toml::node& n, const std::string& key) {
  if (auto t = n.as_table()) return *t;
  bad(source, n, key, "must be a table");
}

std::string string_at(const std::string& source, const toml::node& n, const std::string& key) {
  if (auto s = n.as_string()) return s->get();
  bad(source, n, key, "must be a string");
}

std::vector<std::string> strings_at(const std::string& source, const toml::node& n, const std::string& key) {
  std::vector<std::string> out;
  auto a = n.as_array();
  if (!a) bad(source, n, key, "must be an array of strings");
  for (const auto& e : *a) out.push_back(string_at(source, e, key));
  return out;
}

}  // namespace

namespace {

using NodeList = std::vector<std::pair<std::string, const toml::node*>>;
using Axes = std::vector<std::pair<std::string, std::vector<std::string>>>;

// What the study file's top-level keys give before the checks across them.
struct StudyKeys {
  NodeList grid, fixed, units;
  std::vector<std::map<std::string, std::string>> points;
  std::map<std::string, const toml::node*> point_keys;  // first node that set each point key
};

// The top-level keys, each checked on its own; the scalars go straight into 's'.
StudyKeys read_study_keys(const toml::table& root, const std::string& source, Study& s) {
  StudyKeys r;
  const std::set<std::string> known{"base",  "title",        "repetitions",    "seed_key", "seed_start",
                                    "plots", "plot_metrics", "plot_against",   "set",      "grid",
                                    "point", "units",        "case_time_limit"};
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    if (!known.count(key))
      bad(source, v, key,
          "unknown key (known: base, title, repetitions, seed_key, seed_start, plots, plot_metrics, plot_against, "
          "case_time_limit, [set], [grid], [[point]], [units])");
    if (key == "base") {
      s.base = string_at(source, v, key);
      if (s.base.empty()) bad(source, v, key, "must name the base case file");
    } else if (key == "title") {
      s.title = string_at(source, v, key);
    } else if (key == "repetitions" || key == "seed_start") {
      auto i = v.as_integer();
      if (!i) bad(source, v, key, "must be an integer");
      if (key == "seed_start") {
        // (seed_start + repetition must not overflow: 2^63 - 1 with two repetitions did)
        if (i->get() < -(std::int64_t{1} << 53) || i->get() > (std::int64_t{1} << 53))
          bad(source, v, key, "must lie in [-2^53, 2^53]");
        s.seed_start = i->get();
      } else {
        if (i->get() < 1 || i->get() > 10000) bad(source, v, key, "must lie in [1, 10000]");
        s.repetitions = int(i->get());
      }
    } else if (key == "seed_key") {
      s.seed_key = string_at(source, v, key);
      if (!valid_key(s.seed_key)) bad(source, v, key, "not a case key");
    } else if (key == "case_time_limit") {
      const auto f = v.value<double>();
      if (!f || !(*f >= 0.0) || !std::isfinite(*f)) bad(source, v, key, "must be a time >= 0 in s (0: no limit)");
      s.case_time_limit = *f;
    } else if (key == "plots") {
      auto b = v.as_boolean();
      if (!b) bad(source, v, key, "must be true or false");
      s.plots = b->get();
    } else if (key == "plot_metrics") {
      s.plot_metrics = strings_at(source, v, key);
    } else if (key == "plot_against") {
      s.plot_against = strings_at(source, v, key);
    } else if (key == "set") {
      flatten(source, table_at(source, v, key), "", r.fixed);
    } else if (key == "grid") {
      flatten(source, table_at(source, v, key), "", r.grid);
    } else if (key == "units") {
      flatten(source, table_at(source, v, key), "", r.units);
    } else if (key == "point") {
      auto a = v.as_array();
      if (!a || !a->is_array_of_tables()) bad(source, v, key, "must be an array of tables: [[point]] entries");
      for (const auto& e : *a) {
        NodeList kv;
        flatten(source, *e.as_table(), "", kv);
        if (kv.empty()) bad(source, e, "point", "an empty [[point]]: give at least one key = value");
        std::map<std::string, std::string> p;
        for (const auto& [pk, pn] : kv) {
          p[pk] = value_text(source, *pn, "point." + pk);
          r.point_keys.emplace(pk, pn);
        }
        if (std::find(r.points.begin(), r.points.end(), p) != r.points.end())
          bad(source, e, "point", fmt::format("the point {} is listed twice", describe(p)));
        r.points.push_back(p);
      }
    }
  }
  return r;
}

// The fixed overrides, the grid's axes and the checks across keys (a key fixed or varied in
// one place only, the seed key, something varies); fills s.fixed, s.parameters and s.units.
Axes check_varied(const toml::table& root, const std::string& source, const StudyKeys& r, Study& s) {
  for (const auto& [k, n] : r.fixed) s.fixed[k] = value_text(source, *n, "set." + k);
  Axes axes;
  for (const auto& [k, n] : r.grid) {
    auto a = n->as_array();
    if (!a || a->empty()) bad(source, *n, "grid." + k, "a grid key needs a non-empty array of the values to run");
    std::vector<std::string> vals;
    for (const auto& e : *a) {
      std::string t = value_text(source, e, "grid." + k);
      if (std::find(vals.begin(), vals.end(), t) != vals.end())
        bad(source, *n, "grid." + k, fmt::format("the value {} is listed twice", t));
      vals.push_back(t);
    }
    if (r.point_keys.count(k)) bad(source, *n, "grid." + k, "is also set by a [[point]]: vary a key in one place");
    axes.emplace_back(k, vals);
  }
  for (const auto& [k, n] : r.fixed) {
    if (r.point_keys.count(k) ||
        std::any_of(axes.begin(), axes.end(), [&key = k](const auto& a) { return a.first == key; }))
      bad(source, *n, "set." + k, "is also varied ([grid] or [[point]]): a key is either fixed or varied");
    if (k == s.seed_key) bad(source, *n, "set." + k, "is the seed_key, which the repetitions set");
  }
  if (!s.seed_key.empty() &&
      (r.point_keys.count(s.seed_key) ||
       std::any_of(axes.begin(), axes.end(), [&](const auto& a) { return a.first == s.seed_key; })))
    throw InputError(
        fmt::format("{}: key 'seed_key' = \"{}\": that key is also varied by [grid] or [[point]]", source, s.seed_key));
  if (s.repetitions > 1 && s.seed_key.empty())
    bad(source, *root.get("repetitions"), "repetitions",
        "swarf runs are deterministic, so repetitions would repeat identical cases; give seed_key = "
        "\"workpiece.disorder_seed\" (the workpiece's disorder) or another case key to set to seed_start + "
        "repetition in each repetition");
  if (axes.empty() && r.points.empty() && s.repetitions == 1)
    throw InputError(
        fmt::format("{}: nothing varies: give a [grid] table, [[point]] entries, or repetitions > 1 "
                    "with seed_key",
                    source));

  // Varied keys: alphabetical, the seed key last.
  std::set<std::string> varied;
  for (const auto& [k, v] : axes) varied.insert(k);
  for (const auto& [k, n] : r.point_keys) varied.insert(k);
  s.parameters.assign(varied.begin(), varied.end());
  if (!s.seed_key.empty()) s.parameters.push_back(s.seed_key);
  for (const auto& [k, n] : r.units) {
    if (std::find(s.parameters.begin(), s.parameters.end(), k) == s.parameters.end())
      bad(source, *n, "units." + k, "not a varied key: [units] gives the units of the varied keys for study.csv");
    s.units[k] = string_at(source, *n, "units." + k);
  }
  return axes;
}

// Expansion: points (in file order) x grid (first key slowest) x repetitions.
void expand(const std::string& source, const Axes& axes, std::vector<std::map<std::string, std::string>> points,
            Study& s) {
  // (the count stops growing past the limit: 64 axes of two values wrapped a 64-bit product
  // round to 0, and the study then ran no case at all)
  constexpr std::size_t kMaxCases = 100000;
  std::size_t grid_count = 1;
  for (const auto& [k, v] : axes) grid_count = std::min(grid_count * v.size(), kMaxCases + 1);
  const std::size_t total = std::max<std::size_t>(1, points.size()) * grid_count * std::size_t(s.repetitions);
  if (total > kMaxCases)
    throw InputError(grid_count > kMaxCases
                         ? fmt::format("{}: more than {} cases (split the study)", source, kMaxCases)
                         : fmt::format("{}: {} cases: more than {} (split the study)", source, total, kMaxCases));
  if (points.empty()) points.emplace_back();
  const int width = id_width(static_cast<long long>(total));
  for (const auto& p : points) {
    for (std::size_t g = 0; g < grid_count; ++g) {
      std::map<std::string, std::string> values = p;
      std::size_t rest = g;
      for (std::size_t a = axes.size(); a-- > 0;) {
        values[axes[a].first] = axes[a].second[rest % axes[a].second.size()];
        rest /= axes[a].second.size();
      }
      for (int r = 0; r < s.repetitions; ++r) {
        StudyCase c;
        c.id = case_id(static_cast<long long>(s.cases.size()), width);
        c.values = values;
        c.repetition = r;
        if (!s.seed_key.empty()) c.values[s.seed_key] = fmt::format("{}", s.seed_start + r);
        s.cases.push_back(std::move(c));
      }
    }
  }
}

}  // namespace

Study parse_study(const std::string& text, const std::string& source, const std::string& directory) {
  const toml::table root = parse_toml_input(text, source);
  Study s;
  s.file = source;
  const StudyKeys keys = read_study_keys(root, source, s);
  if (s.base.empty()) throw InputError(fmt::format("{}: key 'base' must be set: the base case file (TOML)", source));
  const Axes axes = check_varied(root, source, keys, s);
  expand(source, axes, keys.points, s);
  s.base_path = (fs::path(directory) / s.base).lexically_normal().string();
  if (fs::path(s.base).is_absolute()) s.base_path = s.base;
  return s;
}

Study load_study(const std::string& path) {
  std::string text;
  try {
    text = read_text(path);
  } catch (const InputError&) {
    throw InputError(fmt::format("cannot read the study file '{}'", path));
  }
  const fs::path dir = fs::absolute(fs::path(path)).parent_path();
  Study s = parse_study(text, path, dir.string());
  std::string base_text;
  try {
    base_text = read_text(s.base_path);
  } catch (const InputError&) {
    throw InputError(fmt::format("{}: key 'base' = \"{}\": cannot read the base case '{}'", path, s.base, s.base_path));
  }
  s.base_hash = fnv1a_hex(base_text);
  return s;
}

std::vector<std::string> case_overrides(const Study& study, const StudyCase& c) {
  std::vector<std::string> out;
  for (const auto& [k, v] : study.fixed) out.push_back(k + "=" + v);
  for (const auto& [k, v] : c.values) out.push_back(k + "=" + v);
  return out;
}

void check_cases(const Study& study) {
  for (const auto& c : study.cases) {
    try {
      (void)load_case(study.base_path, case_overrides(study, c));
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: case {} ({}): {}", study.file, c.id, describe(c.values), e.what()));
    }
  }
}

}  // namespace swarf

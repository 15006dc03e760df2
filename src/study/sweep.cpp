// sweep.cpp: study files, their expansion into cases, running the cases as subprocesses and
// resuming (see sweep.h and docs/studies.md).
#include "study/sweep.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>
#include <toml++/toml.h>

#include "io/atomic_file.h"
#include "setup/case_config.h"
#include "swarf/core/errors.h"
#include "study/study_table.h"
#include "study/sweep_mpi.h"

extern char** environ;

namespace swarf {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("cannot read '{}'", path));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

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
  std::string s = fmt::format("{}", v);  // fixed notation for exponents in [-4, 16)
  if (std::string sci(buf.data(), res.ptr); sci.size() + 3 <= s.size()) s = sci;  // 2e+11, not 200000000000
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string toml_string(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    if (c == '\n') q += "\\n";
    else if (c == '\t') q += "\\t";
    else q += c;
  }
  return q + "\"";
}

// Where a node stands, for messages: "study.toml:12".
std::string at(const std::string& source, const toml::node& n) {
  return n.source().begin.line > 0 ? fmt::format("{}:{}", source, n.source().begin.line) : source;
}

std::string shown(const toml::node& n) {
  if (n.is_table()) return "(a table)";
  std::ostringstream os;
  n.visit([&](auto&& v) { os << v; });
  return os.str();
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
  return std::all_of(key.begin(), key.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'; });
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

std::string describe(const std::map<std::string, std::string>& values) {
  std::string out;
  for (const auto& [k, v] : values) out += (out.empty() ? "" : ", ") + k + "=" + v;
  return out;
}

std::string case_id(long long n, int width) { return fmt::format("{:0{}d}", n, width); }
int id_width(long long count) { return std::max<int>(4, int(fmt::format("{}", std::max(0LL, count - 1)).size())); }

std::string log_tail(const std::string& path, int lines) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::vector<std::string> all;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto cr = line.rfind('\r');  // progress lines rewritten in place on a terminal
    all.push_back(cr == std::string::npos ? line : line.substr(cr + 1));
  }
  std::string out;
  for (std::size_t k = all.size() > std::size_t(lines) ? all.size() - lines : 0; k < all.size(); ++k)
    out += all[k] + "\n";
  return out.size() > 2000 ? out.substr(out.size() - 2000) : out;
}

}  // namespace

Study parse_study(const std::string& text, const std::string& source, const std::string& directory) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", source, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  Study s;
  s.file = source;
  const std::set<std::string> known{"base",         "title", "repetitions", "seed_key", "seed_start", "plots",
                                    "plot_metrics", "plot_against", "set", "grid",        "point",    "units"};
  std::vector<std::pair<std::string, const toml::node*>> grid, fixed, units;
  std::vector<std::map<std::string, std::string>> points;
  std::map<std::string, const toml::node*> point_keys;  // first node that set each point key
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    if (!known.count(key))
      bad(source, v, key,
          "unknown key (known: base, title, repetitions, seed_key, seed_start, plots, plot_metrics, plot_against, "
          "[set], [grid], [[point]], [units])");
    if (key == "base") {
      s.base = string_at(source, v, key);
      if (s.base.empty()) bad(source, v, key, "must name the base case file");
    } else if (key == "title") {
      s.title = string_at(source, v, key);
    } else if (key == "repetitions" || key == "seed_start") {
      auto i = v.as_integer();
      if (!i) bad(source, v, key, "must be an integer");
      if (key == "seed_start") {
        s.seed_start = i->get();
      } else {
        if (i->get() < 1 || i->get() > 10000) bad(source, v, key, "must lie in [1, 10000]");
        s.repetitions = int(i->get());
      }
    } else if (key == "seed_key") {
      s.seed_key = string_at(source, v, key);
      if (!valid_key(s.seed_key)) bad(source, v, key, "not a case key");
    } else if (key == "plots") {
      auto b = v.as_boolean();
      if (!b) bad(source, v, key, "must be true or false");
      s.plots = b->get();
    } else if (key == "plot_metrics") {
      s.plot_metrics = strings_at(source, v, key);
    } else if (key == "plot_against") {
      s.plot_against = strings_at(source, v, key);
    } else if (key == "set") {
      flatten(source, table_at(source, v, key), "", fixed);
    } else if (key == "grid") {
      flatten(source, table_at(source, v, key), "", grid);
    } else if (key == "units") {
      flatten(source, table_at(source, v, key), "", units);
    } else if (key == "point") {
      auto a = v.as_array();
      if (!a || !a->is_array_of_tables()) bad(source, v, key, "must be an array of tables: [[point]] entries");
      for (const auto& e : *a) {
        std::vector<std::pair<std::string, const toml::node*>> kv;
        flatten(source, *e.as_table(), "", kv);
        if (kv.empty()) bad(source, e, "point", "an empty [[point]]: give at least one key = value");
        std::map<std::string, std::string> p;
        for (const auto& [pk, pn] : kv) {
          p[pk] = value_text(source, *pn, "point." + pk);
          point_keys.emplace(pk, pn);
        }
        if (std::find(points.begin(), points.end(), p) != points.end())
          bad(source, e, "point", fmt::format("the point {} is listed twice", describe(p)));
        points.push_back(p);
      }
    }
  }
  if (s.base.empty()) throw InputError(fmt::format("{}: key 'base' must be set: the base case file (TOML)", source));

  // The fixed overrides and the grid.
  for (const auto& [k, n] : fixed) s.fixed[k] = value_text(source, *n, "set." + k);
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
  for (const auto& [k, n] : grid) {
    auto a = n->as_array();
    if (!a || a->empty()) bad(source, *n, "grid." + k, "a grid key needs a non-empty array of the values to run");
    std::vector<std::string> vals;
    for (const auto& e : *a) {
      std::string t = value_text(source, e, "grid." + k);
      if (std::find(vals.begin(), vals.end(), t) != vals.end())
        bad(source, *n, "grid." + k, fmt::format("the value {} is listed twice", t));
      vals.push_back(t);
    }
    if (point_keys.count(k)) bad(source, *n, "grid." + k, "is also set by a [[point]]: vary a key in one place");
    axes.emplace_back(k, vals);
  }
  for (const auto& [k, n] : fixed) {
    if (point_keys.count(k) || std::any_of(axes.begin(), axes.end(), [&](const auto& a) { return a.first == k; }))
      bad(source, *n, "set." + k, "is also varied ([grid] or [[point]]): a key is either fixed or varied");
    if (k == s.seed_key) bad(source, *n, "set." + k, "is the seed_key, which the repetitions set");
  }
  if (!s.seed_key.empty() &&
      (point_keys.count(s.seed_key) ||
       std::any_of(axes.begin(), axes.end(), [&](const auto& a) { return a.first == s.seed_key; })))
    throw InputError(fmt::format("{}: key 'seed_key' = \"{}\": that key is also varied by [grid] or [[point]]",
                                 source, s.seed_key));
  if (s.repetitions > 1 && s.seed_key.empty())
    bad(source, *root.get("repetitions"), "repetitions",
        "swarf runs are deterministic (a case has no random seed), so repetitions would repeat identical "
        "cases; give seed_key = \"<case key>\" to set a key to seed_start + repetition in each repetition");
  if (axes.empty() && points.empty() && s.repetitions == 1)
    throw InputError(fmt::format("{}: nothing varies: give a [grid] table, [[point]] entries, or repetitions > 1 "
                                 "with seed_key", source));

  // Varied keys: alphabetical, the seed key last.
  std::set<std::string> varied;
  for (const auto& [k, v] : axes) varied.insert(k);
  for (const auto& [k, n] : point_keys) varied.insert(k);
  s.parameters.assign(varied.begin(), varied.end());
  if (!s.seed_key.empty()) s.parameters.push_back(s.seed_key);
  for (const auto& [k, n] : units) {
    if (std::find(s.parameters.begin(), s.parameters.end(), k) == s.parameters.end())
      bad(source, *n, "units." + k, "not a varied key: [units] gives the units of the varied keys for study.csv");
    s.units[k] = string_at(source, *n, "units." + k);
  }

  // Expansion: points (in file order) x grid (first key slowest) x repetitions.
  std::size_t grid_count = 1;
  for (const auto& [k, v] : axes) grid_count *= v.size();
  const std::size_t total = std::max<std::size_t>(1, points.size()) * grid_count * std::size_t(s.repetitions);
  if (total > 100000)
    throw InputError(fmt::format("{}: {} cases: more than 100000 (split the study)", source, total));
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

// ---- study.json -------------------------------------------------------------------------

void write_study_json(const Study& s, const std::string& out_dir) {
  json j;
  j["format"] = "swarf-study-1";
  j["study_file"] = s.file;
  j["title"] = s.title;
  j["base"] = s.base;
  j["base_path"] = s.base_path;
  j["base_hash"] = s.base_hash;
  j["set"] = s.fixed;
  j["parameters"] = s.parameters;
  j["units"] = s.units;
  j["repetitions"] = s.repetitions;
  j["seed_key"] = s.seed_key;
  j["seed_start"] = s.seed_start;
  j["plots"] = s.plots;
  j["plot_metrics"] = s.plot_metrics;
  j["plot_against"] = s.plot_against;
  j["cases"] = json::array();
  for (const auto& c : s.cases) j["cases"].push_back({{"id", c.id}, {"values", c.values}, {"repetition", c.repetition}});
  fs::create_directories(out_dir);
  write_text_atomic((fs::path(out_dir) / "study.json").string(), j.dump(2) + "\n");
}

Study read_study_json(const std::string& out_dir) {
  const std::string path = (fs::path(out_dir) / "study.json").string();
  if (!fs::exists(path))
    throw InputError(fmt::format("'{}' is not a study directory: no study.json (written by swarf sweep)", out_dir));
  try {
    const json j = json::parse(read_text(path));
    if (j.at("format") != "swarf-study-1") throw InputError("unknown format " + j.at("format").dump());
    Study s;
    s.file = j.at("study_file");
    s.title = j.at("title");
    s.base = j.at("base");
    s.base_path = j.at("base_path");
    s.base_hash = j.at("base_hash");
    s.fixed = j.at("set").get<std::map<std::string, std::string>>();
    s.parameters = j.at("parameters").get<std::vector<std::string>>();
    s.units = j.at("units").get<std::map<std::string, std::string>>();
    s.repetitions = j.at("repetitions");
    s.seed_key = j.at("seed_key");
    s.seed_start = j.at("seed_start");
    s.plots = j.at("plots");
    s.plot_metrics = j.at("plot_metrics").get<std::vector<std::string>>();
    s.plot_against = j.at("plot_against").get<std::vector<std::string>>();
    for (const auto& c : j.at("cases")) {
      StudyCase sc;
      sc.id = c.at("id");
      sc.values = c.at("values").get<std::map<std::string, std::string>>();
      sc.repetition = c.at("repetition");
      s.cases.push_back(std::move(sc));
    }
    return s;
  } catch (const std::exception& e) {
    throw InputError(fmt::format("'{}' is damaged ({}); remove it to start the study afresh", path, e.what()));
  }
}

void reconcile_study(Study& s, const std::string& out_dir) {
  if (!fs::exists(fs::path(out_dir) / "study.json")) return;
  const Study old = read_study_json(out_dir);
  std::set<std::string> finished;
  for (const auto& c : old.cases)
    if (case_status(old, c, out_dir).state == CaseState::completed) finished.insert(c.id);

  std::vector<std::string> changes;
  if (old.base_hash != s.base_hash)
    changes.push_back(fmt::format("base (the text of the base case '{}' changed)", s.base_path));
  std::set<std::string> fixed_keys;
  for (const auto& [k, v] : old.fixed) fixed_keys.insert(k);
  for (const auto& [k, v] : s.fixed) fixed_keys.insert(k);
  for (const auto& k : fixed_keys) {
    const auto a = old.fixed.find(k);
    const auto b = s.fixed.find(k);
    const std::string va = a == old.fixed.end() ? "not set" : a->second, vb = b == s.fixed.end() ? "not set" : b->second;
    if (va != vb) changes.push_back(fmt::format("set.{} ({} -> {})", k, va, vb));
  }
  if (old.seed_key != s.seed_key) changes.push_back(fmt::format("seed_key (\"{}\" -> \"{}\")", old.seed_key, s.seed_key));

  // Match the cases by their values; known cases keep their ids.
  std::map<std::map<std::string, std::string>, std::string> old_ids;
  long long next = 0;
  int width = 4;
  for (const auto& c : old.cases) {
    old_ids[c.values] = c.id;
    next = std::max(next, std::stoll(c.id) + 1);
    width = std::max<int>(width, int(c.id.size()));
  }
  std::set<std::map<std::string, std::string>> fresh;
  for (const auto& c : s.cases) fresh.insert(c.values);
  std::set<std::string> removed_reasons;
  for (const auto& c : old.cases) {
    if (fresh.count(c.values) || !finished.count(c.id)) continue;
    std::string why;
    for (const auto& [k, v] : c.values) {
      const bool present = std::any_of(s.cases.begin(), s.cases.end(), [&](const StudyCase& n) {
        auto it = n.values.find(k);
        return it != n.values.end() && it->second == v;
      });
      if (!present) why += (why.empty() ? "" : ", ") + fmt::format("{} = {} is no longer in the study", k, v);
    }
    for (const auto& k : s.parameters)
      if (!c.values.count(k)) why += (why.empty() ? "" : ", ") + fmt::format("{} is newly varied", k);
    if (why.empty()) why = fmt::format("the point {} is no longer in the study", describe(c.values));
    removed_reasons.insert(fmt::format("{} (finished case {})", why, c.id));
  }
  changes.insert(changes.end(), removed_reasons.begin(), removed_reasons.end());
  if (!changes.empty() && !finished.empty())
    throw InputError(fmt::format(
        "{}: the study changed since {} finished case(s) in '{}' were run: {}. Restore the study file, or run it "
        "with another --out directory (adding values or points is allowed)",
        s.file, finished.size(), out_dir, fmt::join(changes, "; ")));

  for (auto& c : s.cases) {
    auto it = old_ids.find(c.values);
    c.id = it != old_ids.end() ? it->second : case_id(next++, width);
  }
  std::sort(s.cases.begin(), s.cases.end(),
            [](const StudyCase& a, const StudyCase& b) { return std::stoll(a.id) < std::stoll(b.id); });
}

// ---- case state ------------------------------------------------------------------------

std::string CaseStatus::text() const {
  switch (state) {
    case CaseState::completed: return "completed";
    case CaseState::failed:
      return exit_code > 128 ? fmt::format("failed (signal {})", exit_code - 128)
                             : fmt::format("failed (exit {})", exit_code);
    case CaseState::interrupted: return "interrupted";
    case CaseState::not_run: break;
  }
  return "not run";
}

std::string case_dir(const std::string& out_dir, const StudyCase& c) {
  return (fs::path(out_dir) / "cases" / c.id).string();
}

CaseStatus case_status(const Study& study, const StudyCase& c, const std::string& out_dir) {
  const fs::path dir = case_dir(out_dir, c);
  CaseStatus st;
  if (fs::exists(dir / "summary.json")) {
    try {
      const json j = json::parse(read_text((dir / "summary.json").string()));
      if (j.value("status", "") == "completed" &&
          j.value("overrides", std::vector<std::string>{}) == case_overrides(study, c)) {
        st.state = CaseState::completed;
        return st;
      }
    } catch (const std::exception&) {
      // not a complete summary: run the case again
    }
  }
  if (fs::exists(dir / "sweep_status.json")) {
    try {
      const json j = json::parse(read_text((dir / "sweep_status.json").string()));
      st.state = CaseState::failed;
      st.exit_code = j.at("exit_code");
      st.log_tail = j.at("log_tail");
      return st;
    } catch (const std::exception&) {
    }
  }
  st.state = fs::exists(dir / "log.txt") ? CaseState::interrupted : CaseState::not_run;
  return st;
}

// ---- running ---------------------------------------------------------------------------

int run_logged(const std::vector<std::string>& argv, const std::string& log_path) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0].c_str(), &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw std::runtime_error(fmt::format("cannot start '{}': {}", argv[0], std::strerror(rc)));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error(fmt::format("waiting for '{}': {}", argv[0], std::strerror(errno)));
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

namespace {

std::string duration_text(double s) {
  if (!(s >= 0)) return "?";
  if (s < 10) return fmt::format("{:.1f} s", s);
  if (s < 60) return fmt::format("{:.0f} s", s);
  if (s < 3600) return fmt::format("{} min {:02.0f} s", int(s / 60), s - 60 * int(s / 60));
  return fmt::format("{} h {:02d} min", int(s / 3600), int(s / 60) % 60);
}

// Progress of this process's cases on stderr: one line per finished case.
class SweepProgress {
 public:
  SweepProgress(std::string prefix, std::size_t to_run) : prefix_(std::move(prefix)), to_run_(to_run) {}
  void started() {
    std::lock_guard<std::mutex> lock(m_);
    ++running_;
  }
  void finished(const std::string& id, bool ok, double seconds, const std::string& detail) {
    std::lock_guard<std::mutex> lock(m_);
    --running_;
    ++done_;
    if (!ok) ++failed_;
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const std::size_t left = to_run_ - done_;
    fmt::print(stderr, "sweep{}: case {} {} in {}; {}/{} done, {} failed, {} running, ETA {}\n", prefix_, id,
               ok ? "completed" : "FAILED", duration_text(seconds), done_, to_run_, failed_, running_,
               left == 0 ? "0 s" : duration_text(el * double(left) / double(done_)));
    if (!ok && !detail.empty()) fmt::print(stderr, "{}", detail);
    std::fflush(stderr);
  }
  std::size_t failed() const { return failed_; }

 private:
  std::mutex m_;
  std::string prefix_;
  std::size_t to_run_, done_ = 0, failed_ = 0, running_ = 0;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

// Runs one case as 'swarf run' in its folder and records a failure.
bool run_one(const Study& s, const StudyCase& c, const SweepOptions& o, int threads, SweepProgress& progress) {
  const std::string dir = case_dir(o.out_dir, c);
  const auto t0 = std::chrono::steady_clock::now();
  progress.started();
  int code = -1;
  std::string detail;
  try {
    fs::create_directories(dir);
    fs::remove(fs::path(dir) / "sweep_status.json");
    std::vector<std::string> argv{o.swarf_exe.empty() ? "/proc/self/exe" : o.swarf_exe, "run", s.base_path, "--out", dir};
    for (const auto& ov : case_overrides(s, c)) argv.insert(argv.end(), {"--set", ov});
    argv.insert(argv.end(), {"--threads", std::to_string(threads)});
    code = run_logged(argv, (fs::path(dir) / "log.txt").string());
  } catch (const std::exception& e) {
    detail = std::string(e.what()) + "\n";
  }
  bool ok = code == 0 && case_status(s, c, o.out_dir).state == CaseState::completed;
  if (!ok) {
    detail += log_tail((fs::path(dir) / "log.txt").string(), 8);
    if (code == 0) detail += "(exit code 0 but no complete summary.json)\n";
    try {
      const json st{{"exit_code", code}, {"log_tail", detail}};
      write_text_atomic((fs::path(dir) / "sweep_status.json").string(), st.dump(2) + "\n");
    } catch (const std::exception& e) {
      detail += fmt::format("(could not record the failure: {})\n", e.what());
    }
  }
  progress.finished(c.id, ok, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), detail);
  return ok;
}

}  // namespace

int run_sweep(const SweepOptions& o) {
  MpiSession mpi;
  const int rank = mpi.rank(), size = mpi.size();
  Study study;
  std::vector<std::size_t> pending;
  std::exception_ptr setup_error;
  try {
    if (o.jobs < 1) throw InputError(fmt::format("--jobs {}: must be at least 1", o.jobs));
    if (o.threads < 0) throw InputError(fmt::format("--threads {}: must be at least 1", o.threads));
    study = load_study(o.study_path);
    check_cases(study);
    reconcile_study(study, o.out_dir);
    for (std::size_t k = 0; k < study.cases.size(); ++k)
      if (case_status(study, study.cases[k], o.out_dir).state != CaseState::completed) pending.push_back(k);
  } catch (...) {
    setup_error = std::current_exception();
  }
  // Every rank reads the same files, so a bad study stops all of them; a rank-specific
  // failure (a file this rank cannot see) stops the others too instead of leaving them waiting.
  const int any_error = mpi.max_all(setup_error ? 1 : 0), root_error = mpi.from_root(setup_error ? 1 : 0);
  if (any_error) {
    if (rank == 0 && setup_error) std::rethrow_exception(setup_error);
    if (rank == 0) throw std::runtime_error("another MPI rank could not set up the study (see its message)");
    if (setup_error && !root_error) {
      try {
        std::rethrow_exception(setup_error);
      } catch (const std::exception& e) {
        fmt::print(stderr, "swarf: error (MPI rank {}): {}\n", rank, e.what());
      }
    }
    return 2;
  }

  if (o.list_only) {
    if (rank == 0)
      for (const auto& c : study.cases)
        fmt::print("{} {:<11} {}\n", c.id, case_status(study, c, o.out_dir).text(),
                   fmt::join(case_overrides(study, c), " "));
    return 0;
  }
  if (rank == 0) {
    fs::create_directories(fs::path(o.out_dir) / "cases");
    write_study_json(study, o.out_dir);
    for (const auto& p : study.parameters)
      if (!study.units.count(p))
        fmt::print(stderr, "sweep: note: no unit for '{}' in [units]: its study.csv unit cell stays empty\n", p);
  }
  mpi.barrier();

  std::vector<std::size_t> mine;
  for (std::size_t k = 0; k < pending.size(); ++k)
    if (int(k % std::size_t(size)) == rank) mine.push_back(pending[k]);
  const int cores = std::max(1, int(std::thread::hardware_concurrency()));
  const int threads = o.threads > 0 ? o.threads : std::max(1, cores / (o.jobs * mpi.local_size()));
  const std::string prefix = size > 1 ? fmt::format(" [rank {} of {}]", rank, size) : "";
  if (rank == 0)
    fmt::print(stderr, "sweep: {}: {} cases, {} finished earlier, {} to run{}; {} at once x {} thread(s) per case\n",
               study.file, study.cases.size(), study.cases.size() - pending.size(), pending.size(),
               size > 1 ? fmt::format(" on {} ranks", size) : "", o.jobs, threads);
  SweepProgress progress(prefix, mine.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&]() {
    for (std::size_t k = next++; k < mine.size(); k = next++) run_one(study, study.cases[mine[k]], o, threads, progress);
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < std::min<int>(o.jobs, int(mine.size())); ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  mpi.barrier();
  if (rank != 0) return progress.failed() ? 1 : 0;

  // Rank 0 gathers what every rank wrote into the case folders.
  const StudyTable table = collect_table(study, o.out_dir);
  write_text_atomic((fs::path(o.out_dir) / "study.csv").string(), table_csv(table));
  write_text_atomic((fs::path(o.out_dir) / "timing.csv").string(), table_csv(collect_table(study, o.out_dir, true)));
  std::size_t completed = 0;
  for (const auto& st : table.status) completed += st.state == CaseState::completed;
  std::string plots = "no plots (plots = false)";
  if (study.plots) {
    const std::string why = draw_plots(study, table, o.out_dir);
    plots = why.empty() ? "plots in plots/" : "no plots: " + why;
  }
  fmt::print("sweep: {} cases: {} completed, {} failed or not finished; wrote {}/study.csv, timing.csv; {}\n",
             table.rows.size(), completed, table.rows.size() - completed, o.out_dir, plots);
  return completed == table.rows.size() ? 0 : 1;
}

}  // namespace swarf
